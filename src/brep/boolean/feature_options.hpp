#pragma once
// How often the feature stages run brep::verify_solid (BRepCheck, free edges, shells, closed mesh: ~1 s
// each on the cooled blade), and the options every feature stage takes with it.
#include "src/core/progress.hpp"

namespace cg::features {

/// EachStep: verify_solid on the result of every boolean step (a defect is named at the step that makes
/// it). FinalOnly: the steps run their cheap checks and per-tool volume checks but no verify_solid; the
/// caller verifies the final solid once and, if that fails, runs the steps again with EachStep to name the
/// feature to blame (pipeline::run_build does). None: no verify_solid by the steps and no recheck.
enum class Verification { EachStep, FinalOnly, None };

/// Options of a feature stage.
struct FeatureOptions {
  Verification verification = Verification::EachStep;
  /// Progress and cancellation (src/core/progress.hpp); null: none. A stop throws cg::Cancelled.
  ProgressSink* progress = nullptr;
};

}  // namespace cg::features
