// The wall's periodic seam away from the LE (issue 8, item 4): the seam edge of the wall face lies on the
// TE (default blade.seam = +1), and tools straddling it cut correct solids. C3X vane: a box beyond a line
// across the chord near the TE removes exactly the profile area beyond that line times the box height
// (the area by our own polygon clipping of 200 000 profile points, ~1e-9 relative); the rotor: the cut
// and the common of a tool across the TE add up to the blade (OCCT's volumes, 1e-6 relative).
#define BOOST_TEST_MODULE blade_seam
#include <boost/test/unit_test.hpp>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include "blade/blade_fixtures.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/brep/solid_integrals.hpp"
#include "src/brep/verify.hpp"

using namespace cg;
using namespace cg::blade;

namespace {

void require_valid(const TopoDS_Shape& s, const char* what) {
  const brep::SolidCheck c = brep::verify_solid(s);
  for (const brep::Check* k : c.checks()) BOOST_TEST(k->passed, what << ": " << k->name << ": " << k->message);
}

using brep::volume_of;

// Area of the polygon q clipped to the half-plane (p - o) . n >= 0 (Sutherland-Hodgman, one edge).
double clipped_area(const std::vector<Eigen::Vector2d>& q, const Eigen::Vector2d& o, const Eigen::Vector2d& n) {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Eigen::Vector2d& a = q[i];
    const Eigen::Vector2d& b = q[(i + 1) % q.size()];
    const double da = (a - o).dot(n), db = (b - o).dot(n);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return std::abs(test::polygon_area(out));
}

// The seam edge of the wall face (closed on the face: used twice) and a point in its middle.
Eigen::Vector3d seam_midpoint(const brep::BladeSolid& s) {
  for (const auto& f : s.faces) {
    if (f.name != brep::kWallFaceName) continue;
    for (TopExp_Explorer e(f.face, TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge edge = TopoDS::Edge(e.Current());
      if (!BRep_Tool::IsClosed(edge, f.face)) continue;
      double a = 0, b = 0;
      const gp_Pnt p = BRep_Tool::Curve(edge, a, b)->Value(0.5 * (a + b));
      return {p.X(), p.Y(), p.Z()};
    }
  }
  BOOST_FAIL("the wall face has no seam edge");
  return {};
}

}  // namespace

BOOST_AUTO_TEST_CASE(c3x_cut_across_the_seam) {
  const BladeModel m = build_blade(test::c3x_vane());
  const brep::BladeSolid s = brep::build_blade_solid(m);
  require_valid(s.solid, "blade");
  // The seam is the TE line: its middle lies on S(u_te, v) for some v (straight vane: same x, y).
  const Eigen::Vector3d mid = seam_midpoint(s);
  const Eigen::Vector3d te = m.surface.point(m.u_te, mid.z() / 144.93);
  BOOST_TEST((mid - te).norm() < 1e-6);

  // Box: beyond the line 12 mm before the TE across the chord, z in [40, 100], straddling the seam.
  const SectionProfile& p = m.profiles[0];
  const Eigen::Vector2d dir = p.chord_direction, o = p.te - 12 * dir, side(-dir.y(), dir.x());
  const gp_Ax2 frame(gp_Pnt(o.x() - 10 * side.x(), o.y() - 10 * side.y(), 40), gp::DZ(), gp_Dir(dir.x(), dir.y(), 0));
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(frame, 20, 20, 60).Shape();
  std::vector<Eigen::Vector2d> q;
  for (int i = 0; i < 200000; ++i) q.push_back(p.curve.point(i / 200000.0));
  const double expected = clipped_area(q, o, dir) * 60;
  BRepAlgoAPI_Cut cut(s.solid, box);
  BOOST_TEST_REQUIRE(cut.IsDone());
  require_valid(cut.Shape(), "cut");
  const double removed = volume_of(s.solid) - volume_of(cut.Shape());
  BOOST_TEST_MESSAGE("removed " << removed << " mm^3, expected " << expected);
  // 1e-5: both volumes carry BRepGProp's 1e-7 relative error of the whole vane (~0.04 mm^3 each).
  BOOST_TEST(std::abs(removed - expected) < 1e-5 * expected);
  BRepAlgoAPI_Common common(s.solid, box);
  BOOST_TEST_REQUIRE(common.IsDone());
  require_valid(common.Shape(), "common");
  BOOST_TEST(std::abs(volume_of(common.Shape()) - expected) < 1e-6 * expected);
}

BOOST_AUTO_TEST_CASE(rotor_hole_across_the_seam) {
  const BladeModel m = build_blade(test::hpt_rotor());
  const brep::BladeSolid s = brep::build_blade_solid(m);
  // A cylinder of radius 1.5 mm at mid-span, its axis 0.5 mm inside the TE point along the wall's chord
  // tangent there (across the TE nose, from the suction to the pressure side): it straddles the seam.
  BladeCoordinates bc(m);
  const BladeFrame f = bc.frame(0.5, 1.0);
  const Eigen::Vector3d base = f.point - 0.5 * f.normal, axis = f.chord_tangent;
  const gp_Ax2 ax(gp_Pnt(base.x() - 4 * axis.x(), base.y() - 4 * axis.y(), base.z() - 4 * axis.z()),
                  gp_Dir(axis.x(), axis.y(), axis.z()));
  const TopoDS_Shape tool = BRepPrimAPI_MakeCylinder(ax, 1.5, 8).Shape();
  BRepAlgoAPI_Cut cut(s.solid, tool);
  BRepAlgoAPI_Common common(s.solid, tool);
  BOOST_TEST_REQUIRE(cut.IsDone());
  BOOST_TEST_REQUIRE(common.IsDone());
  require_valid(cut.Shape(), "cut");
  require_valid(common.Shape(), "common");
  const double v0 = volume_of(s.solid), vc = volume_of(cut.Shape()), vk = volume_of(common.Shape());
  BOOST_TEST_MESSAGE("rotor: blade " << v0 << ", cut " << vc << ", removed " << vk << " mm^3");
  BOOST_TEST(vk > 1.0);  // the tool really cuts the TE
  BOOST_TEST(std::abs(vc + vk - v0) < 1e-6 * v0);
}
