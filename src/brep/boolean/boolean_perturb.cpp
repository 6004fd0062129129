#include "src/brep/boolean/boolean_perturb.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdio>

namespace cg::features {

std::optional<gp_Ax1> detect_symmetry_axis(const TopoDS_Shape& tool) {
  std::optional<gp_Ax1> axis;
  std::vector<gp_Dir> plane_normals;
  constexpr double kAngle = 1e-9, kDist = 1e-7;
  for (TopExp_Explorer e(tool, TopAbs_FACE); e.More(); e.Next()) {
    const BRepAdaptor_Surface s(TopoDS::Face(e.Current()), false);
    gp_Ax1 a;
    switch (s.GetType()) {
      case GeomAbs_Plane:
        plane_normals.push_back(s.Plane().Axis().Direction());
        continue;
      case GeomAbs_Cylinder:
        a = s.Cylinder().Axis();
        break;
      case GeomAbs_Cone:
        a = s.Cone().Axis();
        break;
      default:
        return std::nullopt;
    }
    if (!axis) axis = a;
    else if (!axis->IsParallel(a, kAngle) || gp_Lin(*axis).Distance(a.Location()) > kDist)
      return std::nullopt;
  }
  if (!axis) return std::nullopt;
  for (const gp_Dir& n : plane_normals)
    if (!n.IsParallel(axis->Direction(), kAngle)) return std::nullopt;
  return axis;
}

Perturbed perturb_tool(const brep::NamedShape& tool, const std::optional<gp_Ax1>& axis, int attempt, double shift) {
  Perturbed p;
  gp_Trsf t;
  if (axis && attempt % 2 == 1) {
    const double angle = attempt == 1 ? 0.37 : 0.37 + 1.2 * (attempt / 2);
    t.SetRotation(*axis, angle);
    p.same_geometry = true;
    p.what = "rotated " + format_number(angle * 180 / kPi) + " deg about its axis";
  } else {
    gp_Vec d(1, 1, 1);
    if (axis) {
      // Across the axis, diagonal to two perpendicular directions, so a tool tangent to a plane
      // that contains the axis direction leaves the tangency.
      const gp_Vec a(axis->Direction());
      const gp_Vec p = a.Crossed(std::abs(a.X()) < 0.9 ? gp_Vec(1, 0, 0) : gp_Vec(0, 1, 0)).Normalized();
      d = p + a.Crossed(p);
    }
    const double amount = shift * std::max(1, attempt / 2);
    t.SetTranslation(d.Normalized() * amount);
    p.what = "shifted " + format_number(amount) + " mm";
  }
  const TopLoc_Location loc(t);
  p.shape.shape = tool.shape.Moved(loc);
  for (const brep::NamedFace& f : tool.faces) p.shape.faces.push_back({TopoDS::Face(f.face.Moved(loc)), f.name});
  return p;
}

}  // namespace cg::features
