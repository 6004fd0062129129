// Meridional net: m and m' against closed forms (cylinder, cone) and dense Simpson quadrature (curved
// contour), streamline blending, station cuts, and the validity checks.
#define BOOST_TEST_MODULE meridional_net
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "src/algo/project_point_curve.hpp"
#include "src/blade/meridional_net.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::blade;

namespace {

MeridionalNetDefinition cylinder_net() {
  MeridionalNetDefinition d;
  d.hub = {{0, 200}, {100, 200}};
  d.casing = {{0, 250}, {100, 250}};
  return d;
}

// Composite Simpson on [a, b] with n (even) panels: reference for the Gauss-Legendre tables.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
  return s * h / 3;
}

}  // namespace

BOOST_AUTO_TEST_CASE(cylinder_m_prime_is_m_over_r) {
  // Collinear points: the cubic interpolant is the line with a linear parametrisation, so m' = m / r
  // holds to rounding; 1e-13 relative covers the quadrature's summation error.
  MeridionalNetDefinition d = cylinder_net();
  d.hub = {{0, 200}, {13, 200}, {40, 200}, {71, 200}, {100, 200}};
  const MeridionalNet net(d);
  const Streamline& hub = net.hub();
  BOOST_TEST(std::abs(hub.total_length() - 100) < 1e-12 * 100);
  BOOST_TEST(std::abs(hub.total_m_prime() - 0.5) < 1e-13);
  for (int k = 0; k <= 50; ++k) {
    const double u = hub.first_param() + (hub.last_param() - hub.first_param()) * k / 50.0;
    const double m = hub.point(u).x();  // x is the arc length on this line
    BOOST_TEST(std::abs(hub.meridional_length(u) - m) < 1e-12 * 100);
    BOOST_TEST(std::abs(hub.m_prime(u) - m / 200) < 1e-13);
    // Inverse round trip.
    BOOST_TEST(std::abs(hub.param_at_m_prime(hub.m_prime(u)) - u) < 1e-12);
    BOOST_TEST(std::abs(hub.param_at_length(m) - u) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(cone_m_prime_matches_closed_form) {
  // r = r0 + m sin(phi): m' = ln(r / r0) / sin(phi). The integrand 1 / (a + b u) is not polynomial; the
  // 8-point rule on 4 cells per span is still exact to ~1e-15 for b h / a < 0.1, so 1e-12 relative.
  for (double phi_deg : {5.0, 20.0, 45.0, 70.0, -30.0}) {
    const double phi = phi_deg * M_PI / 180, r0 = 150, L = 80;
    MeridionalNetDefinition d;
    for (double m : {0.0, 11.0, 30.0, 52.0, 80.0}) d.hub.emplace_back(m * std::cos(phi), r0 + m * std::sin(phi));
    for (double m : {0.0, 80.0})
      d.casing.emplace_back(m * std::cos(phi) - 40 * std::sin(phi), r0 + 40 * std::cos(phi) + m * std::sin(phi));
    const MeridionalNet net(d);
    const Streamline& hub = net.hub();
    BOOST_TEST(std::abs(hub.total_length() - L) < 1e-12 * L);
    for (int k = 0; k <= 40; ++k) {
      const double u = hub.first_param() + (hub.last_param() - hub.first_param()) * k / 40.0;
      const double m = hub.meridional_length(u), r = hub.point(u).y();
      BOOST_TEST(std::abs(r - (r0 + m * std::sin(phi))) < 1e-10);
      const double exact = std::log(r / r0) / std::sin(phi);
      BOOST_TEST(std::abs(hub.m_prime(u) - exact) < 1e-12 * (1 + exact), "phi " << phi_deg << " u " << u);
      BOOST_TEST(std::abs(hub.param_at_m_prime(exact) - u) < 1e-11);
    }
  }
}

BOOST_AUTO_TEST_CASE(curved_contour_matches_simpson) {
  // A curved hub: m' against composite Simpson with 20000 panels per knot span (error ~1e-14).
  MeridionalNetDefinition d;
  d.hub = {{-30, 272}, {0, 275}, {20, 277.5}, {40, 279}, {70, 280}};
  d.casing = {{-30, 334}, {0, 331}, {20, 329.5}, {40, 329}, {70, 330}};
  const MeridionalNet net(d);
  for (const Streamline& s : net.streamlines()) {
    const auto& U = s.curve().knots();
    double m = 0, mp = 0;
    for (std::size_t i = 0; i + 1 < U.size(); ++i) {
      if (U[i + 1] <= U[i]) continue;
      auto speed = [&](double u) { return s.curve().derivatives(u, 1)[1].norm(); };
      m += simpson(speed, U[i], U[i + 1], 20000);
      mp += simpson([&](double u) { return speed(u) / s.curve().point(u).y(); }, U[i], U[i + 1], 20000);
    }
    BOOST_TEST(std::abs(s.total_length() - m) < 1e-11 * m);
    BOOST_TEST(std::abs(s.total_m_prime() - mp) < 1e-11 * mp);
  }
}

BOOST_AUTO_TEST_CASE(blended_streamlines_and_stations) {
  MeridionalNetDefinition d = cylinder_net();
  d.interpolated_spans = {0.5};
  d.leading_edge = {{20, 190}, {25, 260}};
  d.trailing_edge = {{80, 195}, {78, 230}, {81, 255}};
  const MeridionalNet net(d);
  BOOST_TEST_REQUIRE(net.streamlines().size() == 3u);
  const Streamline& mid = net.streamlines()[1];
  BOOST_TEST(mid.span() == 0.5);
  for (int k = 0; k <= 20; ++k) {
    const double u = mid.first_param() + (mid.last_param() - mid.first_param()) * k / 20.0;
    BOOST_TEST(std::abs(mid.point(u).y() - 225) < 1e-10);  // blend of r = 200 and 250
  }
  // Extrapolated (over-build) streamline: linear in span.
  const Streamline below = net.streamline_at(-0.1);
  BOOST_TEST(std::abs(below.point(below.first_param()).y() - 195) < 1e-10);
  // Every cut lies on both curves (1e-9 mm: the intersection tolerance).
  for (const auto* q : {&*net.leading_edge(), &*net.trailing_edge()}) {
    BOOST_TEST_REQUIRE(q->cuts.size() == 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      const StationCut& c = q->cuts[k];
      BOOST_TEST((net.streamlines()[k].point(c.streamline_param) - c.point).norm() < 1e-9);
      BOOST_TEST((q->curve.point(c.station_param) - c.point).norm() < 1e-9);
    }
  }
  // LE line from (20, 190) to (25, 260): the cut with r = 200 is at x = 20 + 5 * 10 / 70.
  BOOST_TEST(std::abs(net.leading_edge()->cuts[0].point.x() - (20 + 50.0 / 70)) < 1e-9);
}

BOOST_AUTO_TEST_CASE(station_ending_on_the_contours) {
  // A leading-edge line whose ends lie exactly on hub and casing is accepted.
  MeridionalNetDefinition d = cylinder_net();
  d.leading_edge = {{20, 200}, {22, 250}};
  const MeridionalNet net(d);
  BOOST_TEST((net.leading_edge()->cuts[0].point - Eigen::Vector2d(20, 200)).norm() < 1e-9);
  BOOST_TEST((net.leading_edge()->cuts[1].point - Eigen::Vector2d(22, 250)).norm() < 1e-9);
}

BOOST_AUTO_TEST_CASE(invalid_nets_throw) {
  for (int n : {15, 100001}) {  // samples in [16, 100000], as the schema
    MeridionalNetDefinition d = cylinder_net();
    d.samples = n;
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // r <= 0
    MeridionalNetDefinition d = cylinder_net();
    d.hub = {{0, -5}, {100, 10}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // r dips below zero between positive points
    MeridionalNetDefinition d = cylinder_net();
    d.hub = {{0, 5}, {30, 0.5}, {60, 0.5}, {100, 5}};
    d.hub[1].y() = 0.01;
    d.hub[2].y() = -0.01;
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // explicit streamline crossing the casing
    MeridionalNetDefinition d = cylinder_net();
    d.streamlines = {{{0, 220}, {50, 260}, {100, 220}}};
    d.streamline_spans = {0.5};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // streamline on the wrong side of the hub (no crossing, wrong order)
    MeridionalNetDefinition d = cylinder_net();
    d.streamlines = {{{0, 150}, {100, 150}}};
    d.streamline_spans = {0.5};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // hub and casing crossing
    MeridionalNetDefinition d = cylinder_net();
    d.casing = {{0, 250}, {100, 150}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // span list mismatch / not increasing
    MeridionalNetDefinition d = cylinder_net();
    d.streamlines = {{{0, 220}, {100, 220}}, {{0, 230}, {100, 230}}};
    d.streamline_spans = {0.5};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
    d.streamline_spans = {0.6, 0.5};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
    d.streamline_spans = {0.4, 0.6};
    BOOST_CHECK_NO_THROW(MeridionalNet{d});
  }
  {  // LE line missing the casing
    MeridionalNetDefinition d = cylinder_net();
    d.leading_edge = {{20, 190}, {20, 230}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // TE line cutting the hub three times
    MeridionalNetDefinition d = cylinder_net();
    d.trailing_edge = {{70, 190}, {75, 210}, {80, 190}, {85, 260}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // too few points, coincident points
    MeridionalNetDefinition d = cylinder_net();
    d.hub = {{0, 200}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
    d.hub = {{0, 200}, {0, 200}, {100, 200}};
    BOOST_CHECK_THROW(MeridionalNet{d}, InvalidGeometry);
  }
  {  // m' outside the streamline
    const MeridionalNet net(cylinder_net());
    BOOST_CHECK_THROW(net.hub().param_at_m_prime(0.6), InvalidGeometry);
    BOOST_CHECK_THROW(net.hub().param_at_m_prime(-0.01), InvalidGeometry);
  }
}
