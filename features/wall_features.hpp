#pragma once
// The features that stand on or pass through the core's walls after the chambers exist: rib
// turbulators (turbulators.hpp) and the trailing edge's pin fins and ejection slots
// (trailing_edge.hpp). Each group is one verified BooleanStep (verified_boolean.hpp) with the added or
// removed volume of every tool computed independently (ruled_block.hpp, wall_lines.hpp):
//   1. turbulators: Fuse;  2. pin fins: Fuse;  3. slots: Cut.
#include <string>
#include <vector>

#include "features/core_passages.hpp"
#include "features/passage_report.hpp"
#include "features/trailing_edge.hpp"
#include "features/turbulators.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct WallFeatureBuild {
  TurbulatorBuild turbulators;
  TrailingEdgeBuild trailing_edge;
  std::vector<BooleanStepReport> steps;  ///< one per applied group, in order
  std::vector<std::string> step_names;   ///< "turbulators", "pin_fins", "te_slots"
};

/// The checks of the definitions that need no geometry (PassageInputError).
void check_wall_feature_definitions(const CoreDefinition& def);

/// Builds and applies the turbulators, pin fins and slots of `def` to `blade` (the blade with its
/// chambers). Appends stage times and per-tool volume checks to `report`. Throws PassageInputError for
/// input that does not fit, FeatureFailure when a boolean step fails.
brep::NamedShape apply_wall_features(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core,
                                     const brep::NamedShape& blade, PassageReport& report, WallFeatureBuild* build = nullptr);

}  // namespace cg::features
