// Many film holes through a blade wall: direct drilling (features/drilling/drill_holes.hpp) against OCCT's plain
// path (one BRepAlgoAPI_Cut with all tools), in the same run; optionally the verified boolean path
// (src/brep/boolean/verified_boolean.hpp) on the same holes.
//
//   bench_holes            N = 100, 400, 1000 holes drilled into the cooled example blade (ours, cut and
//                          verified), OCCT plain at 100 and 400; each result also checked globally by
//                          brep::verify_solid after the clock stopped
//   bench_holes --quick    N = 12 holes in the hollow example blade (smoke run, < 10 s)
//   bench_holes --counts 50,200 --occt 50 --step 100 --hollow --no-global --patches
//                          (--step: also the verified boolean path; --patches: split walls first)
//
// Work loads: the cooled example blade (builtin hpt_rotor config with its chambers, ribs and fillets,
// features/internal_cooling.hpp; ~40 s to build, not timed) with a film-hole field from
// tests/support/drill_sample_holes.hpp (D 0.5 mm, 30 deg to the surface, staggered rows on both sides
// wherever the exit lies on a chamber wall); or (--hollow, --quick) the hollow blade of
// tests/support/boolean_sample_part.hpp with its hole field. Our time covers everything drill_holes does:
// patches, geometry and preconditions, topology, the local checks (per-hole volume by the divergence
// theorem against ray quadrature, BRepCheck of every new face, edge use of the whole solid) and the
// fallback step for holes that do not qualify.
//
// Exit status 1 when our result fails a check (drill_holes throws, or the global verify_solid or the
// volume balance fails), 0 otherwise. OCCT's plain result is checked (solids, removed volume against
// our independent quadrature) and reported, never fatal.
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/boolean_sample_part.hpp"
#include "features/drilling/drill_holes.hpp"
#include "tests/support/drill_sample_holes.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/cooling.hpp"

using namespace cg;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Processor time of the whole process (all threads), s: with other jobs on the machine the wall clock
// alone says little.
double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string load_average() {
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return "?";
  char b[64] = {0};
  const bool ok = std::fgets(b, sizeof b, f) != nullptr;
  std::fclose(f);
  std::string s = ok ? b : "?";
  return s.substr(0, s.find(' '));
}

struct Workload {
  std::string description;
  brep::NamedShape part;
  double part_volume = 0;
  std::function<std::vector<features::CylindricalHole>(int count)> holes;
};

const blade::BladeModel& example_model() {
  static const blade::BladeModel model = config::build_model(config::builtin_example_config());
  return model;
}

// The cooled example blade (chambers, ribs, fillets, inlets) and film holes exiting onto chamber walls.
Workload cooled_blade_workload() {
  const config::Config c = config::builtin_example_config();
  const blade::BladeModel& model = example_model();
  const brep::BladeSolid s = brep::build_blade_solid(model);
  static features::PassagesResult cooled;
  cooled = pipeline::apply_cooling(model, pipeline::plan_cooling(c.cooling, model), brep::NamedShape{s.solid, s.faces});
  Workload w;
  std::ostringstream d;
  d << "cooled hpt_rotor example blade, " << cooled.blade.faces.size() << " faces";
  w.description = d.str();
  w.part = cooled.blade;
  w.part_volume = cooled.check.volume;
  w.holes = [](int count) {
    features::FilmFieldOptions o;
    o.count = count;
    // Spanwise pitch 2 D (1.0 mm) rather than the field's default 1.2 mm: at 1.2 mm only 929 of the
    // 1000 holes found room beside the example's ribs (33 rows of at most 34).
    o.min_pitch = 1.0;
    return features::film_hole_field(example_model(), cooled.blade, o);
  };
  return w;
}

// The hollow blade of boolean_sample_part (fast to build: the smoke run).
Workload hollow_blade_workload(bool verify_part) {
  features::HollowBladeOptions ho;
  ho.verify = verify_part;
  static features::HollowBlade hb;
  hb = features::make_hollow_blade(example_model(), ho);
  Workload w;
  std::ostringstream d;
  d << "hollow hpt_rotor blade, wall " << ho.wall << " mm, " << hb.part.faces.size() << " faces";
  w.description = d.str();
  w.part = hb.part;
  w.part_volume = hb.volume;
  w.holes = [](int count) {
    features::HoleFieldOptions o;
    o.count = count;
    return features::holes_of_tools(features::make_hole_tools(example_model(), hb, o));
  };
  return w;
}

int count_solids(const TopoDS_Shape& s) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(s, TopAbs_SOLID, m);
  return m.Extent();
}

