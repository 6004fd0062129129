#pragma once
// Trailing-edge cooling: ejection slots from the last chamber through the trailing edge, either along
// the TE centreline or as a pressure-side cutback, and a staggered pin-fin bank upstream of the slots.
//
// Frame per span s (mm, blade-relative: it moves with the section): the inner wall's crease C (the
// chamber's TE end, blade/inner_wall.hpp) and the TE point P (chord +-1).
//  - centreline: origin C, x along C -> P, z along the crease's tangent (made normal to x), the slot
//    |y| <= H / 2, |z| <= (w - 2 x tan(land_taper)) / 2: width w at the crease, narrowing towards the TE.
//    The slot contains the crease, where the last chamber's two wall faces meet on one periodic surface:
//    the slot step first repairs that false seam (false_seams.hpp), else OCCT's boolean drops the
//    crease's split pieces (BOPAlgo_AlertFaceBuilderUnusedEdges on every slot of the example);
//  - pressure-side cutback: origin A = the suction-side foot of the crease, x along the suction surface's
//    tangent there (towards the TE), y towards the pressure side; the slot floor is the plane
//    y = y_f with y_f = y_ps(x_c) - lip - H, x_c = L - cutback_length (L: x of the TE point, y_ps the
//    pressure surface), so under the lip the slot is H high and the lip `lip_thickness` thick; from x_c
//    to the TE everything above the floor is removed (the cutback), between lands whose sides turn by
//    land_taper_deg (slots narrow, lands widen towards the TE).
//  z along the span. A slot starts inside the chamber where its whole inlet face (+0.05 mm) lies in the
//  chamber, and runs 1 mm past the TE.
// Pins: cylinders of diameter D along y across the last chamber, from half the wall thickness inside the
// suction-side wall to half inside the pressure-side wall, in rows at x = x0 - slot_gap - D / 2 - r X
// (x0 the slots' inlet), spanwise pitch S, odd rows shifted by S / 2 (staggered).
// Slots and pins lie between the end walls, span_margin clear of them; positions along the crease line
// at equal arc length (pitch or count, centred).
// Expected volumes (independent of OCCT's boolean): slots = the tool's part inside the material, pins =
// the cylinder's part inside the chamber, both by Gauss-Legendre quadrature of exact line / surface
// crossings (ruled_block.hpp, wall_lines.hpp).
// Face names: te_slot_<nn>, pin_fin_<nnn> (from 01 / 001, hub to tip; pins row by row from the slots).
#include <string>
#include <vector>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_definition.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "features/wall/wall_lines.hpp"

namespace cg::features {

struct SlotInfo {
  std::string name;
  double span = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                  z = Eigen::Vector3d::UnitZ();  ///< the slot's frame (see the header comment)
  double floor_y = 0, height = 0, width = 0;     ///< mm, the slot's floor, height and width at its inlet
  double x_inlet = 0, x_lip = 0, x_end = 0;      ///< mm along x: inlet face, lip (cutback) or TE, tool end
  double y_inlet = 0;                            ///< mm along y: the inlet face's floor
  double te_x = 0, crease_x = 0, crease_y = 0;   ///< mm in the frame: the TE point's x, the crease's x and y
  double removed_volume = 0;                     ///< mm^3, expected (0 until the tool is built)
};

struct PinInfo {
  std::string name;
  double span = 0;
  int row = 0;
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitY();  ///< suction-side end, unit axis
  Eigen::Vector3d z = Eigen::Vector3d::UnitZ();  ///< the TE frame's span direction (the pin's disc quadrature starts from z x axis)
  double length = 0, diameter = 0;  ///< mm (tool length, end to end)
  double chamber_length = 0;        ///< mm, across the chamber along the axis (at the axis)
  double added_volume = 0;          ///< mm^3, expected (0 until the tool is built)
};

/// Where every slot and pin goes (plan_trailing_edge): placed, with every check that needs no tool.
struct TrailingEdgePlan {
  std::vector<SlotInfo> slots;
  std::vector<PinInfo> pins;
  /// Centreline slots cut through the inner wall's crease (see TrailingEdgeBuild::through_crease).
  bool through_crease = false;
};

struct TrailingEdgeBuild {
  std::vector<FeatureTool> slot_tools, pin_tools;
  std::vector<SlotInfo> slots;
  std::vector<PinInfo> pins;
  /// Centreline slots cut through the inner wall's crease: the part's false seam there must be repaired
  /// before the slot step (src/brep/boolean/false_seams.hpp).
  bool through_crease = false;
};

/// mm: how far downstream of the last chamber's end (the inner wall's crease) a cutback's lip must lie.
constexpr double kLipClear = 0.1;

/// A pressure-side cutback whose lip would lie over the last chamber (not kLipClear downstream of its
/// end): "core.trailing_edge.cutback_length" with the limit at the span. The plan
/// (features/plan/cooling_plan.hpp) then tries the wall thickened toward the TE (cutback_wall.hpp).
class LipOverChamber : public PassageInputError {
 public:
  using PassageInputError::PassageInputError;
};

/// Along the slot frame at `span` (see the header comment): the TE point's x less the crease's x, i.e.
/// the longest cutback (less kLipClear) the chamber's end leaves room for. Throws PassageInputError
/// where the inner wall rounds the TE (no crease), blade::InnerWallError where the wall is too thick.
double te_region_length(const blade::BladeCoordinates& coords, const CoreDefinition& def, double span);

/// Checks without geometry: sizes, slot pitch > slot width, count, taper (PassageInputError with
/// "core.trailing_edge.<field>").
void check_trailing_edge_definition(const CoreDefinition& def);
/// The placement of the slots and pins on the core's walls (the planning stage's part,
/// features/plan/cooling_plan.hpp; no tools): the slots' layout between the end walls (pitch, count),
/// each slot's frame, lip, floor and inlet station, each pin's station, axis and length. Throws
/// PassageInputError when they do not fit (a cutback longer than the TE region: LipOverChamber, the slot does not fit
/// the chamber, no suction-side wall left under the cutback or, centreline, less than 0.1 mm beside the
/// slot over the first half of the TE region, a floor through the TE's tip, a taper that closes the slot
/// or (centreline) widens the inlets into each other, pins reaching the last rib or finding no chamber).
TrailingEdgePlan plan_trailing_edge(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core,
                                    WallLines& lines);

/// The slot and pin tools of `plan` (plan_trailing_edge of the same definition and core) with their
/// independent volumes. Throws PassageInputError when a slot's channel leaves the blade early or a pin
/// does not end inside both walls (found by the volume quadrature), FeatureFailure for OCCT failures.
TrailingEdgeBuild build_trailing_edge(const CoreDefinition& def, const TrailingEdgePlan& plan, WallLines& lines);

}  // namespace cg::features
