// bench_cooled_build: config -> verified STEP of a cooled blade, with stage times (the cooling stage split
// into its steps), and the chambers' insertion as checked voids against OCCT's BRepAlgoAPI_Cut of the
// same tools from the same blade (time ratio; the two results' volumes must agree, else exit 1).
//
//   bench_cooled_build            the built-in example (HPT rotor: LE chamber + 3-pass serpentine with
//                                 turbulators, a TE cutback with pin fins, film rows and a showerhead),
//                                 then the same without its film cooling (internal passages only); the
//                                 wall features against OCCT's plain Fuse + Cut of the same tools
//   bench_cooled_build --quick    the C3X vane with its ten radial passages, and one closed chamber in it
//   bench_cooled_build CONFIG     any config with a "cooling" section
//   bench_cooled_build --wall     the built-in example's chambers and wall features only, ours only (no
//                                 full build, no OCCT comparison: for profiling the cooling booleans)
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopTools_ListOfShape.hxx>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_boolean.hpp"
#include "features/wall/wall_features.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/outputs.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

bool g_compare_occt = true;  // off with --wall

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double volume(const TopoDS_Shape& s) {
  GProp_GProps p;
  BRepGProp::VolumeProperties(s, p, 1e-9);
  return p.Mass();
}

// config -> build -> files; prints the stages. Returns false when the build's checks fail.
bool timed_build(const config::Config& c, const char* what) {
  const fs::path dir = fs::temp_directory_path() / ("cg_bench_cooled_" + std::to_string(::getpid()));
  const auto t0 = std::chrono::steady_clock::now();
  const pipeline::BuildResult r = pipeline::run_build(c);
  const pipeline::WrittenOutputs w = pipeline::write_outputs(c, r, dir);
  const double total = seconds_since(t0);
  // The goal's measure: every build stage and the STEP file (the other outputs come after it).
  double to_step = 0;
  for (const auto& s : r.timings) to_step += s.seconds;
  for (const auto& s : w.timings)
    if (s.stage == "step") to_step += s.seconds;
  std::printf("%s: config -> verified STEP in %.2f s, all outputs in %.2f s (%s)\n", what, to_step, total,
              r.valid() ? "valid" : r.failed_checks().c_str());
  for (const auto& s : r.timings) std::printf("  %-12s %7.3f s\n", s.stage.c_str(), s.seconds);
  double step = 0, iges = 0;
  for (const auto& s : w.timings) {
    std::printf("  %-12s %7.3f s\n", s.stage.c_str(), s.seconds);
    if (s.stage == "step") step = s.seconds;
    if (s.stage == "iges") iges = s.seconds;
  }
  if (step > 0 && iges > 0) std::printf("  IGES / STEP stage: %.2f (goal <= 2)\n", iges / step);
  if (!r.checks.empty())
    for (const brep::Check* c : r.checks.front().checks()) std::printf("    verify/%-25s %7.3f s\n", c->name.c_str(), c->seconds);
  if (r.cooling)
    for (const auto& [stage, s] : r.cooling->seconds) std::printf("    cooling/%-24s %7.3f s\n", stage.c_str(), s);
  if (r.film)
    for (const auto& [stage, s] : r.film->seconds) std::printf("    film/%-27s %7.3f s\n", stage.c_str(), s);
  std::error_code ec;
  fs::remove_all(dir, ec);
  return r.valid() && (!r.cooling || r.cooling->passed());
}

void print_steps(const features::WallFeatureBuild& wb) {
  for (std::size_t k = 0; k < wb.steps.size(); ++k)
    std::printf("    %-12s boolean %.3f (intersect %.3f) / measure %.3f / verify %.3f s, %d boolean run(s)\n",
                wb.step_names[k].c_str(), wb.steps[k].seconds_boolean, wb.steps[k].seconds_intersect,
                wb.steps[k].seconds_measure, wb.steps[k].seconds_verify, wb.steps[k].boolean_runs);
}

