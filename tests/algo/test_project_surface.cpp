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

#include <Eigen/Cholesky>
#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/knots.hpp"
#include "support/eval_scales.hpp"
#include "support/random_geometry.hpp"
#include "support/random_periodic.hpp"

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

namespace {

// Two random query points near s (within 5 of a random surface point): ours must be a surface point
// at its distance, with parameters in the domain (a periodic direction's in [first, last)), never
// farther than OCCT's answer (1e-10) nor than a dense sample (1e-12). Returns the cases where OCCT's
// answer is a non-global minimum (ours strictly closer).
int compare_with_occt(const BSplineSurface<3>& s, test::Rng& r, int& cases) {
  const auto os = occt::to_occt(s);
  SurfaceProjector proj(s);
  int occt_missed = 0;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d P = s.point(r.uniform(s.first_u(), s.last_u()), r.uniform(s.first_v(), s.last_v())) +
                              r.uniform(0, 5) * Eigen::Vector3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
    const auto res = proj.project(P);
    BOOST_TEST_REQUIRE(res.found);
    ++cases;
    const bool pu = s.is_periodic_u(), pv = s.is_periodic_v();
    BOOST_TEST((res.u >= s.first_u() && (pu ? res.u < s.last_u() : res.u <= s.last_u())));
    BOOST_TEST((res.v >= s.first_v() && (pv ? res.v < s.last_v() : res.v <= s.last_v())));
    BOOST_TEST((s.point(res.u, res.v) - res.point).norm() <= 1e-12 * (1 + res.point.norm()));
    BOOST_TEST(std::abs((res.point - P).norm() - res.distance) <= 1e-13 * (1 + res.distance));
    const double o = occt_distance(os, s, P);
    BOOST_TEST(res.distance <= o + 1e-10);
    if (res.distance < o - 1e-10) ++occt_missed;
    BOOST_TEST(res.distance <= sampled_min(s, P, 30) + 1e-12);
  }
  return occt_missed;
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_vs_occt) {
  test::Rng r(21);
  int cases = 0, occt_missed = 0;
  for (int i = 0; i < 250; ++i) occt_missed += compare_with_occt(test::random_surface(r, i % 2 == 1), r, cases);
  std::printf("surface: %d cases, ours strictly closer than OCCT in %d\n", cases, occt_missed);
  BOOST_TEST(cases == 500);
}

namespace {

// The nine-point unit circle (kernel-references.md): poles, weights, and its knots, either clamped on
// [0, 1] or as one period of a periodic curve (the last pole dropped; seam multiplicity 2 = degree).
const double kS = std::sqrt(0.5);
const std::vector<Eigen::Vector2d> kCircle = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
const std::vector<double> kCircleW = {1, kS, 1, kS, 1, kS, 1, kS, 1};
const std::vector<double> kCircleKnots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};

// Surface of revolution about z of the profile (x, z) = (a + b cos, b sin) over `profile` poles (a
// full circle or the half circle of a sphere), exact rational biquadratic NURBS; u = longitude (as a
// periodic direction when periodic_u), v = the profile.
BSplineSurface<3> revolve(const std::vector<Eigen::Vector2d>& profile, const std::vector<double>& pw,
                          const std::vector<double>& V, bool periodic_u) {
  const int nu = periodic_u ? 10 : 9;  // periodic: 8 distinct poles + 2 repeated (degree 2)
  const int nv = static_cast<int>(profile.size());
  std::vector<std::vector<Eigen::Vector3d>> P(static_cast<std::size_t>(nu), std::vector<Eigen::Vector3d>(static_cast<std::size_t>(nv)));
  std::vector<std::vector<double>> W(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      // Periodic knots start one span early (-0.25): periodic pole i is the clamped pole i - 1.
      const std::size_t ic = static_cast<std::size_t>(periodic_u ? (i + 7) % 8 : i), jj = static_cast<std::size_t>(j);
      P[static_cast<std::size_t>(i)][jj] = Eigen::Vector3d(kCircle[ic].x() * profile[jj].x(), kCircle[ic].y() * profile[jj].x(), profile[jj].y());
      W[static_cast<std::size_t>(i)][jj] = kCircleW[ic] * pw[jj];
    }
  std::vector<double> U = kCircleKnots;
  if (periodic_u) U = unwrap_periodic_knots(2, {0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75}, 1.0);
  return BSplineSurface<3>::from_poles(2, 2, U, V, P, W, periodic_u, false);
}

// Rational quadratic sphere of radius R (u: nine-point circle in longitude, v: half circle in
// latitude), exact NURBS.
BSplineSurface<3> sphere(double R, bool periodic_u = false) {
  std::vector<Eigen::Vector2d> lat = {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};  // (radius, z)
  for (auto& q : lat) q *= R;
  return revolve(lat, {1, kS, 1, kS, 1}, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, periodic_u);
}

