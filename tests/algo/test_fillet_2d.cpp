// 2D fillets against OCCT's ChFi2d_FilletAPI (line-line, line-circle, random B-spline corners) and by
// their properties: the arc has radius r, is tangent to both curves at its ends, and chains with the
// trimmed curves; "no fillet" cases report found = false with a reason.
#define BOOST_TEST_MODULE fillet_2d
#include <boost/test/unit_test.hpp>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <ChFi2d_FilletAPI.hxx>
#include <gp_Circ.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "adaptors/occt_convert.hpp"
#include "src/algo/fillet_2d.hpp"
#include "src/algo/fillet_arc.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/core/error.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

TopoDS_Edge planar_edge(const Curve2& c) {
  const Curve2::HPoles& H2 = c.homogeneous_poles();
  BSplineCurve<3>::HPoles H3(4, H2.cols());
  H3.row(0) = H2.row(0);
  H3.row(1) = H2.row(1);
  H3.row(2).setZero();
  H3.row(3) = H2.row(2);
  return BRepBuilderAPI_MakeEdge(occt::to_occt(BSplineCurve<3>::from_homogeneous(c.degree(), c.knots(), H3)));
}

struct OcctFillet {
  bool found = false;
  Eigen::Vector2d centre;
  double radius = 0;
};

// Lines and arcs as OCCT's analytic edges (ChFi2d then uses its exact analytic algorithm; its
// iterative one fails on B-spline lines meeting at shallow corners).
TopoDS_Edge line_edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return BRepBuilderAPI_MakeEdge(gp_Pnt(a.x(), a.y(), 0), gp_Pnt(b.x(), b.y(), 0));
}

TopoDS_Edge arc_edge(const Eigen::Vector2d& c, double r, double start, double sweep) {
  const gp_Circ circ(gp_Ax2(gp_Pnt(c.x(), c.y(), 0), gp::DZ()), r);
  const double a = sweep > 0 ? start : start + sweep, b = sweep > 0 ? start + sweep : start;
  const TopoDS_Edge e = BRepBuilderAPI_MakeEdge(circ, a, b);
  return sweep > 0 ? e : TopoDS::Edge(e.Reversed());
}

OcctFillet occt_fillet(const TopoDS_Edge& e1, const TopoDS_Edge& e2, const Curve2& c1, double r) {
  OcctFillet f;
  ChFi2d_FilletAPI api(e1, e2, gp_Pln(gp::Origin(), gp::DZ()));
  if (!api.Perform(r)) return f;
  const Eigen::Vector2d q = c1.point(c1.last_param());
  const gp_Pnt corner(q.x(), q.y(), 0);
  if (api.NbResults(corner) < 1) return f;
  TopoDS_Edge m1, m2;
  const TopoDS_Edge fe = api.Result(corner, m1, m2, -1);
  if (fe.IsNull()) return f;
  BRepAdaptor_Curve ac(fe);
  if (ac.GetType() != GeomAbs_Circle) return f;
  const gp_Circ circ = ac.Circle();
  f.found = true;
  f.centre = Eigen::Vector2d(circ.Location().X(), circ.Location().Y());
  f.radius = circ.Radius();
  return f;
}

OcctFillet occt_fillet(const Curve2& c1, const Curve2& c2, double r) { return occt_fillet(planar_edge(c1), planar_edge(c2), c1, r); }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Radius, tangency (unit tangents parallel to 1e-9) and the G0 chain trimmed1 -> arc -> trimmed2.
void check_fillet(const Curve2& c1, const Curve2& c2, const Fillet2d& f, double r) {
  BOOST_TEST(f.radius == r);
  for (int k = 0; k <= 20; ++k)
    BOOST_TEST(std::abs((f.arc.point(k / 20.0) - f.centre).norm() - r) <= 1e-12 * (1 + f.centre.norm() + r));
  const Eigen::Vector2d a0 = f.arc.derivatives(0.0, 1)[1].normalized(), a1 = f.arc.derivatives(1.0, 1)[1].normalized();
  const Eigen::Vector2d t1 = c1.derivatives(f.param1, 1)[1].normalized(), t2 = c2.derivatives(f.param2, 1)[1].normalized();
  BOOST_TEST(std::abs(cross(a0, t1)) <= 1e-9);
  BOOST_TEST(std::abs(cross(a1, t2)) <= 1e-9);
  BOOST_TEST((f.arc.point(0.0) - f.point1).norm() <= 1e-12 * (1 + f.point1.norm()));
  BOOST_TEST((f.arc.point(1.0) - f.point2).norm() <= 1e-12 * (1 + f.point2.norm()));
  BOOST_TEST((f.point1 - f.centre).norm() - r <= 1e-12 * (1 + r + f.centre.norm()));
}

