// bench_cooled_build: config -> verified STEP of a cooled blade, with stage times (the cooling stage split
// into its steps), and the chambers' insertion as checked voids against OCCT's BRepAlgoAPI_Cut of the
// same tools from the same blade (time ratio; the two results' volumes must agree, else exit 1).
//
//   bench_cooled_build            the built-in example (HPT rotor: LE chamber + 3-pass serpentine)
//   bench_cooled_build --quick    the C3X vane with its ten radial passages, and one closed chamber in it
//   bench_cooled_build CONFIG     any config with a "cooling" section
#include <BRepAlgoAPI_Cut.hxx>
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
#include <filesystem>
#include <string>

#include "features/core_passages.hpp"
#include "features/passage_boolean.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/outputs.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

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
  std::printf("%s: config -> verified STEP in %.2f s (%s)\n", what, total, r.valid() ? "valid" : r.failed_checks().c_str());
  for (const auto& s : r.timings) std::printf("  %-12s %7.3f s\n", s.stage.c_str(), s.seconds);
  for (const auto& s : w.timings) std::printf("  %-12s %7.3f s\n", s.stage.c_str(), s.seconds);
  if (r.cooling)
    for (const auto& [stage, s] : r.cooling->seconds) std::printf("    cooling/%-24s %7.3f s\n", stage.c_str(), s);
  std::error_code ec;
  fs::remove_all(dir, ec);
  return r.valid() && (!r.cooling || r.cooling->passed());
}

// The chambers of `core` into the blade of `model`: as checked voids (ours) and by one OCCT Cut.
bool voids_against_cut(const blade::BladeModel& model, const features::CoreDefinition& core) {
  const brep::BladeSolid s = brep::build_blade_solid(model);
  const brep::NamedShape blade{s.solid, s.faces};
  const features::CoreBuild cb = features::build_core_tools(model, core);
  auto t0 = std::chrono::steady_clock::now();
  features::PassageBooleanReport rep;
  const brep::NamedShape ours = features::apply_passage_tools(blade, cb.interior_tools, {}, rep);
  const double t_ours = seconds_since(t0);
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
  return agree;
}

}  // namespace

int main(int argc, char** argv) {
  // OCCT's data exchange prints transfer statistics through the default messenger; keep stdout ours.
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
  const std::string arg = argc > 1 ? argv[1] : "";
  const bool quick = arg == "--quick";
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
      const config::Config c = arg.empty() ? config::builtin_example_config() : config::load_config_file(arg);
      ok &= timed_build(c, c.name.c_str());
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
