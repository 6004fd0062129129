// Point projection onto curves (CurveProjector / project_point_on_curve) against OCCT's
// GeomAPI_ProjectPointOnCurve + ShapeAnalysis_Curve::Project (AdjustToEnds) in 3D and
// Geom2dAPI_ProjectPointOnCurve + the curve ends in 2D, on random curves (degrees 1..7, repeated
// knots, rational and polynomial), plus analytic cases and properties.
//
// Tolerances: distances agree to 1e-10 (both sides converge Newton to ~1e-15 relative in the
// parameter; the distance is stationary there, so the difference is rounding of coordinates ~10).
// Ours may be strictly smaller than OCCT's when OCCT returns a local minimum; such cases are counted
// and printed, never the other way round.
#define BOOST_TEST_MODULE project_curve
#include <boost/test/unit_test.hpp>

#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <ShapeAnalysis_Curve.hxx>

#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/core/error.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

// A random point near the curve: a curve point moved by up to 5 units (a few far points too).
template <int Dim>
Eigen::Matrix<double, Dim, 1> point_near(const BSplineCurve<Dim>& c, test::Rng& r) {
  Eigen::Matrix<double, Dim, 1> off;
  for (int d = 0; d < Dim; ++d) off[d] = r.uniform(-1, 1);
  const double reach = r.coin(0.1) ? 40.0 : r.uniform(0.0, 5.0);
  return c.point(r.uniform(c.first_param(), c.last_param())) + reach * off;
}

// Upper bound of the true minimum by dense sampling: our result must never exceed it.
template <int Dim>
double sampled_min(const BSplineCurve<Dim>& c, const Eigen::Matrix<double, Dim, 1>& P, int n) {
  double best = 1e300;
  for (int i = 0; i <= n; ++i) {
    const double u = c.first_param() + (c.last_param() - c.first_param()) * i / n;
    best = std::min(best, (c.point(u) - P).norm());
  }
  return best;
}

struct Tally {
  int cases = 0, occt_missed = 0, several = 0;
};

// Our projection against OCCT's distance `occt` (inf when OCCT found nothing).
template <int Dim>
void check_case(CurveProjector<Dim>& proj, const Eigen::Matrix<double, Dim, 1>& P, double occt, Tally& t) {
  const auto& c = proj.curve();
  const auto res = proj.project(P);
  BOOST_TEST_REQUIRE(res.found);
  ++t.cases;
  // The reported point is the curve point at the parameter, at the reported distance.
  BOOST_TEST((c.point(res.param) - res.point).norm() <= 1e-12 * (1 + res.point.norm()));
  BOOST_TEST(std::abs((res.point - P).norm() - res.distance) <= 1e-13 * (1 + res.distance));
  BOOST_TEST(res.distance <= occt + 1e-10);
  if (res.distance < occt - 1e-10) ++t.occt_missed;
  if (res.several_minima()) ++t.several;
  BOOST_TEST(res.distance <= sampled_min(c, P, 200) + 1e-12);
  // Interior minimum where the curve is C1 (not at a knot of multiplicity p, a corner): the residual
  // is orthogonal to the tangent (first-order condition).
  const double lo = c.first_param(), hi = c.last_param();
  const bool corner = knot_multiplicity(c.knots(), res.param, 1e-9 * (hi - lo)) >= c.degree();
  if (!corner && res.param > lo + 1e-9 * (hi - lo) && res.param < hi - 1e-9 * (hi - lo) && res.distance > 1e-9) {
    const auto d = c.derivatives(res.param, 1);
    BOOST_TEST(std::abs(d[1].dot(res.point - P)) <= 1e-8 * d[1].norm() * (1 + res.distance));
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_3d_vs_occt) {
  test::Rng r(11);
  Tally t;
  ShapeAnalysis_Curve sa;
  for (int i = 0; i < 700; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 1);
    const auto oc = occt::to_occt(c);
    CurveProjector<3> proj(c);
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d P = point_near(c, r);
      const gp_Pnt gP(P.x(), P.y(), P.z());
      double occt = 1e300;
      GeomAPI_ProjectPointOnCurve api(gP, oc);
      if (api.NbPoints() > 0) occt = api.LowerDistance();
      gp_Pnt proj_pt;
      double param = 0;
      occt = std::min(occt, sa.Project(oc, gP, 1e-10, proj_pt, param, true));
      check_case(proj, P, occt, t);
    }
  }
  std::printf("3D: %d cases, ours strictly closer than OCCT in %d, several minima in %d\n", t.cases,
              t.occt_missed, t.several);
  BOOST_TEST(t.cases >= 1000);
}

