#include "src/pipeline/build.hpp"

#include "src/brep/blade_solid.hpp"
#include "src/pipeline/cooling.hpp"
#include "src/pipeline/cooling_stage_cache.hpp"
#include "src/pipeline/network_job.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::pipeline {
namespace {

// The message of an exception from a codec (OCCT's Standard_Failure is no std::exception).
std::string failure(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "an OCCT exception in the B-rep reader or writer";
  }
}

// The cooling stage through `cache` (when one is given and on): the stored result of the same inputs,
// else built and stored. A cache that cannot be read or written costs a warning and a build, never the
// build.
//
// Cache or not, what the later stages get is the built result as an entry holds it (encoded and
// decoded): the B-rep reader rebuilds the axes of elementary surfaces (gp_Ax3) to within an ulp, so
// only then is a build bit for bit the same whether its cooling stage came from the cache or not. It
// costs ~0.03 s on the built-in example (1.5 MB of shapes).
features::PassagesResult cooling_stage(const config::Config& c, const features::CoolingPlan& plan, BuildResult& r,
                                       features::Verification verification, StageCache* cache) {
  const bool on = cache && cache->options().mode != StageCacheMode::kOff;
  const std::string key = on ? cooling_stage_key(c, verification) : std::string();
  if (on)
    if (const auto entry = cache->find(kCoolingStage, key)) {
      try {
        features::PassagesResult p = decode_cooling_stage(*entry, r.model);
        r.stage_cache.push_back({kCoolingStage, key, StageCacheUse::Outcome::kHit});
        return p;
      } catch (...) {
        r.warnings.push_back("stage cache: the cooling entry " + key + " could not be read (" + failure(std::current_exception()) +
                             "); built again");
      }
    }
  features::PassagesResult built = apply_cooling(r.model, plan, r.part.front().geometry, verification);
  StageCacheEntry entry;
  features::PassagesResult canonical;
  try {
    entry = encode_cooling_stage(built);
    canonical = decode_cooling_stage(entry, r.model);
  } catch (...) {
    r.warnings.push_back("cooling: the stage's result could not be encoded (" + failure(std::current_exception()) +
                         "); later stages use it as built" + (on ? ", and it was not stored" : ""));
    if (on) r.stage_cache.push_back({kCoolingStage, key, StageCacheUse::Outcome::kNotStored});
    return built;
  }
  if (!on) return canonical;
  try {
    cache->store(kCoolingStage, key, std::move(entry));
    r.stage_cache.push_back({kCoolingStage, key, StageCacheUse::Outcome::kStored});
  } catch (...) {
    r.warnings.push_back("stage cache: the cooling stage was not stored (" + failure(std::current_exception()) + ")");
    r.stage_cache.push_back({kCoolingStage, key, StageCacheUse::Outcome::kNotStored});
  }
  return canonical;
}

}  // namespace

Validation validate(const config::Config& config, ProgressSink* progress) {
  Validation v{config::build_model(config, progress), {}};
  if (!config.cooling.empty()) v.notes = plan_cooling(config.cooling, v.model).notes;  // the plan: no solid needed
  return v;
}

BuildResult run_build(const config::Config& config, const BuildOptions& options, ProgressSink* progress) {
  BuildResult r;
  StageRunner stages(progress, r.timings);
  stages.run("blade_model", "blade model", [&] { r.model = config::build_model(config, progress); });
  // The plan (what validate checks): every placement the feature stages then build on.
  features::CoolingPlan plan;
  if (!config.cooling.empty())
    stages.run("plan", "cooling plan (placements and checks before any boolean)", [&] {
      plan = plan_cooling(config.cooling, r.model);
      r.slots = plan.trailing_edge.slots;
      for (const std::string& note : plan.notes) r.warnings.push_back("plan: " + note);
    });
  stages.run("solid", "solid (blade surface trimmed to the flow path)", [&] {
    brep::BladeSolid solid = brep::build_blade_solid(r.model, progress);
    for (const std::string& w : solid.warnings) r.warnings.push_back("solid: " + w);
    r.uncooled = {solid.solid, solid.faces};
    r.part.push_back({"blade", {solid.solid, std::move(solid.faces)}});
  });
  // Checks the feature stages already ran on a body with the default options, by body index.
  std::vector<std::optional<brep::SolidCheck>> known_checks;
  // The feature stages on the uncooled blade, verified as `verification` says.
  auto build_features = [&](features::Verification verification, const std::string& suffix) {
    r.part.resize(1);
    r.part.front().geometry = r.uncooled;
    known_checks.assign(1, std::nullopt);
    std::optional<features::PassagesResult> cooled;
    if (!config.cooling.passages.empty())
      stages.run("cooling" + suffix, "cooling features (chambers, ribs, passages)", [&] {
        cooled = cooling_stage(config, plan, r, verification, options.stage_cache);
        r.part.front().geometry = cooled->blade;
        r.cooling = cooled->report;
        if (cooled->checked) known_checks[0] = cooled->check;
      });
    if (!config.cooling.film.empty())
      stages.run("film" + suffix, "film cooling holes and impingement inserts", [&] {
        features::FilmCoolingResult film = apply_film(config.cooling, r.model, plan, *cooled, {verification, progress});
        r.part.front().geometry = std::move(film.blade);
        if (film.holes_cut) known_checks[0] = film.blade_checked ? std::optional(film.check) : std::nullopt;
        for (std::size_t i = 0; i < film.inserts.size(); ++i) {
          r.part.push_back(std::move(film.inserts[i]));
          known_checks.push_back(film.insert_checks[i]);
        }
        r.film = std::move(film.report);
      });
  };
  auto verify_bodies = [&](const std::string& suffix) {
    stages.run("verify" + suffix, "checks (BRepCheck, free edges, closed mesh, volume)", [&] {
      brep::VerifyOptions vo = options.verify;
      vo.progress = progress;
      // The feature stages verified their bodies with the default options after their last step.
      const brep::VerifyOptions defaults;
      const bool reuse = vo.mesh_relative_deflection == defaults.mesh_relative_deflection &&
                         vo.mesh_angular_deflection == defaults.mesh_angular_deflection;
      r.checks.clear();
      for (std::size_t i = 0; i < r.part.size(); ++i) {
        const bool known = reuse && i < known_checks.size() && known_checks[i];
        r.checks.push_back(known ? *known_checks[i] : brep::verify_solid(r.part[i].geometry.shape, vo));
      }
    });
  };
  build_features(options.verification, "");
  verify_bodies("");
  if (options.verification == features::Verification::FinalOnly && !config.cooling.empty() && !r.valid()) {
    // A defect one of the deferred steps left: build the features again, each step verified, so the
    // step that makes it throws FeatureFailure naming its feature (or the final checks stay failed).
    r.warnings.push_back("the cooled blade failed " + r.failed_checks() +
                         ": the cooling features were built again with verify_solid after every step");
    build_features(features::Verification::EachStep, "_rechecked");
    verify_bodies("_rechecked");
  }
  if (r.valid() && r.cooling && config.coolant && config::has_format(config.output.formats, config::OutputFormat::Network))
    stages.run("coolant_network", "coolant flow network (CalculiX)", [&] { r.network = solve_network(config, r); });
  return r;
}

}  // namespace cg::pipeline