std::vector<int> parse_list(const char* s) {
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) v.push_back(std::stoi(item));
  return v;
}

struct OursResult {
  bool ok = false;
  double seconds = 0, cpu = 0;
  std::vector<double> independent;  // per hole, mm^3 (ray quadrature; NaN for holes that fell back)
};

OursResult run_drill(const Workload& w, const std::vector<features::CylindricalHole>& holes,
                     const features::DrillOptions& options, bool global) {
  OursResult r;
  const int n = static_cast<int>(holes.size());
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  features::DrillResult d;
  try {
    d = features::drill_holes(w.part, holes, options);
  } catch (const std::exception& e) {
    r.seconds = since(t0);
    std::printf("%d holes: FAILED after %.1f s: %s\n", n, r.seconds, e.what());
    return r;
  }
  r.seconds = since(t0);
  r.cpu = cpu_seconds() - c0;
  double worst = 0;
  std::map<std::string, int> reasons;
  for (const features::DrilledHole& h : d.holes) {
    r.independent.push_back(h.independent_volume);
    if (h.drilled) worst = std::max(worst, std::abs(h.volume - h.independent_volume) / h.independent_volume);
    else ++reasons[h.fallback_reason];
  }
  std::printf("%d holes: %.1f s, %.1f ms/hole\n", n, r.seconds, 1000 * r.seconds / n);
  std::printf("    processor time %.1f s (%.1f ms/hole), load average at start %s\n", r.cpu, 1000 * r.cpu / n,
              load_average().c_str());
  std::printf("    stages: patches %.2f s (%d faces added), geometry %.2f s, topology %.2f s, local checks %.2f s, "
              "fallback %.2f s\n",
              d.seconds_patches, d.patched_faces, d.seconds_geometry, d.seconds_topology, d.seconds_checks,
              d.seconds_fallback);
  std::printf("    %d drilled directly (%d wall faces rebuilt), %d through the boolean fallback; worst |divergence - "
              "quadrature| / quadrature %.1e; removed %.4f mm^3\n",
              d.drilled, d.rebuilt_faces, d.fallen_back, worst, d.volume_change);
  for (const auto& [reason, k] : reasons) std::printf("    fallback x%d: %s\n", k, reason.c_str());
  r.ok = true;
  if (global) {
    // Not timed: the global checks the local ones stand in for.
    const auto tg = Clock::now();
    const brep::SolidCheck c = brep::verify_solid(d.part.shape);
    double fallback_removed = 0;
    for (const features::DrilledHole& h : d.holes)
      if (!h.drilled) fallback_removed += h.volume;
    const double expected = w.part_volume - d.volume_change - fallback_removed;
    const bool volume_ok = std::abs(c.volume - expected) <= 1e-6 * w.part_volume;
    r.ok = c.all_passed() && count_solids(d.part.shape) == 1 && volume_ok;
    std::printf("    global check (not timed, %.1f s): %s; volume %.4f mm^3 = part %.4f - removed %.4f %s (%.1e)\n",
                since(tg), c.all_passed() ? "verify_solid passed" : ("FAILED " + c.failed_names()).c_str(), c.volume,
                w.part_volume, d.volume_change + fallback_removed, volume_ok ? "within 1e-6" : "DIFFERS",
                (c.volume - expected) / w.part_volume);
  }
  return r;
}

// The verified boolean path on the same holes (tools with our quadrature as expected volume).
void run_boolean_step(const Workload& w, const std::vector<features::CylindricalHole>& holes,
                      const std::vector<double>& independent) {
  const int n = static_cast<int>(holes.size());
  features::BooleanStep step(features::BooleanOperation::Cut);
  for (std::size_t i = 0; i < holes.size(); ++i) {
    features::FeatureTool t = features::hole_tool(holes[i]);
    if (i < independent.size()) t.expected_volume = independent[i];
    step.add(t);
  }
  const auto t0 = Clock::now();
  try {
    step.apply(w.part);
  } catch (const std::exception& e) {
    std::printf("BooleanStep, %d holes: FAILED after %.1f s: %s\n", n, since(t0), e.what());
    return;
  }
  const double s = since(t0);
  const features::BooleanStepReport& rep = step.report();
  std::printf("BooleanStep, %d holes: %.1f s, %.1f ms/hole, %s (boolean %.1f s, measure %.1f s, verify %.1f s)\n", n,
              s, 1000 * s / n, rep.check.all_passed() ? "all checks passed" : "FAILED", rep.seconds_boolean,
              rep.seconds_measure, rep.seconds_verify);
}