void check_corner_chain(const Fillet2d& f) {
  BOOST_TEST((f.trimmed1.point(f.trimmed1.last_param()) - f.point1).norm() <= 1e-12 * (1 + f.point1.norm()));
  BOOST_TEST((f.trimmed2.point(f.trimmed2.first_param()) - f.point2).norm() <= 1e-12 * (1 + f.point2.norm()));
  // G1: the arc leaves c1 and enters c2 in their directions of travel.
  BOOST_TEST(f.arc.derivatives(0.0, 1)[1].dot(f.trimmed1.derivatives(f.trimmed1.last_param(), 1)[1]) > 0);
  BOOST_TEST(f.arc.derivatives(1.0, 1)[1].dot(f.trimmed2.derivatives(f.trimmed2.first_param(), 1)[1]) > 0);
}

Curve2 segment_curve(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return Curve2(1, {0, 0, 1, 1}, {a, b}); }

}  // namespace

// ChFi2d's iterative algorithm (B-spline edges) is ~7e-8 accurate (occt-platform.md); ours is exact
// to rounding, so centres and radii agree within 1e-7.
constexpr double kOcctTol = 1e-7;

BOOST_AUTO_TEST_CASE(line_line_vs_chfi2d_and_analytic) {
  for (double deg : {30.0, 60.0, 90.0, 120.0, 150.0, -45.0, -100.0}) {
    const double a = deg * M_PI / 180;
    const Curve2 c1 = segment_curve({-2, 0}, {0, 0});
    const Curve2 c2 = segment_curve({0, 0}, {2 * std::cos(a), 2 * std::sin(a)});
    const double r = 0.3;
    const Fillet2d f = fillet_corner_2d(c1, c2, r);
    BOOST_TEST_REQUIRE(f.found, f.reason);
    check_fillet(c1, c2, f, r);
    check_corner_chain(f);
    // Analytic: the centre is on the bisector of the corner at distance r / sin(interior / 2).
    const double interior = M_PI - std::abs(a);
    const Eigen::Vector2d bis = (Eigen::Vector2d(-1, 0) + Eigen::Vector2d(std::cos(a), std::sin(a))).normalized();
    BOOST_TEST((f.centre - bis * r / std::sin(interior / 2)).norm() <= 1e-13);
    const OcctFillet o = occt_fillet(line_edge({-2, 0}, {0, 0}), line_edge({0, 0}, {2 * std::cos(a), 2 * std::sin(a)}), c1, r);
    BOOST_TEST_REQUIRE(o.found);
    BOOST_TEST((o.centre - f.centre).norm() <= kOcctTol);
    BOOST_TEST(std::abs(o.radius - r) <= kOcctTol);
  }
}

BOOST_AUTO_TEST_CASE(line_circle_vs_chfi2d) {
  // Line into the top of the unit circle, then clockwise along it: the fillet sits outside the circle
  // (|centre| = 1 + r); and the reverse corner (circle into a line) with the fillet inside.
  const Curve2 arc = circular_arc({0, 0}, 1.0, M_PI / 2, -M_PI / 2);
  for (double r : {0.05, 0.2, 0.5}) {
    const Curve2 line = segment_curve({-1.5, 1.5}, {0, 1});
    const Fillet2d f = fillet_corner_2d(line, arc, r);
    BOOST_TEST_REQUIRE(f.found, f.reason);
    check_fillet(line, arc, f, r);
    check_corner_chain(f);
    BOOST_TEST(std::abs(f.centre.norm() - (1 + r)) <= 1e-13);
    // The clockwise arc goes to OCCT as a B-spline edge: as a reversed analytic edge, ChFi2d's
    // analytic algorithm returns the circle tangent to the arc's extension beyond the corner.
    const OcctFillet o = occt_fillet(line_edge({-1.5, 1.5}, {0, 1}), planar_edge(arc), line, r);
    BOOST_TEST_REQUIRE(o.found);
    BOOST_TEST((o.centre - f.centre).norm() <= kOcctTol);
    BOOST_TEST(std::abs(o.radius - r) <= kOcctTol);
  }
  const Curve2 arc2 = circular_arc({0, 0}, 1.0, 0.0, M_PI / 2);  // (1,0) -> (0,1) counter-clockwise
  const Curve2 line2 = segment_curve({0, 1}, {-1, -0.5});          // turns left, into the circle
  const Fillet2d f = fillet_corner_2d(arc2, line2, 0.2);
  BOOST_TEST_REQUIRE(f.found, f.reason);
  check_fillet(arc2, line2, f, 0.2);
  BOOST_TEST(std::abs(f.centre.norm() - 0.8) <= 1e-13);  // inside the circle: |centre| = 1 - r
  const OcctFillet o = occt_fillet(arc_edge({0, 0}, 1.0, 0.0, M_PI / 2), line_edge({0, 1}, {-1, -0.5}), arc2, 0.2);
  BOOST_TEST_REQUIRE(o.found);
  BOOST_TEST((o.centre - f.centre).norm() <= kOcctTol);
}

