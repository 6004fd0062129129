// Many small holes through a hollow B-spline blade wall: the verified boolean path
// (features/verified_boolean.hpp) against OCCT's plain path (one BRepAlgoAPI_Cut with all tools), in
// the same run.
//
//   bench_holes            N = 100, 400, 1000 holes (ours, cut and verified), OCCT plain at 100 and 400
//   bench_holes --quick    N = 12 holes, ours and OCCT plain (smoke run, < 10 s on a quiet machine)
//   bench_holes --hollow   the full run on the hollow blade below instead of the cooled example
//   bench_holes --counts 50,200 --occt 50
//
// The full run's work load is the cooled example blade with film rows (cooled_example_workload()); the
// quick one, hollow_blade_workload(): the built-in example blade (hpt_rotor) minus a core ~1.2 mm
// inside its wall; holes D 0.5 mm,
// inclined 30 deg to the surface, drilled from outside into the core, on a staggered grid that fills
// the same field for every N (features/boolean_sample_part.hpp). Each hole's expected removed volume
// comes from our own kernel (ray casting, quadrature), not from OCCT, and is computed before the clock
// starts. Our time covers everything apply() does: disjointness test, patches, the boolean, naming,
// per-hole volume measurement and verify_solid of the result.
//
// Exit status 1 when our result fails a check (or the step throws), 0 otherwise. OCCT's plain result
// is checked (solids, removed volume against the same expectations) and reported, never fatal.
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
#include <sstream>
#include <string>
#include <vector>

#include "features/boolean_sample_part.hpp"
#include "features/film_bench.hpp"
#include "features/film_cavity.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/pipeline/cooling.hpp"
#include "features/verified_boolean.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

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
  std::function<std::vector<features::FeatureTool>(int count)> holes;
};

// The work load of the full run: the built-in example blade with its configured passages (LE chamber,
// 3-pass serpentine, ribs with fillets) and film rows of `count` holes (D 0.3 mm, 30 deg) placed,
// analysed and checked by the film feature (features/film_bench.hpp) against the real chambers, ribs and
// end walls (features/film_cavity.hpp); the expected volumes are the film quadrature.
Workload cooled_example_workload() {
  static const config::Config config = config::builtin_example_config();
  static const blade::BladeModel model = config::build_model(config);
  const brep::BladeSolid solid = brep::build_blade_solid(model);
  static const features::PassagesResult cooled = pipeline::apply_cooling(config.cooling, model, {solid.solid, solid.faces});
  static const features::FilmCavity cavity = features::film_cavity_of_core(model, *config.cooling.passages.core, *cooled.core);
  Workload w;
  std::ostringstream d;
  d << "cooled hpt_rotor blade (passages of the built-in example), " << cooled.blade.faces.size() << " faces";
  w.description = d.str();
  w.part = cooled.blade;
  w.part_volume = cooled.check.volume;
  w.holes = [](int count) { return features::film_bench_holes(cavity.target, count).tools; };
  return w;
}

