#pragma once
// The product of a build: bodies whose every face carries the name of the feature that made it.
//
// Face names come from boolean history (BRepAlgoAPI Modified/Generated), never from surface identity:
// a face keeps the name of the face it was split from, and a face made by a tool gets the tool's name.
//
// Naming scheme (one string per face; stable, lower case, ASCII):
//   <kind>[_<number>][_<part>][_<number>]   e.g. blade_wall, hub, casing, tip_cap, hub_floor, chamber_2_wall,
//   rib_1, turnaround_1, turbulator_3_012, te_slot_07, pin_fin_013, film_row_2_hole_014,
//   showerhead_1_hole_003, insert_1.
// The *kind* is the leading run of alphabetic words before the first number ("film_row_2_hole_014" ->
// "film_row", "chamber_2_wall" -> "chamber", "blade_wall" -> "blade_wall"); exporters colour and group
// by kind (STEP colours, IGES levels, gmsh physical groups, VTK feature ids) and keep the full name.
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <map>
#include <string>
#include <vector>

namespace cg::brep {

struct NamedFace {
  TopoDS_Face face;  ///< a face of the owning shape (same TShape)
  std::string name;  ///< feature name, see the naming scheme above
};

/// A solid whose faces are named; `faces` lists every face of `shape` exactly once.
struct NamedShape {
  TopoDS_Shape shape;
  std::vector<NamedFace> faces;
};

/// One body of the product: the blade, or an impingement insert (its own solid, not cut from the blade).
struct NamedBody {
  std::string name;  ///< "blade", "insert_1", ...
  NamedShape geometry;
};

/// Everything a build hands to export, meshing and the report; bodies[0] is the blade.
using Part = std::vector<NamedBody>;

/// The kind of a face name (see above): "film_row_2_hole_014" -> "film_row".
std::string feature_kind(const std::string& face_name);

/// Face name -> number of faces with it.
std::map<std::string, int> count_face_names(const NamedShape& shape);

}  // namespace cg::brep