namespace {

// Independent check that a circle (centre, r) is a fillet of the corner on `side` of both curves
// (+1 left of the tangent): its centre is at GLOBAL distance r from each curve (it touches and does
// not cut them; CurveProjector, verified against OCCT and dense sampling in test_project_curve), each
// touching point lies inside its curve (not at an end) and the centre lies on `side` of each curve
// there (for fillet_corner_2d both sides are the inside of the turn: the arc sits in the corner).
bool is_fillet(const Curve2& c1, const Curve2& c2, const Eigen::Vector2d& centre, double r, int side, double tol) {
  for (const Curve2* c : {&c1, &c2}) {
    const auto pr = project_point_on_curve(*c, centre);
    if (std::abs(pr.distance - r) > tol) return false;
    const double span = c->last_param() - c->first_param();
    for (double u : pr.params) {
      if (u <= c->first_param() + 1e-9 * span || u >= c->last_param() - 1e-9 * span) return false;
      const Eigen::Vector2d t = c->derivatives(u, 1)[1];
      if (cross(t, centre - c->point(u)) * side <= 0) return false;
    }
  }
  return true;
}

}  // namespace

// Random B-spline corners against ChFi2d_FilletAPI. Every case is decided, none skipped:
//  - ours found: it must pass is_fillet at 1e-12 (ours is exact to rounding);
//  - OCCT found: its circle is checked by is_fillet at 2e-7 (ChFi2d's iterative accuracy, ~1e-7);
//  - both found and valid: equal centres (within 2e-7), or ours is the one nearer to the corner (the
//    documented choice; OCCT returned another local solution) - ours farther is a failure;
//  - only OCCT found a valid fillet: a failure of ours; an invalid OCCT circle is counted as OCCT's error;
//  - only ours found: counted (ChFi2d's iteration did not converge); neither: ours must give a reason.
BOOST_AUTO_TEST_CASE(bspline_corners_vs_chfi2d) {
  test::Rng rng(31);
  int same = 0, ours_nearer = 0, only_ours = 0, occt_invalid = 0, neither = 0;
  // 60 cases: ChFi2d's iterative algorithm takes ~0.1 s per B-spline corner (ours ~10 ms).
  const int cases = 60;
  for (int i = 0; i < cases; ++i) {
    // Two random curves (degrees 2..5, polynomial and rational) moved so that c1 ends where c2
    // starts, turning by 40..140 degrees there.
    const int p1 = rng.integer(2, 5), p2 = rng.integer(2, 5);
    Curve2 c1 = test::random_curve<2>(rng, p1, rng.integer(p1 + 1, p1 + 4), i % 2 == 1);
    Curve2 c2 = test::random_curve<2>(rng, p2, rng.integer(p2 + 1, p2 + 4), i % 3 == 1);
    const Eigen::Vector2d t1 = c1.derivatives(c1.last_param(), 1)[1].normalized();
    Eigen::Vector2d t2 = c2.derivatives(c2.first_param(), 1)[1].normalized();
    const double turn = (rng.coin() ? 1 : -1) * rng.uniform(40, 140) * M_PI / 180;
    const Eigen::Vector2d want(std::cos(turn) * t1.x() - std::sin(turn) * t1.y(), std::sin(turn) * t1.x() + std::cos(turn) * t1.y());
    const double rot = std::atan2(cross(t2, want), t2.dot(want));
    Eigen::Matrix2d Rm;
    Rm << std::cos(rot), -std::sin(rot), std::sin(rot), std::cos(rot);
    auto H2 = c2.homogeneous_poles();
    const Eigen::Vector2d start = Rm * c2.point(c2.first_param()), end1 = c1.point(c1.last_param());
    for (int k = 0; k < H2.cols(); ++k)
      H2.col(k).head<2>() = Rm * H2.col(k).head<2>() + (end1 - start) * H2(2, k);
    c2 = Curve2::from_homogeneous(p2, c2.knots(), H2);
    const double r = rng.uniform(0.1, 1.0);
    const int side = turn > 0 ? 1 : -1;
    const Eigen::Vector2d corner = c1.point(c1.last_param());
    const double size = 1 + std::max(test::pole_scale(c1), test::pole_scale(c2));
    const Fillet2d f = fillet_corner_2d(c1, c2, r);
    const OcctFillet o = occt_fillet(c1, c2, r);
    if (f.found) {
      check_fillet(c1, c2, f, r);
      check_corner_chain(f);
      BOOST_TEST(is_fillet(c1, c2, f.centre, r, side, 1e-12 * size), "case " << i << ": ours is not a fillet");
    }
    const bool occt_valid = o.found && std::abs(o.radius - r) <= kOcctTol && is_fillet(c1, c2, o.centre, r, side, 2 * kOcctTol);
    // OCCT's invalid circles (measured: tangent to one curve from the outside of the corner, or cutting
    // a curve) are other tangent circles, not fillets inside this corner.
    if (o.found && !occt_valid) ++occt_invalid;
    if (f.found && occt_valid) {
      if ((o.centre - f.centre).norm() <= 2 * kOcctTol) {
        ++same;
      } else {
        // Two valid fillets: ours must be the one nearer to the corner.
        BOOST_TEST((f.centre - corner).norm() <= (o.centre - corner).norm() + 2 * kOcctTol,
                   "case " << i << ": OCCT's fillet is nearer to the corner");
        ++ours_nearer;
      }
    } else if (occt_valid) {
      BOOST_TEST(f.found, "case " << i << ": OCCT found a valid fillet, ours none: " << f.reason);
    } else if (f.found) {
      ++only_ours;
    } else {
      BOOST_TEST(!f.reason.empty());
      ++neither;
    }
  }
  std::printf("fillets vs ChFi2d: %d cases: %d same centre, %d ours nearer to the corner, %d only ours valid, %d "
              "OCCT circles not a corner fillet, %d none by both\n", cases, same, ours_nearer, only_ours, occt_invalid,
              neither);
  BOOST_TEST(same + ours_nearer >= cases / 2);  // the comparison is not vacuous
}