// The work load of --quick (and --hollow): a part and a generator of `count` disjoint hole tools with
// independent expectations.
Workload hollow_blade_workload(bool verify_part) {
  static const blade::BladeModel model = config::build_model(config::builtin_example_config());
  features::HollowBladeOptions ho;
  ho.verify = verify_part;
  static features::HollowBlade hb;
  hb = features::make_hollow_blade(model, ho);
  Workload w;
  std::ostringstream d;
  d << "hollow hpt_rotor blade, wall " << ho.wall << " mm, " << hb.part.faces.size() << " faces";
  w.description = d.str();
  w.part = hb.part;
  w.part_volume = hb.volume;
  w.holes = [](int count) {
    features::HoleFieldOptions o;
    o.count = count;
    return features::make_hole_tools(model, hb, o);
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
};

OursResult run_ours(const Workload& w, const std::vector<features::FeatureTool>& tools) {
  OursResult r;
  const int n = static_cast<int>(tools.size());
  features::BooleanStep step(features::BooleanOperation::Cut);
  for (const features::FeatureTool& t : tools) step.add(t);
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  try {
    step.apply(w.part);
  } catch (const std::exception& e) {
    r.seconds = since(t0);
    std::printf("%d holes: FAILED after %.1f s: %s\n", n, r.seconds, e.what());
    return r;
  }
  r.seconds = since(t0);
  r.cpu = cpu_seconds() - c0;
  const features::BooleanStepReport& rep = step.report();
  double worst = 0, removed = 0;
  for (const features::ToolReport& t : rep.tools) {
    worst = std::max(worst, std::abs(t.measured_volume - t.expected_volume) / t.expected_volume);
    removed += t.measured_volume;
  }
  r.ok = rep.check.all_passed();
  std::printf("%d holes: %.1f s, %.1f ms/hole\n", n, r.seconds, 1000 * r.seconds / n);
  std::printf("    processor time %.1f s (%.1f ms/hole), load average at start %s\n", r.cpu, 1000 * r.cpu / n,
              load_average().c_str());
  std::printf("    stages: disjoint %.2f s, patches %.2f s (%d faces added), boolean %.2f s, measure %.2f s, "
              "verify %.2f s; %d boolean run(s)\n",
              rep.seconds_disjoint, rep.seconds_patches, rep.patched_faces, rep.seconds_boolean, rep.seconds_measure,
              rep.seconds_verify, rep.boolean_runs);
  std::printf("    result: %s, volume %.4f mm^3 (part %.4f - removed %.4f = %.4f), worst |measured - expected| / "
              "expected %.1e\n",
              r.ok ? "all checks passed" : ("FAILED " + rep.check.failed_names()).c_str(), rep.check.volume,
              w.part_volume, removed, w.part_volume - removed, worst);
  for (const std::string& warning : rep.warnings) std::printf("    note: %s\n", warning.c_str());
  return r;
}

double run_occt_plain(const Workload& w, const std::vector<features::FeatureTool>& tools, double ours_seconds) {
  const int n = static_cast<int>(tools.size());
  TopTools_ListOfShape args, tls;
  args.Append(w.part.shape);
  double expected = 0;
  for (const features::FeatureTool& t : tools) {
    tls.Append(t.shape.shape);
    expected += t.expected_volume;
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
  std::vector<int> counts{100, 400, 1000}, occt{100, 400};
  bool quick = false, hollow = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true, counts = {12}, occt = {12};
    else if (!std::strcmp(argv[i], "--hollow")) hollow = true;
    else if (!std::strcmp(argv[i], "--counts") && i + 1 < argc) counts = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--occt") && i + 1 < argc) occt = parse_list(argv[++i]);
    else {
      std::fprintf(stderr, "usage: bench_holes [--quick] [--hollow] [--counts N,N,...] [--occt N,...]\n");
      return 2;
    }
  }
  const auto t0 = Clock::now();
  const Workload w = quick || hollow ? hollow_blade_workload(/*verify_part=*/!quick) : cooled_example_workload();
  std::printf("part: %s, %.3f mm^3, built in %.1f s\n", w.description.c_str(), w.part_volume, since(t0));
  bool all_ok = true;
  double per_hole_first = 0, per_hole_last = 0;
  int first_n = 0, last_n = 0;
  for (const int n : counts) {
    const auto tg = Clock::now();
    const std::vector<features::FeatureTool> tools = w.holes(n);
    std::printf("(%d hole tools and their expected volumes by ray casting: %.1f s, not timed)\n", n, since(tg));
    const OursResult r = run_ours(w, tools);
    all_ok = all_ok && r.ok;
    if (!first_n) first_n = n, per_hole_first = r.seconds / n;
    last_n = n, per_hole_last = r.seconds / n;
    for (const int m : occt)
      if (m == n) run_occt_plain(w, tools, r.seconds);
  }
  for (const int m : occt)
    if (std::find(counts.begin(), counts.end(), m) == counts.end()) run_occt_plain(w, w.holes(m), NAN);
  if (last_n != first_n)
    std::printf("cost per hole at %d / at %d: %.2f (goal <= 1.5)\n", last_n, first_n, per_hole_last / per_hole_first);
  std::printf("%s\n", all_ok ? "all results verified" : "FAILED: a result did not pass its checks");
  return all_ok ? 0 : 1;
}
