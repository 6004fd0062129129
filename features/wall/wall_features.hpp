#pragma once
// The features that stand on or pass through the core's walls after the chambers exist: rib
// turbulators (turbulators.hpp) and the trailing edge's pin fins and ejection slots
// (trailing_edge.hpp). Each group is one verified BooleanStep (verified_boolean.hpp) with the added or
// removed volume of every tool computed independently (ruled_block.hpp, wall_lines.hpp):
//   1. turbulators: Fuse;  2. pin fins: Fuse;  3. slots: Cut.
#include <string>
#include <vector>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_report.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/turbulators.hpp"
#include "src/brep/boolean/feature_options.hpp"
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

/// Builds the turbulator, pin-fin and slot tools of `def` (the slots and pins where `trailing_edge`,
/// the plan's, placed them; the expected volumes need only the model and the core's inner wall, not the
/// part). Throws PassageInputError for input that does not fit, FeatureFailure for OCCT failures in
/// building a tool.
WallFeatureBuild build_wall_feature_tools(const blade::BladeModel& model, const CoreDefinition& def,
                                          const CoreBuild& core, const TrailingEdgePlan& trailing_edge,
                                          PassageReport& report);

/// Applies the tools of `build` to `blade` (the blade with its chambers): one BooleanStep per group
/// (turbulators: Fuse, pin fins: Fuse, slots: Cut), each with its cheap checks and per-tool volume
/// checks, and brep::verify_solid once on the result (the last step report's `check`); only when that
/// fails are the steps redone with verify_solid after each, to name the group and tools to blame.
/// (One boolean for all groups was measured slower: OCCT then intersects the tools with each other,
/// 69 s against 28 s for the three steps' intersections on the example.) Appends stage times and
/// per-tool volume checks to `report`, the step reports to `build`. Throws FeatureFailure when a step fails.
/// `verification` EachStep as described; FinalOnly, None: no verify_solid at all (the caller verifies the final solid).
/// `retries`: what a step may change to get a tool through (boolean_retries.hpp).
brep::NamedShape apply_wall_feature_tools(const brep::NamedShape& blade, WallFeatureBuild& build, PassageReport& report,
                                          Verification verification = Verification::EachStep,
                                          PerturbedRetries retries = PerturbedRetries::Any);

}  // namespace cg::features