// Turbulators, pin fins and slots into the blade with its chambers: our three verified BooleanSteps
// against OCCT's plain multi-tool Fuse (turbulators and pins) then Cut (slots) of the same tools, with the
// same final checks; the two results' volumes must agree.
bool wall_features_against_occt(const blade::BladeModel& model, const features::CoreDefinition& core,
                                const features::CoreBuild& cb, const brep::NamedShape& with_chambers) {
  features::PassageReport report;
  auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  features::WallLines lines(model.surface, cb.inner_wall.surface);
  const features::TrailingEdgePlan te = features::plan_trailing_edge(model, core, cb, lines);
  features::WallFeatureBuild wb = features::build_wall_feature_tools(model, core, cb, te, report);
  const double t_tools = seconds_since(t0), cpu_tools = double(std::clock() - c0) / CLOCKS_PER_SEC;
  for (const auto& [stage, sec] : report.seconds) std::printf("    %-24s %7.3f s\n", stage.c_str(), sec);
  t0 = std::chrono::steady_clock::now();
  const brep::NamedShape ours = features::apply_wall_feature_tools(with_chambers, wb, report);
  const double t_ours = seconds_since(t0);
  if (!g_compare_occt) {
    double e[3] = {0, 0, 0};
    for (const auto& t : wb.turbulators.tools) e[0] += t.expected_volume;
    for (const auto& t : wb.trailing_edge.pin_tools) e[1] += t.expected_volume;
    for (const auto& t : wb.trailing_edge.slot_tools) e[2] += t.expected_volume;
    std::printf("tools CPU %.3f s\n", cpu_tools);
    std::printf("turbulators + pin fins + slots: tools %.3f s, ours %.3f s, volume %.6f mm^3; expected %.12g / %.12g / "
                "%.12g mm^3\n", t_tools, t_ours, volume(ours.shape), e[0], e[1], e[2]);
    print_steps(wb);
    return true;
  }
  t0 = std::chrono::steady_clock::now();
  TopTools_ListOfShape args, fuse_tools, cut_tools;
  args.Append(with_chambers.shape);
  for (const auto& t : wb.turbulators.tools) fuse_tools.Append(t.shape.shape);
  for (const auto& t : wb.trailing_edge.pin_tools) fuse_tools.Append(t.shape.shape);
  for (const auto& t : wb.trailing_edge.slot_tools) cut_tools.Append(t.shape.shape);
  TopoDS_Shape occt = with_chambers.shape;
  bool done = true;
  if (!fuse_tools.IsEmpty()) {
    BRepAlgoAPI_Fuse fuse;
    fuse.SetArguments(args);
    fuse.SetTools(fuse_tools);
    fuse.SetRunParallel(true);
    fuse.Build();
    done &= fuse.IsDone();
    if (done) occt = fuse.Shape();
  }
  if (done && !cut_tools.IsEmpty()) {
    TopTools_ListOfShape a2;
    a2.Append(occt);
    BRepAlgoAPI_Cut cut;
    cut.SetArguments(a2);
    cut.SetTools(cut_tools);
    cut.SetRunParallel(true);
    cut.Build();
    done &= cut.IsDone();
    if (done) occt = cut.Shape();
  }
  const brep::SolidCheck occt_check = brep::verify_solid(occt);
  const double t_occt = seconds_since(t0);
  const double v_ours = volume(ours.shape), v_occt = done ? volume(occt) : 0;
  const bool agree = done && std::abs(v_ours - v_occt) <= 1e-6 * v_occt;
  std::printf("turbulators + pin fins + slots (%zu + %zu + %zu tools; tools built in %.3f s): ours (3 checked steps, verify_solid once) "
              "%.3f s, OCCT Fuse + Cut + checks %.3f s, ratio %.2fx; volumes %.6f / %.6f mm^3 %s; OCCT result checks %s\n",
              wb.turbulators.tools.size(), wb.trailing_edge.pin_tools.size(), wb.trailing_edge.slot_tools.size(), t_tools,
              t_ours, t_occt, t_occt / t_ours, v_ours, v_occt, agree ? "agree" : "DISAGREE",
              occt_check.all_passed() ? "pass" : occt_check.failed_names().c_str());
  print_steps(wb);
  return agree;
}