BOOST_AUTO_TEST_CASE(random_2d_vs_occt) {
  test::Rng r(12);
  Tally t;
  for (int i = 0; i < 600; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 0);
    const auto oc = occt::to_occt(c);
    CurveProjector<2> proj(c);
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d P = point_near(c, r);
      const gp_Pnt2d gP(P.x(), P.y());
      // OCCT's 2D projector reports interior extrema only: add the curve ends.
      double occt = std::min((c.point(c.first_param()) - P).norm(), (c.point(c.last_param()) - P).norm());
      Geom2dAPI_ProjectPointOnCurve api(gP, oc);
      if (api.NbPoints() > 0) occt = std::min(occt, api.LowerDistance());
      check_case(proj, P, occt, t);
    }
  }
  std::printf("2D: %d cases, ours strictly closer than OCCT in %d, several minima in %d\n", t.cases,
              t.occt_missed, t.several);
  BOOST_TEST(t.cases >= 1000);
}

namespace {

BSplineCurve<2> nine_point_circle(double radius = 1.0) {
  const double s = std::sqrt(0.5);
  std::vector<Eigen::Vector2d> P = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  for (auto& q : P) q *= radius;
  return BSplineCurve<2>(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P, {1, s, 1, s, 1, s, 1, s, 1});
}

// Rational ellipse x = a cos, y = b sin as a nine-point NURBS (affine image of the circle).
BSplineCurve<2> ellipse(double a, double b) {
  auto c = nine_point_circle();
  std::vector<Eigen::Vector2d> P = c.poles();
  for (auto& q : P) q = Eigen::Vector2d(a * q.x(), b * q.y());
  return BSplineCurve<2>(2, c.knots(), P, c.weights());
}

}  // namespace

BOOST_AUTO_TEST_CASE(circle_centre_all_points) {
  const auto c = nine_point_circle();
  const auto res = project_point_on_curve(c, Eigen::Vector2d(0, 0));
  BOOST_TEST(res.found);
  BOOST_TEST(std::abs(res.distance - 1.0) <= 1e-14);
  BOOST_TEST(res.several_minima());
  BOOST_TEST(res.params.size() >= 2u);
  for (double u : res.params) BOOST_TEST(std::abs(c.point(u).norm() - 1.0) <= 1e-14);
  // Slightly off the centre, the minimum is unique and lies in the direction of the offset.
  const auto off = project_point_on_curve(c, Eigen::Vector2d(1e-3, 2e-3));
  BOOST_TEST(off.num_minima == 1);
  BOOST_TEST(std::abs(off.distance - (1.0 - std::sqrt(5e-6))) <= 1e-14);
  BOOST_TEST((off.point - Eigen::Vector2d(1, 2).normalized()).norm() <= 1e-12);
}

BOOST_AUTO_TEST_CASE(point_on_curve_distance_zero) {
  test::Rng r(5);
  for (int i = 0; i < 200; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 0);
    CurveProjector<3> proj(c);
    const double u = r.uniform(c.first_param(), c.last_param());
    const auto res = proj.project(c.point(u));
    BOOST_TEST(res.distance <= 1e-12 * (1 + test::pole_scale(c)));
  }
}

