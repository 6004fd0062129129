#pragma once
// Rib turbulators: transverse ribs of height e and width w standing on the suction- and/or
// pressure-side inner wall of a chamber, at pitch P along the passage axis and an angle to it, inline or
// staggered between the two walls; fused onto the blade (material added) through the verified boolean
// path.
//
// Placement (blade-relative, so they move with the blade): on each wall the passage axis is the iso-line
// of the outer surface through the middle of the chamber's wall at mid-span; turbulator centres lie on it
// at equal arc-length steps P (centred in the chamber's straight part: clear of the end walls and the
// U-bends by span_margin). Around each centre the wall is developed by its local metric (x chordwise
// from the LE side, y along the passage axis, mm); the turbulator is the strip |y' | <= w / 2 across its
// centre line at `angle` to the axis, from end_gap past the LE-side rib's fillet to end_gap short of the
// TE-side rib's fillet. Its top is the inner wall offset by e into the chamber (points S - (t + e) n, S
// the outer wall, n its outward normal, t the wall thickness at the centre); its bottom the same strip at
// depth t / 2 inside the wall. Both are interpolated on one 13 x 3 grid (cubic x quadratic) and joined by
// ruled sides (ruled_block.hpp), so the expected added volume (the block's part inside the chamber) is
// integrated exactly against the inner wall surface.
// Face names: turbulator_<chamber>_<nnn>, nnn from 001: suction side first, hub to tip, then pressure side.
#include <string>
#include <vector>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_definition.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "features/wall/wall_lines.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {

struct TurbulatorInfo {
  std::string name;   ///< turbulator_<chamber>_<nnn>
  int chamber = 0;
  int definition = 0;  ///< index into CoreDefinition::turbulators
  bool suction = true;
  double span = 0;     ///< span fraction of the centre
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< centre of its top face
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< outward wall normal at the centre
  double height = 0, width = 0, length = 0;          ///< mm (length along its centre line)
  double added_volume = 0;                           ///< mm^3, expected (inside the chamber)
};

struct TurbulatorBuild {
  std::vector<FeatureTool> tools;
  std::vector<TurbulatorInfo> turbulators;
};

/// The checks without geometry: chamber number and that it lies between two ribs, sizes, angle in
/// [30, 90] deg, pitch > width / sin(angle). Throws PassageInputError ("core.turbulators[i].<field>").
void check_turbulator_definitions(const CoreDefinition& def);

/// What build_turbulators makes: the tools (and their expected volumes), or only the placement (spans,
/// ends between the ribs' fillets, height against the chamber: `turbulators` without volumes, no tools),
/// which needs only the core's walls and no B-rep (the plan, features/plan/cooling_plan.hpp).
enum class TurbulatorOutput { kTools, kPlacement };

/// Builds the turbulator tools of `def` in the chambers of `core`. Throws PassageInputError when they do
/// not fit (taller than the chamber, no room between the end walls), FeatureFailure for OCCT failures.
TurbulatorBuild build_turbulators(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core,
                                  WallLines& lines, TurbulatorOutput output = TurbulatorOutput::kTools);

}  // namespace cg::features
