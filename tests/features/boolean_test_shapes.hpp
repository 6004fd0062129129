#pragma once
// Small named solids for the verified boolean path tests: a block whose faces are named by side and
// cylinders whose faces all carry the tool's name, with analytic volumes.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <map>
#include <string>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/core/constants.hpp"

namespace cg::test {

using cg::kPi;

/// Every face named `name`.
inline brep::NamedShape named_all(const TopoDS_Shape& s, const std::string& name) {
  brep::NamedShape n{s, {}};
  for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) n.faces.push_back({TopoDS::Face(e.Current()), name});
  return n;
}

/// Block [0, a] x [0, b] x [0, c]; faces "block_top" (z = c), "block_bottom" (z = 0), "block_side".
inline brep::NamedShape named_block(double a, double b, double c) {
  BRepPrimAPI_MakeBox mk(a, b, c);
  brep::NamedShape n{mk.Shape(), {}};
  for (TopExp_Explorer e(mk.Shape(), TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& f = TopoDS::Face(e.Current());
    std::string name = "block_side";
    if (f.IsSame(mk.TopFace())) name = "block_top";
    if (f.IsSame(mk.BottomFace())) name = "block_bottom";
    n.faces.push_back({f, name});
  }
  return n;
}

/// Cylinder tool of radius r from `base` along `dir` over `length`, all faces named `feature`.
inline features::FeatureTool cylinder_tool(const std::string& feature, const gp_Pnt& base, const gp_Dir& dir, double r,
                                           double length, double expected) {
  features::FeatureTool t;
  t.feature = feature;
  t.shape = named_all(BRepPrimAPI_MakeCylinder(gp_Ax2(base, dir), r, length).Shape(), feature);
  t.expected_volume = expected;
  return t;
}

inline int count_name(const brep::NamedShape& s, const std::string& name) {
  return brep::count_face_names(s)[name];
}

}  // namespace cg::test
