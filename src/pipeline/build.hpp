#pragma once
// The whole job of `coolinggen build` as a library call, for scripts and design studies:
//
//   config::Config c = config::load_config_file("blade.json");
//   pipeline::BuildResult r = pipeline::run_build(c);          // model -> solid -> checks
//   pipeline::write_outputs(c, r, "out/blade_17");             // blade.step ..., report.json last
//
// Stages, in order (ids as in BuildResult::timings, the progress sink and report.json):
//   blade_model  config -> blade model (config::build_model; errors are ConfigError naming the field)
//   solid        blade surface trimmed to the flow path (brep::build_blade_solid) -> Part bodies[0]
//   cooling      the configured cooling features built into bodies[0] (src/pipeline/cooling.hpp; only
//                when the config has a "cooling" section); its last boolean step verifies the blade
//   film         film holes and impingement inserts (when "cooling" has film_rows, showerhead or inserts),
//                against the core of the cooling stage; inserts become bodies insert_1, ... of the Part
//   verify       brep::verify_solid on every body of the Part (the cooled blade's check is reused)
//   coolant_network  the coolant flow network of the valid part, solved by CalculiX (network_job.hpp;
//                only when the config selects the output format "network") -> BuildResult::network
// A later stage slots in as one more StageRunner::run call in run_build (e.g. cooling features applied
// to bodies[0].geometry between "solid" and "verify"); outputs are written by outputs.cpp.
#include <optional>
#include <string>
#include <vector>

#include "src/brep/boolean/feature_options.hpp"
#include "src/brep/verify.hpp"
#include "src/config/config.hpp"
#include "src/core/progress.hpp"
#include "src/pipeline/build_result.hpp"
#include "src/pipeline/stage_cache.hpp"
#include "src/pipeline/time_limit.hpp"

namespace cg::pipeline {

struct BuildOptions {
  /// Options of the solid checks (mesh deflection); `verify.progress` is set by run_build.
  brep::VerifyOptions verify;
  /// EachStep: the feature stages run verify_solid after each of their boolean steps (every other check
  /// of the verified boolean path runs either way). FinalOnly (default): verify_solid runs once, in the
  /// verify stage, on the final blade; only if that fails are the feature stages run again with it
  /// after every step, which names the feature to blame (stages "cooling_rechecked", "film_rechecked").
  /// None: as FinalOnly without the rerun (the verify stage still checks every body).
  features::Verification verification = features::Verification::FinalOnly;
  /// Optional: the cooling stage is taken from this cache when an earlier build stored the same inputs,
  /// and stored in it otherwise (stage_cache.hpp, cooling_stage_cache.hpp). Null: always built.
  StageCache* stage_cache = nullptr;
};

/// Builds and checks the model of `config`. `progress` (optional) sees the stages and may stop the
/// build (Cancelled naming the stage and the step). Throws ConfigError for inputs only the model can
/// reject, InvalidGeometry / AlgorithmFailure when the solid cannot be made. Failed checks do not
/// throw: see BuildResult::valid().
BuildResult run_build(const config::Config& config, const BuildOptions& options = {}, ProgressSink* progress = nullptr);

/// What `coolinggen validate` found: the blade model and what the cooling plan changed in the
/// definition (features::CoolingPlan::notes; a build reports them as warnings "plan: ...").
struct Validation {
  blade::BladeModel model;
  std::vector<std::string> notes;
};

/// What `coolinggen validate` checks without building the solid (the output formats are checked when
/// the config is parsed): the blade model and the cooling input that needs only the model (pipeline/cooling.hpp).
/// Throws ConfigError.
Validation validate(const config::Config& config, ProgressSink* progress = nullptr);

}  // namespace cg::pipeline
