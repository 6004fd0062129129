// Blade solid from an exact u-periodic surface cut by plane or revolved trims, checked by
// verify_solid and against volumes from analytic formulas or quadrature (synthetic_blade.hpp).
// Volume tolerance 1e-6 relative: the geometry is exact (rational ellipse, exact planes and
// surfaces of revolution), intersection curves are accurate to ~1e-7 mm and BRepGProp integrates to
// a requested 1e-7 (measured volume errors ~1e-9). Area converges more slowly on the rational wall:
// 1e-6 relative is what the same accuracy reaches there.
#define BOOST_TEST_MODULE blade_solid
#include <boost/test/unit_test.hpp>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shell.hxx>

#include <functional>
#include <iomanip>
#include <map>

#include "blade/blade_fixtures.hpp"
#include "brep/synthetic_blade.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/brep/verify.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::brep;

namespace {

void require_all_checks(const SolidCheck& c) {
  for (const Check* k : c.checks()) BOOST_TEST(k->passed, k->name << ": " << k->message);
}

std::map<std::string, int> face_name_counts(const BladeSolid& s) {
  std::map<std::string, int> m;
  for (const auto& f : s.faces) ++m[f.name];
  return m;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Straight line meridional curve (x, r) of the given degree with Greville-placed poles, so x(t) is
// linear in t and r(x) = r-component at t = (x - x0) / (x1 - x0).
BSplineCurve<2> meridional(double x0, double x1, const std::vector<double>& r) {
  const int n = static_cast<int>(r.size()), p = std::min(3, n - 1);
  const auto U = uniform_clamped_knots(p, n);
  std::vector<Eigen::Vector2d> P;
  for (int i = 0; i < n; ++i) {
    double g = 0;
    for (int k = 1; k <= p; ++k) g += U[static_cast<std::size_t>(i + k)];
    P.emplace_back(x0 + (x1 - x0) * g / p, r[static_cast<std::size_t>(i)]);
  }
  return BSplineCurve<2>(p, U, P);
}

double radius_at(const BSplineCurve<2>& c, double x0, double x1, double x) { return c.point((x - x0) / (x1 - x0)).y(); }

}  // namespace

// The synthetic surface itself (our kernel) lies on the elliptic cylinder, z linear in v.
BOOST_AUTO_TEST_CASE(synthetic_surface_is_elliptic) {
  const test::EllipticBlade e;
  const auto s = test::elliptic_blade_surface(e);
  for (int k = 0; k <= 40; ++k)
    for (double v : {0.0, 0.3, 1.0}) {
      const Eigen::Vector3d p = s.point(k / 40.0, v);
      BOOST_TEST(std::abs(p.x() * p.x() / (e.a * e.a) + p.y() * p.y() / (e.b * e.b) - 1) < 1e-14);
      BOOST_TEST(std::abs(p.z() - (e.z0 + v * (e.z1 - e.z0))) < 1e-12);
    }
  // u = 1/8 lies in the first quadrant (x > 0, y > 0) on the quarter arc (a, 0) -> (0, b).
  BOOST_TEST(s.point(0.125, 0).x() > 0);
  BOOST_TEST(s.point(0.125, 0).y() > 0);
}

BOOST_AUTO_TEST_CASE(straight_caps_volume_area_and_names) {
  const test::EllipticBlade e;
  const auto s = build_blade_solid(test::elliptic_blade_surface(e), PlaneTrim{{0, 0, 90}, {0, 0, 1}},
                                   PlaneTrim{{0, 0, 120}, {0, 0, -1}});
  const SolidCheck c = verify_solid(s.solid);
  require_all_checks(c);
  BOOST_TEST(s.warnings.empty());
  const double h = 30, area = test::kPi * e.a * e.b;
  BOOST_TEST(rel(c.volume, area * h) < 1e-6, "volume " << c.volume << " vs " << area * h);
  const double surface = 2 * area + test::ellipse_perimeter(e.a, e.b) * h;
  BOOST_TEST(rel(c.area(), surface) < 1e-6, std::setprecision(15) << "area " << c.area() << " vs " << surface);
  BOOST_TEST(c.face_count == 3);
  const auto names = face_name_counts(s);
  BOOST_TEST(names.at(kWallFaceName) == 1);
  BOOST_TEST(names.at(kHubFaceName) == 1);
  BOOST_TEST(names.at(kCasingFaceName) == 1);
  BOOST_TEST(s.faces.size() == 3u);
  // Bounding box: the ellipse and the two planes, to intersection accuracy.
  BOOST_TEST(std::abs(c.bbox_min[0] + e.a) < 1e-6);
  BOOST_TEST(std::abs(c.bbox_max[1] - e.b) < 1e-6);
  BOOST_TEST(std::abs(c.bbox_min[2] - 90) < 1e-6);
  BOOST_TEST(std::abs(c.bbox_max[2] - 120) < 1e-6);
}

// A leaned prism cut by tilted planes: volume = section area x height over the section's centroid.
BOOST_AUTO_TEST_CASE(tilted_caps_on_leaned_blade) {
  test::EllipticBlade e;
  e.lean_x = 0.2;
  const auto surf = test::elliptic_blade_surface(e);
  // Hub plane z = 90 + 0.1 x, casing plane z = 120 - 0.05 y.
  const Eigen::Vector3d nh(-0.1, 0, 1), nc(0, 0.05, 1);
  const auto s = build_blade_solid(surf, PlaneTrim{{0, 0, 90}, nh}, PlaneTrim{{0, 0, 120}, nc});
  const SolidCheck c = verify_solid(s.solid);
  require_all_checks(c);
  // Leaned prism, vertical extent measured along z: V = A * (z_casing - z_hub) at the centroid line
  // x = lean * z, y = 0. Hub: z = 90 + 0.1 * 0.2 z -> z_h = 90 / 0.98; casing: z_c = 120.
  const double zh = 90 / (1 - 0.1 * e.lean_x), zc = 120;
  const double expect = test::kPi * e.a * e.b * (zc - zh);
  BOOST_TEST(rel(c.volume, expect) < 1e-6, "volume " << c.volume << " vs " << expect);
}

BOOST_AUTO_TEST_CASE(cylindrical_hub_and_casing) {
  const test::EllipticBlade e;
  const double rh = 90, rc = 120;
  const auto s = build_blade_solid(test::elliptic_blade_surface(e), RevolvedTrim{meridional(-40, 40, {rh, rh})},
                                   RevolvedTrim{meridional(-40, 40, {rc, rc})});
  const SolidCheck c = verify_solid(s.solid);
  require_all_checks(c);
  const double expect = test::integrate_over_ellipse(
      e.a, e.b, [&](double, double y) { return std::sqrt(rc * rc - y * y) - std::sqrt(rh * rh - y * y); });
  BOOST_TEST(rel(c.volume, expect) < 1e-6, "volume " << c.volume << " vs " << expect);
  const auto names = face_name_counts(s);
  BOOST_TEST(names.at(kHubFaceName) == 1);
  BOOST_TEST(names.at(kCasingFaceName) == 1);
  // The revolved end faces lie at r = rh, rc: the bbox top is the casing radius at y = 0.
  BOOST_TEST(std::abs(c.bbox_max[2] - rc) < 1e-6);
}

// Conical hub (linear r(x)) and a curved cubic casing: volume by quadrature of the height between
// both surfaces of revolution over the section.
BOOST_AUTO_TEST_CASE(conical_hub_curved_casing) {
  test::EllipticBlade e;
  e.b = 3;
  const auto hub = meridional(-30, 30, {86, 94});
  const auto casing = meridional(-30, 30, {124, 119, 121, 117});
  const auto s = build_blade_solid(test::elliptic_blade_surface(e), RevolvedTrim{hub}, RevolvedTrim{casing});
  const SolidCheck c = verify_solid(s.solid);
  require_all_checks(c);
  const double expect = test::integrate_over_ellipse(e.a, e.b, [&](double x, double y) {
    const double a = radius_at(hub, -30, 30, x), b = radius_at(casing, -30, 30, x);
    return std::sqrt(b * b - y * y) - std::sqrt(a * a - y * y);
  });
  BOOST_TEST(rel(c.volume, expect) < 1e-6, "volume " << c.volume << " vs " << expect);
}

BOOST_AUTO_TEST_CASE(mixed_plane_hub_revolved_casing) {
  const test::EllipticBlade e;
  const double rc = 118;
  const auto s = build_blade_solid(test::elliptic_blade_surface(e), PlaneTrim{{0, 0, 95}, {0, 0, 1}},
                                   RevolvedTrim{meridional(-40, 40, {rc, rc})});
  const SolidCheck c = verify_solid(s.solid);
  require_all_checks(c);
  const double expect =
      test::integrate_over_ellipse(e.a, e.b, [&](double, double y) { return std::sqrt(rc * rc - y * y) - 95; });
  BOOST_TEST(rel(c.volume, expect) < 1e-6, "volume " << c.volume << " vs " << expect);
}

BOOST_AUTO_TEST_CASE(bad_input_is_reported) {
  const test::EllipticBlade e;
  const auto surf = test::elliptic_blade_surface(e);
  const PlaneTrim hub{{0, 0, 90}, {0, 0, 1}}, casing{{0, 0, 120}, {0, 0, 1}};
  // Casing beyond the over-built surface (z1 = 130): no wall between the trims.
  BOOST_CHECK_THROW(build_blade_solid(surf, hub, PlaneTrim{{0, 0, 140}, {0, 0, 1}}), AlgorithmFailure);
  // Both trims on the same side of the surface's end.
  BOOST_CHECK_THROW(build_blade_solid(surf, PlaneTrim{{0, 0, 135}, {0, 0, 1}}, PlaneTrim{{0, 0, 140}, {0, 0, 1}}),
                    AlgorithmFailure);
  // Hub meridional curve too short to cover the blade's axial extent (x in [-20, 20]).
  BOOST_CHECK_THROW(build_blade_solid(surf, RevolvedTrim{meridional(-5, 5, {90, 90})}, casing), AlgorithmFailure);
  BOOST_CHECK_THROW(build_blade_solid(surf, PlaneTrim{{0, 0, 90}, {0, 0, 0}}, casing), InvalidGeometry);
  BOOST_CHECK_THROW(build_blade_solid(surf, RevolvedTrim{meridional(-40, 40, {90, -1})}, casing), InvalidGeometry);
  // A surface not closed in u.
  const BSplineSurface<3> open(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1},
                               {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 200)},
                                {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 200)}});
  BOOST_CHECK_THROW(build_blade_solid(open, hub, casing), InvalidGeometry);
}

