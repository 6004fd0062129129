#pragma once
// The cavity film holes and inserts are built into, taken from the internal passages (core_passages.hpp):
//  - hole target: the core's inner wall, one TargetChamber per chamber (numbered LE to TE as in the
//    passages, chordwise extent from rib centre to rib centre), obstacles: every rib (with its fillets)
//    and the closed end walls (hub floor, tip cap); add_wall_feature_obstacles adds turbulators, pin
//    fins and trailing-edge slots;
//  - insert chambers: per chamber its constant wall thickness, its ends (end walls, or the flow-path
//    surface at an open end), the bounding ribs as splitting tubes thickened by the requested gap.
//
// Rib distance (a lower bound of the distance to the rib's material near the inner wall, where a hole's
// inlet lies): |w| - t / 2 - f, with w the distance from the rib's exact mid-surface along its normal
// (foot by Newton on the ruled surface M(a, s), rib_geometry.hpp) and f the width the fillets add on the
// wall, r / tan(theta / 2) for the smaller corner angle theta between the rib and the wall (r for a rib
// normal to the wall). Ribs are taken to run from the hub floor to the tip cap: beside a turnaround gap
// the bound is conservative (the gap counts as rib).
#include <memory>

#include "features/passages/core_passages.hpp"
#include "features/film/film_cooling.hpp"
#include "features/wall/wall_features.hpp"

namespace cg::features {

/// The hole target of a core: its inner wall, one TargetChamber per ChamberInfo, the ribs and the closed
/// end walls as obstacles. Needs only what build_core_walls makes (inner wall, end walls, chambers), so
/// the plan (features/plan/cooling_plan.hpp) and the film stage (film_cavity_of_core) make it alike.
/// `model` must outlive the result.
HoleTarget hole_target_of_core(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core);

/// The film cavity of a core built by build_core_tools (target: hole_target_of_core). `model` must outlive the result (the target
/// points to it); `core` and `def` are copied where needed.
FilmCavity film_cavity_of_core(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core);

/// The turbulators, pin fins and trailing-edge slots of `walls` as hole obstacles: a hole must keep the
/// film ligament from each (measured from its inlet rim, exact near the tool) and its tool must not reach
/// into one; the error names the row's position field and the feature. Known only once their tools
/// exist, so the build checks the planned holes against them (check_hole_obstacle).
std::vector<TargetObstacle> wall_feature_obstacles(const WallFeatureBuild& walls);

}  // namespace cg::features
