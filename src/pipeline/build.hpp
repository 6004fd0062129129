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
// A later stage slots in as one more StageRunner::run call in run_build (e.g. cooling features applied
// to bodies[0].geometry between "solid" and "verify"); outputs are written by outputs.cpp.
#include <optional>
#include <string>
#include <vector>

#include "features/film/film_report.hpp"
#include "features/passages/passage_report.hpp"
#include "src/brep/boolean/feature_options.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"
#include "src/config/config.hpp"
#include "src/core/progress.hpp"
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

/// What the stage cache did for one stage of a build.
struct StageCacheUse {
  enum class Outcome {
    kHit,        ///< taken from the cache
    kStored,     ///< built and stored
    kNotStored,  ///< built; storing failed (the warning says why)
  };
  std::string stage;
  std::string key;  ///< hex digest of the stage's inputs
  Outcome outcome = Outcome::kStored;
  static const char* name(Outcome o);  ///< "hit", "stored", "not_stored"
};

/// Wall-clock time of one stage, seconds.
struct StageTiming {
  std::string stage;
  double seconds = 0;
};

struct BuildResult {
  blade::BladeModel model;
  /// The product: bodies[0] is the blade ("blade"), each body's faces named (src/brep/named_shape.hpp).
  brep::Part part;
  /// The blade solid before any cooling feature (its faces named): what the coolant domain of
  /// `coolinggen mesh` is cut from (coolant = uncooled - part bodies).
  brep::NamedShape uncooled;
  /// checks[i]: the checks of part[i].
  std::vector<brep::SolidCheck> checks;
  /// Warnings of the stages (e.g. general-fuse alerts), each prefixed with its stage.
  std::vector<std::string> warnings;
  /// Stages in run order.
  std::vector<StageTiming> timings;
  /// The stages that went through BuildOptions::stage_cache, in run order (empty without a cache).
  std::vector<StageCacheUse> stage_cache;
  /// What the cooling stage measured (design checks, passage sections, volumes); none when uncooled.
  std::optional<features::PassageReport> cooling;
  /// What the film stage measured (per hole, row, chamber, insert); none without film input.
  std::optional<features::FilmReport> film;

  /// Every check of every body passed.
  bool valid() const;
  /// "blade: closed_mesh, brep_valid; insert_1: one_solid" (empty when valid).
  std::string failed_checks() const;
};

/// Builds and checks the model of `config`. `progress` (optional) sees the stages and may stop the
/// build (Cancelled naming the stage and the step). Throws ConfigError for inputs only the model can
/// reject, InvalidGeometry / AlgorithmFailure when the solid cannot be made. Failed checks do not
/// throw: see BuildResult::valid().
BuildResult run_build(const config::Config& config, const BuildOptions& options = {}, ProgressSink* progress = nullptr);

/// What `coolinggen validate` checks without building the solid (the output formats are checked when
/// the config is parsed): the blade model (returned) and the cooling input that needs only the model (pipeline/cooling.hpp).
/// Throws ConfigError.
blade::BladeModel validate(const config::Config& config, ProgressSink* progress = nullptr);

}  // namespace cg::pipeline
