#pragma once
// Impingement inserts: a thin sheet-metal shell inside a chamber, its own body in the product (not cut
// from the blade), with an array of jet holes that blow coolant onto the chamber wall.
//
// Geometry (all offsets are true 3D offsets of the outer wall, src/blade/inner_wall.hpp):
//  - the chamber wall is the outer wall offset inward by the wall thickness t_w; the insert's outer
//    surface is the outer wall offset by t_w + Z (Z the jet-to-target gap), its inner surface by
//    t_w + Z + t_s (t_s the sheet thickness). An offset of an offset is the offset by the sum, so the
//    gap to the chamber wall is Z and the sheet t_s wherever the offsets exist (below the wall's radius
//    of curvature; otherwise the insert does not fit and the build says so).
//  - chamber sides: each rib bounding the chamber is a slab; the insert keeps Z (outer) and Z + t_s
//    (inner) from it (the slabs thickened by those amounts are cut away and the piece holding the
//    chamber's reference point is kept).
//  - ends: the chamber's end walls moved into the chamber by the end gaps (hub_gap, tip_gap); a closed
//    end is capped by a sheet t_s thick, an open end leaves the shell open (its inner solid runs past).
//  - jet holes: cylinders of diameter D normal to the sheet (along the outer wall's normal, which is the
//    normal of every offset surface at the same blade coordinate), in lines along the span y D apart,
//    the lines x D apart around the chamber (arc length on the insert's outer surface at mid-span);
//    staggered: every other line shifted by y D / 2. Each jet's expected removed volume is our ray
//    quadrature between the insert's outer and inner surfaces (hole_rays.hpp), no OCCT.
// Booleans: outer solid - inner solid (expected removal: the inner solid's volume when both ends are
// closed, else OCCT's Common), then the jets, through the verified boolean path.
// Names: every sheet face "insert_<k>", jet hole faces "insert_<k>_jet_<nnn>".
#include <functional>
#include <string>
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/film_report.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/blade/inner_wall.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"

namespace cg::features {

/// The chamber an insert goes into.
struct InsertChamber {
  int number = 1;
  std::string name = "chamber_1";
  double wall_thickness = 1;  ///< t_w of the chamber wall (constant), mm
  /// Chordwise extent (as TargetChamber) for the jet lines; the insert itself follows the ribs.
  double suction_from = 0, suction_to = 1, pressure_from = -1, pressure_to = 0;
  /// The chamber's end walls, moved `extra` mm further into the chamber (extra may be < 0 to reach
  /// past them, e.g. for the inner solid of an open end).
  std::function<brep::EndTrim(double extra)> hub_end, tip_end;
  bool hub_open = false, tip_open = false;  ///< the chamber itself runs through that end
  /// The ribs bounding the chamber, thickened by `grow` mm on each side, as shapes that split the
  /// chamber from its neighbours (open rib tubes through the core, or slab solids).
  std::function<std::vector<TopoDS_Shape>(double grow)> rib_walls;
  /// Non-empty: no insert fits this chamber, for this reason (e.g. a turnaround opens it to the next).
  std::string refusal;
  /// The least gap an insert needs here (a rib fillet of radius r leaves less than the gap Z in the
  /// corner unless Z >= r), and why.
  double min_gap = 0;
  std::string min_gap_reason;
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  ///< a point inside the chamber (and the insert)
};

struct InsertBuild {
  brep::NamedBody body;   ///< "insert_<k>"
  InsertMeasure measure;  ///< measured on the built solids when a blade is given
  blade::InnerWall outer_surface, inner_surface;  ///< the offsets by t_w + Z and t_w + Z + t_s
  std::vector<std::pair<std::string, double>> seconds;  ///< stage times
  brep::SolidCheck check;  ///< verify_solid of the insert body (run by its last boolean step)
  std::vector<PerturbedTool> perturbed;  ///< tools of its boolean steps that needed a perturbed retry
};

/// The checks of build_insert that need no geometry (wall, chamber refusal, gap against the fillets,
/// sizes): FilmInputError naming the field below `field` ("inserts[0]").
void check_insert_input(const InsertChamber& chamber, const InsertDefinition& def, int index, const std::string& field);

/// Builds insert `index` (1-based) into `chamber`. `field` is its config path below "cooling" for
/// errors ("inserts[0]"). Throws FilmInputError when it does not fit (offset folds in the chamber, ends
/// cross, no room for a jet line), FeatureFailure when a boolean fails. `retries`: boolean_retries.hpp.
InsertBuild build_insert(const blade::BladeModel& model, const InsertChamber& chamber, const InsertDefinition& def,
                         int index, const std::string& field, ProgressSink* progress = nullptr,
                         PerturbedRetries retries = PerturbedRetries::Any);

/// Measures the insert against the blade on the built solids: the least distance between the bodies
/// (BRepExtrema) and, at sample points of the insert's outer sheet, the gap along the wall normal to the
/// blade and the sheet thickness through the insert (line intersections with the built faces).
void measure_insert(const blade::BladeModel& model, const brep::NamedShape& blade, InsertBuild& insert,
                    const InsertChamber& chamber, const InsertDefinition& def, ProgressSink* progress = nullptr);

}  // namespace cg::features
