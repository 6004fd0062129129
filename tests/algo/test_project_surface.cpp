// Point projection onto surfaces (SurfaceProjector / project_point_on_surface) against OCCT's
// GeomAPI_ProjectPointOnSurf on random surfaces (degrees 1..5, repeated knots, rational and
// polynomial), plus analytic cases.
//
// OCCT's projector reports interior extrema only (none when the foot is on the boundary), so its
// answer is combined with the boundary curves projected by GeomAPI_ProjectPointOnCurve and the
// corners. Tolerance 1e-10 on distances (both converge Newton to rounding; the distance is stationary
// at the foot). Ours may be strictly smaller (OCCT returned a local minimum): counted and printed.
#define BOOST_TEST_MODULE project_surface
#include <boost/test/unit_test.hpp>

#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>

#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/project_point_surface.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

double occt_distance(const Handle(Geom_BSplineSurface) & os, const BSplineSurface<3>& s, const Eigen::Vector3d& P) {
  const gp_Pnt gP(P.x(), P.y(), P.z());
  double best = 1e300;
  GeomAPI_ProjectPointOnSurf api(gP, os, s.first_u(), s.last_u(), s.first_v(), s.last_v(), 1e-9);
  if (api.NbPoints() > 0) best = api.LowerDistance();
  const double us[2] = {s.first_u(), s.last_u()}, vs[2] = {s.first_v(), s.last_v()};
  for (double u : us) {
    GeomAPI_ProjectPointOnCurve c(gP, os->UIso(u));
    if (c.NbPoints() > 0) best = std::min(best, c.LowerDistance());
    for (double v : vs) best = std::min(best, (s.point(u, v) - P).norm());
  }
  for (double v : vs) {
    GeomAPI_ProjectPointOnCurve c(gP, os->VIso(v));
    if (c.NbPoints() > 0) best = std::min(best, c.LowerDistance());
  }
  return best;
}

double sampled_min(const BSplineSurface<3>& s, const Eigen::Vector3d& P, int n) {
  double best = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = s.first_u() + (s.last_u() - s.first_u()) * i / n;
      const double v = s.first_v() + (s.last_v() - s.first_v()) * j / n;
      best = std::min(best, (s.point(u, v) - P).norm());
    }
  return best;
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_vs_occt) {
  test::Rng r(21);
  int cases = 0, occt_missed = 0;
  for (int i = 0; i < 150; ++i) {
    const auto s = test::random_surface(r, i % 2 == 1);
    const auto os = occt::to_occt(s);
    SurfaceProjector proj(s);
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d P = s.point(r.uniform(s.first_u(), s.last_u()), r.uniform(s.first_v(), s.last_v())) +
                                r.uniform(0, 5) * Eigen::Vector3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
      const auto res = proj.project(P);
      BOOST_TEST_REQUIRE(res.found);
      ++cases;
      BOOST_TEST((s.point(res.u, res.v) - res.point).norm() <= 1e-12 * (1 + res.point.norm()));
      BOOST_TEST(std::abs((res.point - P).norm() - res.distance) <= 1e-13 * (1 + res.distance));
      const double o = occt_distance(os, s, P);
      BOOST_TEST(res.distance <= o + 1e-10);
      if (res.distance < o - 1e-10) ++occt_missed;
      BOOST_TEST(res.distance <= sampled_min(s, P, 30) + 1e-12);
    }
  }
  std::printf("surface: %d cases, ours strictly closer than OCCT in %d\n", cases, occt_missed);
  BOOST_TEST(cases >= 300);
}

namespace {

// Rational quadratic sphere of radius R (u: nine-point circle in longitude, v: half circle in
// latitude), exact NURBS.
BSplineSurface<3> sphere(double R) {
  const double s = std::sqrt(0.5);
  const std::vector<Eigen::Vector2d> lon = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  const std::vector<double> wl = {1, s, 1, s, 1, s, 1, s, 1};
  const std::vector<Eigen::Vector2d> lat = {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};  // (radius, z)
  const std::vector<double> wz = {1, s, 1, s, 1};
  std::vector<std::vector<Eigen::Vector3d>> P(9, std::vector<Eigen::Vector3d>(5));
  std::vector<std::vector<double>> W(9, std::vector<double>(5));
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 5; ++j) {
      P[i][j] = R * Eigen::Vector3d(lon[i].x() * lat[j].x(), lon[i].y() * lat[j].x(), lat[j].y());
      W[i][j] = wl[i] * wz[j];
    }
  return BSplineSurface<3>(2, 2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                           P, W);
}

}  // namespace

BOOST_AUTO_TEST_CASE(sphere_cases) {
  const auto s = sphere(2.0);
  SurfaceProjector proj(s);
  // Centre: every point is at distance R.
  std::vector<Eigen::Vector2d> params;
  const auto c = proj.project_all(Eigen::Vector3d::Zero(), params);
  BOOST_TEST(std::abs(c.distance - 2.0) <= 1e-13);
  BOOST_TEST(c.several_minima());
  for (const auto& uv : params) BOOST_TEST(std::abs(s.point(uv.x(), uv.y()).norm() - 2.0) <= 1e-13);
  // Outside and inside points: distance | |P| - R |, foot along P.
  test::Rng r(4);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d dir = Eigen::Vector3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)).normalized();
    const double rho = r.uniform(0.2, 5.0);
    const auto res = proj.project(rho * dir);
    BOOST_TEST(std::abs(res.distance - std::abs(rho - 2.0)) <= 1e-12);
    BOOST_TEST((res.point - 2.0 * dir).norm() <= 1e-7);
  }
}

BOOST_AUTO_TEST_CASE(point_on_surface_and_radius) {
  test::Rng r(8);
  for (int i = 0; i < 40; ++i) {
    const auto s = test::random_surface(r, i % 2 == 0);
    SurfaceProjector proj(s);
    const Eigen::Vector3d P = s.point(r.uniform(s.first_u(), s.last_u()), r.uniform(s.first_v(), s.last_v()));
    BOOST_TEST(proj.project(P).distance <= 1e-11);
    const auto far = proj.project(P + Eigen::Vector3d(1e3, 0, 0), 10.0);
    BOOST_TEST(!far.found);
  }
}
