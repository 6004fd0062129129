#include "src/pipeline/build.hpp"

#include "src/brep/blade_solid.hpp"
#include "src/pipeline/cooling.hpp"
#include "src/pipeline/outputs.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::pipeline {

bool BuildResult::valid() const {
  if (checks.empty() || checks.size() != part.size()) return false;
  for (const brep::SolidCheck& c : checks)
    if (!c.all_passed()) return false;
  return true;
}

std::string BuildResult::failed_checks() const {
  std::string s;
  for (std::size_t i = 0; i < checks.size() && i < part.size(); ++i)
    if (!checks[i].all_passed()) s += (s.empty() ? "" : "; ") + part[i].name + ": " + checks[i].failed_names();
  if (checks.size() != part.size()) s += (s.empty() ? "" : "; ") + std::string("not every body was checked");
  return s;
}

blade::BladeModel validate(const config::Config& config, ProgressSink* progress) {
  check_output_options(config);
  blade::BladeModel model = config::build_model(config, progress);
  if (!config.cooling.empty()) validate_cooling(config.cooling, model);  // ms: no solid needed
  return model;
}

BuildResult run_build(const config::Config& config, const BuildOptions& options, ProgressSink* progress) {
  BuildResult r;
  StageRunner stages(progress, r.timings);
  stages.run("blade_model", "blade model", [&] { r.model = validate(config, progress); });
  stages.run("solid", "solid (blade surface trimmed to the flow path)", [&] {
    brep::BladeSolid solid = brep::build_blade_solid(r.model, progress);
    for (const std::string& w : solid.warnings) r.warnings.push_back("solid: " + w);
    r.uncooled = {solid.solid, solid.faces};
    r.part.push_back({"blade", {solid.solid, std::move(solid.faces)}});
  });
  std::optional<brep::SolidCheck> cooled_check;
  if (!config.cooling.empty())
    stages.run("cooling", "cooling features (chambers, ribs, passages)", [&] {
      features::PassagesResult cooled = apply_cooling(config.cooling, r.model, r.part.front().geometry);
      r.part.front().geometry = std::move(cooled.blade);
      r.cooling = std::move(cooled.report);
      cooled_check = cooled.check;
    });
  stages.run("verify", "checks (BRepCheck, free edges, closed mesh, volume)", [&] {
    brep::VerifyOptions vo = options.verify;
    vo.progress = progress;
    // The cooling stage verified the cooled blade with the default options after its last step.
    const brep::VerifyOptions defaults;
    const bool reuse = cooled_check && vo.mesh_relative_deflection == defaults.mesh_relative_deflection &&
                       vo.mesh_angular_deflection == defaults.mesh_angular_deflection;
    for (std::size_t i = 0; i < r.part.size(); ++i)
      r.checks.push_back(i == 0 && reuse ? *cooled_check : brep::verify_solid(r.part[i].geometry.shape, vo));
  });
  return r;
}

}  // namespace cg::pipeline