// Torus of major radius a and tube radius b about z (clamped in both directions, or periodic in u).
BSplineSurface<3> torus(double a, double b, bool periodic_u) {
  std::vector<Eigen::Vector2d> tube;
  for (const auto& q : kCircle) tube.emplace_back(a + b * q.x(), b * q.y());
  return revolve(tube, kCircleW, kCircleKnots, periodic_u);
}

// Exact foot of P on the torus (a, b): on the tube circle nearest to P's meridian plane.
Eigen::Vector3d torus_foot(double a, double b, const Eigen::Vector3d& P) {
  const Eigen::Vector2d rho(P.x(), P.y());
  const Eigen::Vector3d centre = a * Eigen::Vector3d(rho.x(), rho.y(), 0) / rho.norm();
  return centre + b * (P - centre).normalized();
}

}  // namespace

BOOST_AUTO_TEST_CASE(sphere_cases) {
  for (bool periodic : {false, true}) {
    const auto s = sphere(2.0, periodic);
    SurfaceProjector proj(s);
    // Centre: every point is at distance R.
    std::vector<Eigen::Vector2d> params;
    const auto c = proj.project_all(Eigen::Vector3d::Zero(), params);
    BOOST_TEST(std::abs(c.distance - 2.0) <= 1e-13);
    BOOST_TEST(c.several_minima());
    for (const auto& uv : params) BOOST_TEST(std::abs(s.point(uv.x(), uv.y()).norm() - 2.0) <= 1e-13);
    // Outside and inside points: distance | |P| - R |, foot R P / |P|. The foot is a simple minimum
    // (Hessian ~ |S_u|^2 > 0), so Newton takes it to rounding: 1e-10 leaves a factor ~1e4 over the
    // rounding of the rational evaluation (1e-14 of the radius).
    test::Rng r(4);
    for (int i = 0; i < 100; ++i) {
      const Eigen::Vector3d dir = Eigen::Vector3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)).normalized();
      const double rho = r.uniform(0.2, 5.0);
      const auto res = proj.project(rho * dir);
      BOOST_TEST(std::abs(res.distance - std::abs(rho - 2.0)) <= 1e-12);
      BOOST_TEST((res.point - 2.0 * dir).norm() <= 1e-10, "periodic " << periodic << " rho " << rho);
      BOOST_TEST((s.point(res.u, res.v) - res.point).norm() <= 1e-13);
    }
  }
}

BOOST_AUTO_TEST_CASE(torus_feet_within_1e10) {
  // Torus a = 3, b = 1 as exact NURBS, clamped and periodic in u. Query points off the axis and off
  // the tube's centre circle (where the foot is unique) at distances 0.05..3 from the tube circle.
  const double a = 3, b = 1;
  for (bool periodic : {false, true}) {
    const auto s = torus(a, b, periodic);
    SurfaceProjector proj(s);
    test::Rng r(9);
    for (int i = 0; i < 100; ++i) {
      const double phi = r.uniform(-M_PI, M_PI), theta = r.uniform(-M_PI, M_PI), rho = r.uniform(0.05, 3.0);
      if (std::abs(rho - b) < 0.05) continue;  // on the surface: foot trivially the point
      const Eigen::Vector3d P((a + rho * std::cos(theta)) * std::cos(phi), (a + rho * std::cos(theta)) * std::sin(phi),
                              rho * std::sin(theta));
      const Eigen::Vector3d foot = torus_foot(a, b, P);
      const auto res = proj.project(P);
      BOOST_TEST(std::abs(res.distance - (P - foot).norm()) <= 1e-12);
      BOOST_TEST((res.point - foot).norm() <= 1e-10, "periodic " << periodic << " phi " << phi << " theta " << theta);
    }
  }
}

namespace {

// One-sided partial S_u at the u seam of a surface periodic in u: from the left (end of the period)
// or the right (start).
Eigen::Vector3d seam_su(const BSplineSurface<3>& s, double v, bool left) {
  const double u = left ? std::nextafter(s.last_u(), s.first_u()) : s.first_u();
  return s.derivatives<1>(u, v).S_u();
}

}  // namespace