// verify_solid must fail on broken shapes: an open shell (end face left out) and two solids.
BOOST_AUTO_TEST_CASE(verify_detects_broken_solids) {
  const test::EllipticBlade e;
  const auto s = build_blade_solid(test::elliptic_blade_surface(e), PlaneTrim{{0, 0, 90}, {0, 0, 1}},
                                   PlaneTrim{{0, 0, 120}, {0, 0, 1}});
  // A solid of one shell of use(face) for each face of s (a null shape leaves the face out).
  BRep_Builder bb;
  const auto solid_of = [&](const std::function<TopoDS_Shape(const TopoDS_Face&)>& use) {
    TopoDS_Shell shell;
    bb.MakeShell(shell);
    for (TopExp_Explorer x(s.solid, TopAbs_FACE); x.More(); x.Next()) {
      const TopoDS_Shape f = use(TopoDS::Face(x.Current()));
      if (!f.IsNull()) bb.Add(shell, f);
    }
    TopoDS_Solid solid;
    bb.MakeSolid(solid);
    bb.Add(solid, shell);
    return solid;
  };
  const TopoDS_Face& wall = s.faces.front().face;
  BOOST_TEST_REQUIRE(s.faces.front().name == kWallFaceName);
  // The wall left out: open.
  const SolidCheck c = verify_solid(solid_of([&](const TopoDS_Face& f) -> TopoDS_Shape { return f.IsSame(wall) ? TopoDS_Shape() : TopoDS_Shape(f); }));
  BOOST_TEST(!c.no_free_edges.passed);
  BOOST_TEST(!c.closed_mesh.passed);
  BOOST_TEST(!c.all_passed());

  TopoDS_Compound two;
  bb.MakeCompound(two);
  bb.Add(two, s.solid);
  bb.Add(two, build_blade_solid(test::elliptic_blade_surface(e), PlaneTrim{{0, 0, 85}, {0, 0, 1}},
                                PlaneTrim{{0, 0, 88}, {0, 0, 1}})
                  .solid);
  const SolidCheck c2 = verify_solid(two);
  BOOST_TEST(!c2.one_solid.passed);
  BOOST_TEST(c2.solid_count == 2);

  // One face flipped: the shell is closed but not consistently oriented.
  const SolidCheck c4 = verify_solid(solid_of([&](const TopoDS_Face& f) -> TopoDS_Shape { return f.IsSame(wall) ? f.Reversed() : TopoDS_Shape(f); }));
  BOOST_TEST(!c4.oriented_shells.passed);
  BOOST_TEST(!c4.closed_mesh.passed);
  BOOST_TEST(c4.no_free_edges.passed);

  // A solid whose only shell is turned inside out has negative volume.
  const SolidCheck c3 = verify_solid(s.solid.Reversed());
  BOOST_TEST(!c3.positive_volume.passed);
  BOOST_TEST(verify_solid(TopoDS_Shape()).all_passed() == false);
}

