#pragma once
// The hollow core with its chambers, ribs, fillets, turnarounds and inlets, as named tool solids for
// the verified boolean cut.
//
// Construction (measured to be the robust order on OCCT 7.6):
//  1. Core solid: the inner wall (src/blade/inner_wall.hpp) between the hub floor and the tip cap (end
//     walls, end_walls.hpp), built like the blade solid (brep::build_blade_solid); an open end uses a
//     cutting surface just outside the blade instead.
//  2. Ribs are open tubes (rib_geometry.hpp); one BRepAlgoAPI_Splitter splits the core by all of them
//     into cells. The cells holding a chamber's reference point (midway between its walls at mid-span)
//     are the coolant; the others are rib material. Chambers joined by a turnaround share a cell.
//  3. Fillets: in each coolant cell the convex edges between a rib face and the inner wall are rounded
//     with the rib's fillet radius (BRepFilletAPI_MakeFillet; tangent edge chains round a turnaround's
//     tip in one go). On the tool these are convex, so the blade gets concave fillets after the cut.
//  4. Names: a turnaround's mid-surface sheet splits its cell so that every wall face lies in exactly
//     one chamber (chamber_<k>_wall), then the pieces are merged back into one solid (merge_cells).
// Face names: chamber_<k>_wall, rib_<i>, rib_<i>_fillet, turnaround_<j>, turnaround_<j>_fillet, tip_cap,
// hub_floor, inlet_<m>; open ends: open_hub / open_tip (outside the blade, they never reach it).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "features/passages/end_walls.hpp"
#include "features/passages/passage_definition.hpp"
#include "features/passages/rib_geometry.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/blade/inner_wall.hpp"

namespace cg::features {

struct ChamberInfo {
  int number = 0;  ///< 1-based, from the LE
  /// Chordwise extent on the inner wall (suction side from..to, pressure side from..to; the LE chamber
  /// starts at 0, the last one ends at the inner wall's crease).
  double suction_from = 0, suction_to = 0, pressure_from = 0, pressure_to = 0;
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  ///< a point inside it at mid-span
  int system = -1;          ///< index into CoreBuild::systems (chambers joined by turnarounds)
  double volume = 0;        ///< mm^3, coolant volume of the chamber (its share of the system's cells)
  bool fed = false;         ///< an inlet or an open end supplies it (directly or through turnarounds)
};

/// Chambers joined by turnarounds: one coolant solid, one tool.
struct ChamberSystem {
  std::vector<int> chambers;  ///< 1-based chamber numbers
  std::string feature;        ///< tool feature name, e.g. "chamber_1" or "chambers_2_4"
  double volume = 0;          ///< mm^3 of the tool (after fillets)
  TopoDS_Shape shape;         ///< the tool solid (also in interior_tools or cut_tools)
};

/// Points that must lie inside an inlet's chamber system: a ring of the inlet's diameter just past the
/// end wall (the inlet opens into its chamber), and the input error when one does not.
struct InletRim {
  int system = -1;  ///< index into CoreBuild::systems (set with the cells, build_core_cells)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< on the axis, the ring's centre
  std::vector<Eigen::Vector3d> points;
  std::string field, message;
};

/// An inlet as the plan places it (build_core_walls), the one placement its check and its tool use: a
/// cylinder of `radius` along the unit `axis` (into the chamber) from origin + from * axis, outside the
/// blade, to origin + to * axis, past the end wall; origin is its chamber's point on the flow path's end.
struct InletPlacement {
  std::string name;  ///< inlet_<m>
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::Zero();
  double from = 0, to = 0, radius = 0;
  InletRim rim;
};

struct CoreBuild {
  blade::InnerWall inner_wall;
  std::vector<RibTube> ribs;
  std::vector<ChamberInfo> chambers;
  std::vector<ChamberSystem> systems;
  /// Chamber systems with both ends closed: strictly inside the blade (inside the inner wall, between
  /// the end walls), so they can be inserted as voids; expected volume = their own volume.
  std::vector<FeatureTool> interior_tools;
  /// Tools that reach out of the blade: chamber systems through an open end (expected volume NaN: the
  /// boolean path computes the overlap), then one cylinder per inlet ("inlet_<m>", expected volume =
  /// the material between the flow-path surface and the end wall over its disc, own quadrature).
  std::vector<FeatureTool> cut_tools;
  std::vector<double> inlet_volumes;  ///< mm^3 per inlet, as its expected volume
  /// Per inlet (build_core_walls): its rim checked there against the inner wall and the end wall, and
  /// against its chamber system's solid by check_inlet_rims.
  std::vector<InletPlacement> inlets;
  std::optional<EndWall> hub_floor, tip_cap;  ///< none when that end is open
  double core_volume = 0;                     ///< mm^3, the core before ribs and fillets (sum of its cells)
  std::vector<double> rib_volumes;            ///< mm^3 per rib, rib material inside the core
  std::vector<double> fillet_volumes;         ///< mm^3 per rib, material its fillets leave in the blade
  std::vector<std::pair<std::string, double>> seconds;  ///< stage timings
};

/// Builds the core tools for `model`. Input that cannot be built throws PassageInputError naming the
/// field below "cooling" (and the span / chord where it fails); OCCT failures throw FeatureFailure.
CoreBuild build_core_tools(const blade::BladeModel& model, const CoreDefinition& def);

/// build_core_tools in three parts, so that work which needs only some of it can run alongside the
/// rest (build_passages): build_core_walls builds, for a `def` that check_core_definition passed (the
/// plan runs both, as build_core_tools does), the inner wall, the closed end walls (inner_wall,
/// hub_floor, tip_cap), the chambers' extents (chambers, without volumes) and the inlets (inlets: a
/// rim that leaves the inner wall or lies beyond the end wall is refused here) (stage "inner_wall"; no
/// solid), which is all the turbulator, pin and slot tools and the film holes' target need;
/// build_core_cells adds the core solid, ribs, cells, fillets, names and inlets to `core` (the walls
/// stay as they are: a copy of `core` taken before it is as good for the wall-feature tools);
/// check_inlet_rims throws the PassageInputError of the first inlet whose rim leaves its chamber (point
/// classification against the chamber solids only: safe beside booleans that read them; what the walls
/// alone decide was refused by build_core_walls, this adds the ribs and their fillets).
CoreBuild build_core_walls(const blade::BladeModel& model, const CoreDefinition& def);
void build_core_cells(const blade::BladeModel& model, const CoreDefinition& def, CoreBuild& core);
void check_inlet_rims(const CoreBuild& core);

/// The input checks of build_core_tools that need no solid (ordering, turnarounds against open ends,
/// inlets, coolant supply, the inner wall's trailing-edge crossing and the ribs' placement on five spans),
/// in a few ms: `coolinggen validate` and the build's first stage run them. Throws PassageInputError.
void check_core_definition(const blade::BladeModel& model, const CoreDefinition& def);

/// The reference point of a chamber: midway between its suction- and pressure-side inner-wall points at
/// the middle of its chordwise extent, at `span`.
Eigen::Vector3d chamber_point(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                              const ChamberInfo& c, double span);

}  // namespace cg::features
