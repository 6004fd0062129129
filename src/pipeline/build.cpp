#include "src/pipeline/build.hpp"

#include "src/brep/blade_solid.hpp"
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
  return config::build_model(config, progress);
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
  stages.run("verify", "checks (BRepCheck, free edges, closed mesh, volume)", [&] {
    brep::VerifyOptions vo = options.verify;
    vo.progress = progress;
    for (const brep::NamedBody& body : r.part) r.checks.push_back(brep::verify_solid(body.geometry.shape, vo));
  });
  return r;
}

}  // namespace cg::pipeline