// The chambers of `core` into the blade of `model`: as checked voids (ours) and by one OCCT Cut; then
// the turbulators, pins and slots (if any) against OCCT.
bool voids_against_cut(const blade::BladeModel& model, const features::CoreDefinition& core) {
  const brep::BladeSolid s = brep::build_blade_solid(model);
  const brep::NamedShape blade{s.solid, s.faces};
  const features::CoreBuild cb = features::build_core_tools(model, core);
  auto t0 = std::chrono::steady_clock::now();
  features::PassageBooleanReport rep;
  const brep::NamedShape ours = features::apply_passage_tools(blade, cb.interior_tools, {}, rep);
  const double t_ours = seconds_since(t0);
  if (!g_compare_occt) {
    std::printf("chambers into the blade (%zu tools): ours (voids + checks) %.3f s\n", cb.interior_tools.size(), t_ours);
    return core.turbulators.empty() && !core.trailing_edge ? true : wall_features_against_occt(model, core, cb, ours);
  }
  t0 = std::chrono::steady_clock::now();
  BRepAlgoAPI_Cut cut;
  TopTools_ListOfShape args, tools;
  args.Append(blade.shape);
  for (const auto& t : cb.interior_tools) tools.Append(t.shape.shape);
  cut.SetArguments(args);
  cut.SetTools(tools);
  cut.SetRunParallel(true);
  cut.Build();
  const brep::SolidCheck occt_check = brep::verify_solid(cut.Shape());  // the same checks as ours
  const double t_occt = seconds_since(t0);
  const double v_ours = volume(ours.shape), v_occt = cut.IsDone() ? volume(cut.Shape()) : 0;
  const bool agree = cut.IsDone() && std::abs(v_ours - v_occt) <= 1e-6 * v_occt;
  std::printf("chambers into the blade (%zu tools): ours (voids + checks) %.3f s, OCCT Cut + checks %.3f s, ratio %.1fx;"
              " volumes %.6f / %.6f mm^3 %s; OCCT result checks %s\n",
              cb.interior_tools.size(), t_ours, t_occt, t_occt / t_ours, v_ours, v_occt, agree ? "agree" : "DISAGREE",
              occt_check.all_passed() ? "pass" : occt_check.failed_names().c_str());
  if (agree && (!core.turbulators.empty() || core.trailing_edge))
    return wall_features_against_occt(model, core, cb, ours);
  return agree;
}

}  // namespace

int main(int argc, char** argv) {
  // OCCT's data exchange prints transfer statistics through the default messenger; keep stdout ours.
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
  const std::string arg = argc > 1 ? argv[1] : "";
  const bool quick = arg == "--quick", wall_only = arg == "--wall";
  g_compare_occt = !wall_only;
  bool ok = true;
  try {
    if (quick) {
      const config::Config c = config::load_config_file(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json");
      ok &= timed_build(c, "c3x_vane (10 radial passages)");
      // One closed chamber in the C3X vane: the void insertion against OCCT's Cut.
      const config::Config v = config::load_config_file(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane_open_chamber.json");
      features::CoreDefinition core = *v.cooling.passages.core;
      core.tip_cap = {3.0, false};
      features::InletDefinition in;
      in.diameter = 10;
      core.inlets = {in};
      ok &= voids_against_cut(config::build_model(v), core);
    } else {
      const config::Config c = arg.empty() || wall_only ? config::builtin_example_config() : config::load_config_file(arg);
      if (!wall_only) ok &= timed_build(c, c.name.c_str());
      if (arg.empty()) {
        // The internal passages alone (no film rows, no showerhead): the cooled example of the
        // internal-passages issue, whose goal is config -> verified STEP in 10 s.
        config::Config passages = c;
        passages.cooling.film = {};
        ok &= timed_build(passages, (c.name + ", internal passages only").c_str());
      }
      if (c.cooling.passages.core) {
        features::CoreDefinition core = *c.cooling.passages.core;
        if (!core.hub_floor.open && !core.tip_cap.open) ok &= voids_against_cut(config::build_model(c), core);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_cooled_build: %s\n", e.what());
    return 1;
  }
  return ok ? 0 : 1;
}