// Periodic surfaces (periodic in u, v or both; seam and interior multiplicities 1..degree) against
// OCCT's GeomAPI_ProjectPointOnSurf, which handles periodic B-spline surfaces natively. Tolerance as
// random_vs_occt; ours must also be no farther than a dense sample of the surface (independent).
BOOST_AUTO_TEST_CASE(periodic_surfaces_vs_occt) {
  test::Rng r(22);
  int cases = 0, occt_missed = 0;
  for (int i = 0; i < 250; ++i) {
    const bool pu = i % 3 != 1, pv = i % 3 != 0;
    occt_missed += compare_with_occt(test::random_periodic_surface(r, i % 2 == 1, pu, pv), r, cases);
  }
  std::printf("periodic surfaces: %d cases, ours strictly closer than OCCT in %d\n", cases, occt_missed);
  BOOST_TEST(cases == 500);
}

// Query points whose foot lies on the u seam of a periodic surface: P = Q + t m with Q = S(seam, v0).
// Smooth seam (multiplicity < degree): m is the unit normal at Q and t is small enough that the
// distance Hessian I - t II (first and second fundamental forms along m) stays positive definite with
// a factor 2 to spare, so Q is a strict local minimum. Crease (multiplicity = degree, C0 along the
// seam): m lies in the wedge between the two one-sided normal planes, so the distance grows to first
// order on both sides; t = 1e-5 of the size keeps curvature terms below that growth. The construction is
// checked independently: a projection closer than t must be a genuine surface point at that distance
// (then the case is not a seam foot and is only counted).
BOOST_AUTO_TEST_CASE(feet_on_the_seam) {
  test::Rng r(23);
  int checked = 0, disproved = 0;
  for (int i = 0; i < 200; ++i) {
    const bool crease = i % 2 == 1;
    const auto s = test::random_periodic_surface(r, i % 4 >= 2, true, i % 3 == 0, crease);
    const double v0 = r.uniform(s.first_v(), s.last_v());
    const bool seam_crease = knot_multiplicity(s.knots_u(), s.first_u()) >= s.degree_u();
    if (seam_crease != crease) continue;  // degree-1 or random seam multiplicity: not this construction
    const Eigen::Vector3d Q = s.point(s.first_u(), v0);
    const auto d = s.derivatives<2>(s.first_u(), v0);
    const Eigen::Vector3d a = -seam_su(s, v0, true), b = seam_su(s, v0, false);  // leaving the seam
    if (d.S_v().norm() < 1e-3 || a.norm() < 1e-3 || b.norm() < 1e-3) continue;  // degenerate: no normal
    const double size = test::pole_scale(s);
    Eigen::Vector3d m;
    double t;
    if (crease) {
      const Eigen::Vector3d Sv = d.S_v();
      auto perp = [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(x - x.dot(Sv) / Sv.squaredNorm() * Sv); };
      const Eigen::Vector3d ap = perp(a).normalized(), bp = perp(b).normalized();
      if ((ap + bp).norm() < 0.2) continue;  // nearly smooth: not a crease test
      m = -(ap + bp).normalized();
      t = 1e-5 * size;
    } else {
      m = s.normal(s.first_u(), v0) * (r.coin() ? 1.0 : -1.0);
      Eigen::Matrix2d I, II;
      I << d.S_u().dot(d.S_u()), d.S_u().dot(d.S_v()), d.S_u().dot(d.S_v()), d.S_v().dot(d.S_v());
      II << m.dot(d.S_uu()), m.dot(d.S_uv()), m.dot(d.S_uv()), m.dot(d.S_vv());
      t = 1e-3 * size;
      while (Eigen::Matrix2d(I - 2 * t * II).llt().info() != Eigen::Success || (I - 2 * t * II).determinant() <= 0) t *= 0.5;
    }
    const Eigen::Vector3d P = Q + t * m;
    SurfaceProjector proj(s);
    const auto res = proj.project(P);
    // A closer point than Q, verified to be a genuine surface point at that distance, disproves the
    // construction (a feature of the surface within t of P elsewhere): not a seam-foot case.
    if (res.distance < t - 1e-12 * size && (s.point(res.u, res.v) - res.point).norm() <= 1e-13 * size &&
        std::abs((res.point - P).norm() - res.distance) <= 1e-13 * size) {
      ++disproved;
      continue;
    }
    ++checked;
    if (crease) {  // the C0 seam is projected as a crease iso-curve (step 1 of the projector)
      bool listed = false;
      for (const auto& [fixed_u, value] : proj.iso_curves()) listed = listed || (fixed_u && value == s.first_u());
      BOOST_TEST(listed);
    }
    BOOST_TEST(std::abs(res.distance - t) <= 1e-12 * size, "case " << i << " crease " << crease);
    BOOST_TEST((res.point - Q).norm() <= 1e-10 * size, "case " << i << " crease " << crease);
  }
  std::printf("feet on the seam: %d checked, %d constructions disproved by a closer surface point\n", checked,
              disproved);
  BOOST_TEST(checked >= 100);
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