BOOST_AUTO_TEST_CASE(crossing_curves_choose_the_quadrant) {
  // Two crossing lines: the four quadrants give four fillets, centres at (+-r/sin45 along the axes).
  const Curve2 c1 = segment_curve({-2, -2}, {2, 2}), c2 = segment_curve({-2, 2}, {2, -2});
  const double r = 0.25, d = r / std::sin(M_PI / 4);
  for (int s1 : {1, -1})
    for (int s2 : {1, -1}) {
      const Fillet2d f = fillet_2d(c1, c2, r, s1, s2, Eigen::Vector2d(0, 0));
      BOOST_TEST_REQUIRE(f.found, f.reason);
      check_fillet(c1, c2, f, r);
      // Left of c1 (direction (1,1)) is y > x; left of c2 (direction (1,-1)) is y > -x.
      BOOST_TEST(std::abs(f.centre.norm() - d) <= 1e-13);
      BOOST_TEST((f.centre.y() - f.centre.x()) * s1 > 0);
      BOOST_TEST((f.centre.y() + f.centre.x()) * s2 > 0);
    }
}

BOOST_AUTO_TEST_CASE(no_fillet_cases) {
  // Parallel lines.
  Fillet2d f = fillet_2d(segment_curve({0, 0}, {1, 0}), segment_curve({0, 1}, {1, 1}), 0.3, 1, -1, Eigen::Vector2d(0.5, 0.5));
  BOOST_TEST(!f.found);
  BOOST_TEST(!f.reason.empty());
  // Radius too large for short segments.
  f = fillet_corner_2d(segment_curve({-1, 0}, {0, 0}), segment_curve({0, 0}, {0, 1}), 5.0);
  BOOST_TEST(!f.found);
  BOOST_TEST(!f.reason.empty());
  // Tangent-continuous join: no corner.
  f = fillet_corner_2d(segment_curve({-1, 0}, {0, 0}), segment_curve({0, 0}, {1, 0}), 0.1);
  BOOST_TEST(!f.found);
  // Inside a circle of radius 1 no fillet of radius 2 fits: line into a circle, fillet inside.
  const Curve2 arc = circular_arc({0, 0}, 1.0, 0.0, M_PI / 2);
  f = fillet_corner_2d(arc, segment_curve({0, 1}, {-1, -0.5}), 2.0);
  BOOST_TEST(!f.found);
  BOOST_CHECK_THROW(fillet_corner_2d(arc, segment_curve({5, 5}, {6, 6}), 0.1), InvalidGeometry);
  BOOST_CHECK_THROW(fillet_2d(arc, arc, -1.0, 1, 1, Eigen::Vector2d(0, 0)), InvalidGeometry);
}
