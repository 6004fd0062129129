#include "features/wall/ruled_block.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <GeomFill.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/brep/naming/face_names.hpp"
#include "src/analyze/cell_quadrature.hpp"
#include "src/brep/boolean/verified_boolean.hpp"

namespace cg::features {

BSplineSurface<3> bilinear_patch(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                                 const Eigen::Vector3d& p11) {
  return BSplineSurface<3>(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{p00, p01}, {p10, p11}});
}

namespace {

bool is_bilinear(const BSplineSurface<3>& s) {
  return s.degree_u() == 1 && s.degree_v() == 1 && s.num_poles_u() == 2 && s.num_poles_v() == 2;
}

// A plane face for a quadrilateral (corners in cyclic order) whose corners lie on one plane to 1e-10 mm,
// else a null face. OCCT intersects planes analytically: a slot tool of planes cuts the blade (and joins
// its cutback block) several times faster than the same faces as bilinear B-splines.
TopoDS_Face planar_quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d) {
  const Eigen::Vector3d n = (c - a).cross(d - b);
  if (!(n.norm() > 0)) return {};
  if (std::abs(n.normalized().dot(b - a)) > 1e-10 || std::abs(n.normalized().dot(d - a)) > 1e-10) return {};
  BRepBuilderAPI_MakePolygon poly(occt::to_pnt(a), occt::to_pnt(b), occt::to_pnt(c), occt::to_pnt(d), /*Close=*/true);
  if (!poly.IsDone()) return {};
  BRepBuilderAPI_MakeFace face(poly.Wire(), /*OnlyPlane=*/true);
  return face.IsDone() ? face.Face() : TopoDS_Face();
}

}  // namespace

brep::NamedShape ruled_block_solid(const RuledBlock& block, const std::string& name) {
  const Handle(Geom_BSplineSurface) b = occt::to_occt(block.bottom), t = occt::to_occt(block.top);
  double u0, u1, v0, v1;
  b->Bounds(u0, u1, v0, v1);
  std::vector<Handle(Geom_Surface)> surfaces{Handle(Geom_Surface)(b), Handle(Geom_Surface)(t)};
  // The sides: ruled surfaces between the same iso-curve of the bottom and of the top.
  for (int k = 0; k < 4; ++k) {
    const bool iso_u = k < 2;
    const double p = iso_u ? (k == 0 ? u0 : u1) : (k == 2 ? v0 : v1);
    const Handle(Geom_Curve) cb = iso_u ? b->UIso(p) : b->VIso(p);
    const Handle(Geom_Curve) ct = iso_u ? t->UIso(p) : t->VIso(p);
    surfaces.push_back(GeomFill::Surface(cb, ct));
  }
  // Faces of a block between two bilinear patches are quadrilaterals: the planar ones become planes.
  std::vector<TopoDS_Face> planes(surfaces.size());
  if (is_bilinear(block.bottom) && is_bilinear(block.top)) {
    const auto B = [&](int i, int j) -> Eigen::Vector3d { return block.bottom.pole(i, j); };
    const auto T = [&](int i, int j) -> Eigen::Vector3d { return block.top.pole(i, j); };
    planes[0] = planar_quad(B(0, 0), B(1, 0), B(1, 1), B(0, 1));
    planes[1] = planar_quad(T(0, 0), T(1, 0), T(1, 1), T(0, 1));
    planes[2] = planar_quad(B(0, 0), B(0, 1), T(0, 1), T(0, 0));  // u = u0
    planes[3] = planar_quad(B(1, 0), B(1, 1), T(1, 1), T(1, 0));  // u = u1
    planes[4] = planar_quad(B(0, 0), B(1, 0), T(1, 0), T(0, 0));  // v = v0
    planes[5] = planar_quad(B(0, 1), B(1, 1), T(1, 1), T(0, 1));  // v = v1
  }
  BRepBuilderAPI_Sewing sew(1e-6);
  for (std::size_t k = 0; k < surfaces.size(); ++k)
    sew.Add(planes[k].IsNull() ? BRepBuilderAPI_MakeFace(surfaces[k], 1e-9).Face() : planes[k]);
  sew.Perform();
  TopoDS_Shell shell;
  int shells = 0;
  for (TopExp_Explorer e(sew.SewedShape(), TopAbs_SHELL); e.More(); e.Next(), ++shells) shell = TopoDS::Shell(e.Current());
  if (shells != 1 || sew.NbFreeEdges() != 0) throw FeatureFailure(name + ": its faces do not sew into one closed shell");
  BRepBuilderAPI_MakeSolid ms(shell);
  TopoDS_Solid solid = ms.Solid();
  BRepLib::OrientClosedSolid(solid);
  brep::NamedShape out;
  out.shape = solid;
  for (const TopoDS_Shape& f : faces_of(solid)) out.faces.push_back({TopoDS::Face(f), name});
  return out;
}

namespace {
// Distinct knots of a knot vector between the first and last parameter of the domain.
std::vector<double> breaks(const std::vector<double>& knots, int degree) {
  std::vector<double> out(knots.begin() + degree, knots.end() - degree);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}
}  // namespace

BlockIntegral integrate_block(const RuledBlock& block, WallLines& lines, Region start, Region wanted, Region end,
                              const BlockQuadrature& q) {
  std::vector<double> ba = breaks(block.bottom.knots_u(), block.bottom.degree_u());
  for (double a : q.breaks_a)
    if (a > ba.front() && a < ba.back()) ba.push_back(a);
  std::sort(ba.begin(), ba.end());
  const std::vector<double> bb = breaks(block.bottom.knots_v(), block.bottom.degree_v());
  // Two-point Gauss-Legendre on [0, 1]: exact for det, a quadratic in l.
  const double g = 0.5 / std::sqrt(3.0);
  BlockIntegral out;
  for (std::size_t i = 0; i + 1 < ba.size(); ++i)
    for (std::size_t j = 0; j + 1 < bb.size(); ++j)
      gauss_legendre(ba[i], ba[i + 1], q.cells_a, [&](double a, double wa) {
        gauss_legendre(bb[j], bb[j + 1], q.cells_b, [&](double b, double wb) {
          const auto db = block.bottom.derivatives<1>(a, b);
          const auto dt = block.top.derivatives<1>(a, b);
          const Eigen::Vector3d yl = dt.S() - db.S();
          auto det = [&](double l) {
            const Eigen::Vector3d ya = db.S_u() + l * (dt.S_u() - db.S_u());
            const Eigen::Vector3d yb = db.S_v() + l * (dt.S_v() - db.S_v());
            return std::abs(ya.cross(yb).dot(yl));
          };
          auto integral = [&](double l0, double l1) {
            const double m = 0.5 * (l0 + l1), h = l1 - l0;
            return 0.5 * h * (det(m - g * h) + det(m + g * h));
          };
          Region reached;
          const Intervals iv = lines.intervals(db.S(), dt.S(), start, wanted, &reached, q.chamber);
          if (end != Region::Any && reached != end) out.ok = false;
          double part = 0;
          for (const auto& [l0, l1] : iv) part += integral(l0, l1);
          out.volume += wa * wb * integral(0, 1);
          out.in_region += wa * wb * part;
        });
      });
  return out;
}

}  // namespace cg::features