BOOST_AUTO_TEST_CASE(ellipse_evolute_several_local_minima) {
  // Ellipse a = 2, b = 1: the evolute's cusps are at (+-(a^2-b^2)/a, 0) = (+-1.5, 0). A point on the
  // axis inside the evolute, (0.5, 0), has the normal feet (2cos t, sin t) with cos t = 2 x / 3 as
  // two symmetric global minima plus the local extrema at the vertices.
  const auto c = ellipse(2, 1);
  const auto res = project_point_on_curve(c, Eigen::Vector2d(0.5, 0));
  const double ct = 2.0 * 0.5 / 3.0;
  const double expect = std::hypot(2 * ct - 0.5, std::sqrt(1 - ct * ct));
  BOOST_TEST(std::abs(res.distance - expect) <= 1e-13);
  BOOST_TEST(res.num_minima == 2);
  for (double u : res.params) {
    const Eigen::Vector2d q = c.point(u);
    BOOST_TEST(std::abs(q.x() - 2 * ct) <= 1e-7);  // parameter at a flat-bottomed minimum: sqrt(eps)
  }
  // Off the axis the symmetry breaks: one global minimum, on the side of the point.
  const auto side = project_point_on_curve(c, Eigen::Vector2d(0.5, 0.1));
  BOOST_TEST(side.num_minima == 1);
  BOOST_TEST(side.point.y() > 0);
  // At the evolute's cusp (1.5, 0) the minimum at the vertex (2, 0) is degenerate (fourth order).
  const auto cusp = project_point_on_curve(c, Eigen::Vector2d(1.5, 0));
  BOOST_TEST(std::abs(cusp.distance - 0.5) <= 1e-13);
  // Outside the evolute on the axis: the vertex is the unique minimum.
  const auto out = project_point_on_curve(c, Eigen::Vector2d(1.7, 0));
  BOOST_TEST(std::abs(out.distance - 0.3) <= 1e-14);
  BOOST_TEST(out.num_minima == 1);
}

BOOST_AUTO_TEST_CASE(search_radius) {
  const auto c = nine_point_circle();
  CurveProjector<2> proj(c);
  BOOST_TEST(!proj.project(Eigen::Vector2d(3, 0), 1.5).found);
  const auto res = proj.project(Eigen::Vector2d(3, 0), 2.5);
  BOOST_TEST(res.found);
  BOOST_TEST(std::abs(res.distance - 2.0) <= 1e-14);
  BOOST_CHECK_THROW(proj.project(Eigen::Vector2d(NAN, 0)), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(periodic_curves) {
  // Periodic (closed, unwrapped) curves: the seam is not an end, so the global minimum is found across it.
  test::Rng r(9);
  for (int i = 0; i < 100; ++i) {
    const int p = r.integer(2, 5), n = r.integer(p + 2, p + 8);
    std::vector<double> knots;
    for (int k = 0; k < n; ++k) knots.push_back(k + r.uniform(-0.3, 0.3));
    std::sort(knots.begin(), knots.end());
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    for (int k = 0; k < n; ++k) {
      P.emplace_back(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10));
      w.push_back(r.uniform(0.3, 3));
    }
    const auto c = BSplineCurve<3>::periodic(p, knots, n + 0.0, P, i % 2 ? w : std::vector<double>{});
    const auto oc = occt::to_occt(c);
    CurveProjector<3> proj(c);
    const Eigen::Vector3d X = c.point(c.first_param()) + Eigen::Vector3d(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2));
    const auto res = proj.project(X);
    GeomAPI_ProjectPointOnCurve api(gp_Pnt(X.x(), X.y(), X.z()), oc);
    BOOST_TEST_REQUIRE(api.NbPoints() > 0);
    BOOST_TEST(res.distance <= api.LowerDistance() + 1e-10);
    BOOST_TEST(res.distance <= sampled_min(c, X, 400) + 1e-12);
  }
}