// The model overload maps a straight flow path to the planes z = hub_z, casing_z and a meridional one
// to the revolved contours.
BOOST_AUTO_TEST_CASE(model_trims) {
  const test::EllipticBlade e;
  blade::BladeModel m;
  m.surface = test::elliptic_blade_surface(e);
  m.trim.straight = true;
  m.trim.hub_z = 85;
  m.trim.casing_z = 125;
  const SolidCheck c = verify_solid(build_blade_solid(m).solid);
  require_all_checks(c);
  BOOST_TEST(rel(c.volume, test::kPi * e.a * e.b * 40) < 1e-6);
  m.trim.straight = false;
  m.trim.hub = meridional(-40, 40, {88, 88});
  m.trim.casing = meridional(-40, 40, {121, 121});
  BOOST_TEST(std::holds_alternative<RevolvedTrim>(hub_trim(m.trim)));
  const SolidCheck r = verify_solid(build_blade_solid(m).solid);
  require_all_checks(r);
  BOOST_TEST(std::abs(r.bbox_max[2] - 121) < 1e-6);
}

// A blade model's solid is trimmed along the wall's own iso-curves v = 0 and 1 (they lie on hub and
// casing within the surface tolerance): the same solid as the general fuse (volume 1e-6, end-face
// areas 1e-5 relative: the edges differ by the iso-curves' distance from the trims, ~4e-5 mm here),
// edges with straight pcurves on the wall, tolerances within the surface tolerance, light pcurves.
BOOST_AUTO_TEST_CASE(model_solid_trimmed_along_iso_curves) {
  const blade::BladeModel m = blade::build_blade(blade::test::hpt_rotor());
  const BladeSolid iso = build_blade_solid(m);
  const BladeSolid fused = build_blade_solid(m.surface, hub_trim(m.trim), casing_trim(m.trim));
  const SolidCheck a = verify_solid(iso.solid), b = verify_solid(fused.solid);
  require_all_checks(a);
  require_all_checks(b);
  BOOST_TEST(rel(a.volume, b.volume) < 1e-6, "volume " << a.volume << " vs " << b.volume);
  BOOST_TEST(rel(a.area(), b.area()) < 1e-5, "area " << a.area() << " vs " << b.area());
  const auto names = face_name_counts(iso);
  BOOST_TEST(names.at(kWallFaceName) == 1);
  BOOST_TEST(names.at(kHubFaceName) == 1);
  BOOST_TEST(names.at(kCasingFaceName) == 1);
  for (const NamedFace& f : iso.faces)
    for (TopExp_Explorer e(f.face, TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge edge = TopoDS::Edge(e.Current());
      BOOST_TEST(BRep_Tool::Tolerance(edge) <= 2 * m.surface_tolerance);
      double lo = 0, hi = 0;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, f.face, lo, hi);
      BOOST_TEST_REQUIRE(!pc.IsNull());
      if (f.name == kWallFaceName) {
        BOOST_TEST(pc->IsKind(STANDARD_TYPE(Geom2d_Line)));
      } else {
        const Handle(Geom2d_BSplineCurve) bs = Handle(Geom2d_BSplineCurve)::DownCast(pc);
        BOOST_TEST_REQUIRE(!bs.IsNull());
        BOOST_TEST(bs->NbPoles() <= 16 * m.poles_u());
      }
    }
}