double run_occt_plain(const Workload& w, const std::vector<features::CylindricalHole>& holes,
                      const std::vector<double>& independent, double ours_seconds) {
  const int n = static_cast<int>(holes.size());
  TopTools_ListOfShape args, tls;
  args.Append(w.part.shape);
  double expected = 0;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    tls.Append(features::hole_tool(holes[i]).shape.shape);
    expected += i < independent.size() ? independent[i] : NAN;
  }
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tls);
  cut.SetRunParallel(true);
  cut.SetUseOBB(true);
  cut.SetToFillHistory(false);
  cut.SetCheckInverted(false);
  cut.SetNonDestructive(true);
  cut.Build();
  const double s = since(t0), cpu = cpu_seconds() - c0;
  std::string verdict;
  if (cut.HasErrors()) verdict = "error";
  else {
    GProp_GProps p;
    BRepGProp::VolumeProperties(cut.Shape(), p, 1e-7, true);
    const double removed = w.part_volume - p.Mass();
    const int solids = count_solids(cut.Shape());
    std::ostringstream v;
    v.precision(6);
    v << solids << " solid(s), removed " << removed << " mm^3 of " << expected << " expected"
      << (solids == 1 && std::abs(removed - expected) < 1e-4 * expected ? "" : " (WRONG)")
      << (cut.HasWarnings() ? ", warnings" : "");
    verdict = v.str();
  }
  std::printf("OCCT plain Cut, %d holes: %.1f s, %.1f ms/hole (processor %.1f s), %s; ours / OCCT = %.2f\n", n, s,
              1000 * s / n, cpu, verdict.c_str(), ours_seconds / s);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines appear as they are measured
  std::vector<int> counts{100, 400, 1000}, occt{100, 400}, steps;
  bool quick = false, hollow = false, global = true;
  features::DrillOptions options;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = hollow = true, counts = {12}, occt = {12};
    else if (!std::strcmp(argv[i], "--counts") && i + 1 < argc) counts = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--occt") && i + 1 < argc) occt = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--step") && i + 1 < argc) steps = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--hollow")) hollow = true;
    else if (!std::strcmp(argv[i], "--no-global")) global = false;
    else if (!std::strcmp(argv[i], "--patches")) options.patch_min_holes = 24;
    else {
      std::fprintf(stderr, "usage: bench_holes [--quick] [--counts N,N,...] [--occt N,...] [--step N,...] [--hollow] "
                           "[--no-global] [--patches]\n");
      return 2;
    }
  }
  const auto t0 = Clock::now();
  const Workload w = hollow ? hollow_blade_workload(/*verify_part=*/!quick) : cooled_blade_workload();
  std::printf("part: %s, %.3f mm^3, built in %.1f s (not timed)\n", w.description.c_str(), w.part_volume, since(t0));
  bool all_ok = true;
  double per_hole_first = 0, per_hole_last = 0;
  int first_n = 0, last_n = 0;
  for (const int n : counts) {
    // A case that throws (placement, drilling or a reference) is a failed case, not the end of the bench.
    try {
      const auto tg = Clock::now();
      const std::vector<features::CylindricalHole> holes = w.holes(n);
      std::printf("(%d holes placed: %.1f s, not timed)\n", n, since(tg));
      const OursResult r = run_drill(w, holes, options, global);
      all_ok = all_ok && r.ok;
      if (!first_n) first_n = n, per_hole_first = r.seconds / n;
      last_n = n, per_hole_last = r.seconds / n;
      for (const int m : occt)
        if (m == n) run_occt_plain(w, holes, r.independent, r.seconds);
      for (const int m : steps)
        if (m == n) run_boolean_step(w, holes, r.independent);
    } catch (const std::exception& e) {
      std::printf("FAILED: %d holes: %s\n", n, e.what());
      all_ok = false;
    }
  }
  for (const int m : occt)
    if (m > 0 && std::find(counts.begin(), counts.end(), m) == counts.end()) try {
        run_occt_plain(w, w.holes(m), {}, NAN);
      } catch (const std::exception& e) {
        std::printf("FAILED: OCCT case, %d holes: %s\n", m, e.what());
        all_ok = false;
      }
  if (last_n != first_n)
    std::printf("cost per hole at %d / at %d: %.2f (goal <= 1.5)\n", last_n, first_n, per_hole_last / per_hole_first);
  std::printf("%s\n", all_ok ? "all results verified" : "FAILED: a result did not pass its checks");
  return all_ok ? 0 : 1;
}
