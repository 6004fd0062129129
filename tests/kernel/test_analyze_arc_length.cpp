// Arc length and its inverse against OCCT's GCPnts_AbscissaPoint on random curves, and the exact
// length 2 pi of the nine-point rational circle.
#define BOOST_TEST_MODULE analyze_arc_length
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/analyze/arc_length.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

template <int Dim>
using Adaptor = typename std::conditional<Dim == 3, GeomAdaptor_Curve, Geom2dAdaptor_Curve>::type;

// Both sides integrate |C'| to 1e-12 relative (OCCT with the tolerance passed explicitly); 1e-9 leaves
// room for OCCT's Gauss panels, whose tolerance is checked less strictly than ours.
template <int Dim>
void compare_lengths(unsigned long seed) {
  test::Rng r(seed);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<Dim>(r, i % 2 == 1);
    const Adaptor<Dim> ad(occt::to_occt(c));
    const ArcLength<Dim> table(c);
    const double L = GCPnts_AbscissaPoint::Length(ad, c.first_param(), c.last_param(), 1e-12);
    BOOST_TEST(std::abs(table.total() - L) <= 1e-9 * L);
    double a = r.uniform(c.first_param(), c.last_param()), b = r.uniform(c.first_param(), c.last_param());
    if (a > b) std::swap(a, b);
    const double Lab = GCPnts_AbscissaPoint::Length(ad, a, b, 1e-12);
    BOOST_TEST(std::abs(arc_length(c, a, b) - Lab) <= 1e-9 * L);
    BOOST_TEST(std::abs(table.length(a, b) - Lab) <= 1e-9 * L);
    // Inverse: our parameter at a random length reproduces the length to the tolerance, and lies at
    // OCCT's parameter for the same abscissa within the parameter resolution of that length.
    const double s = r.uniform(0, table.total());
    const double u = table.param_at(s);
    BOOST_TEST(std::abs(table.length_to(u) - s) <= 1e-10 * L);
    typename BSplineCurve<Dim>::Point d[2];
    if (i % 10 == 0) {  // OCCT's inverse at 1e-12 costs ~50x ours: a sample of 100 curves
      GCPnts_AbscissaPoint ap(1e-12, ad, s, c.first_param());
      BOOST_TEST_REQUIRE(ap.IsDone());
      c.derivatives(u, 1, d);
      BOOST_TEST(std::abs(ap.Parameter() - u) * d[1].norm() <= 1e-9 * L);
    }
    if (i % 4 == 0) {  // the free function rebuilds the whole table: a sample keeps ASan runs short
      c.derivatives(b, 1, d);
      BOOST_TEST(std::abs(param_at_arc_length(c, a, Lab) - b) * d[1].norm() <= 1e-9 * L);
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_3d_vs_occt) { compare_lengths<3>(21); }
BOOST_AUTO_TEST_CASE(random_2d_vs_occt) { compare_lengths<2>(22); }

BOOST_AUTO_TEST_CASE(circle_two_pi) {
  const double s = std::sqrt(0.5);
  const Curve2 circle(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                      {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                      {1, s, 1, s, 1, s, 1, s, 1});
  // Exact geometry: only quadrature truncation (<= tolerance 1e-13) and rounding.
  BOOST_TEST(std::abs(arc_length(circle, 1e-13) - 2 * M_PI) <= 1e-12);
  BOOST_TEST(std::abs(arc_length(circle, 0.0, 0.25) - M_PI / 2) <= 1e-12);
  // The quarter points are at lengths k pi / 2 (symmetry of the nine-point circle).
  const ArcLength<2> table(circle);
  for (int k = 1; k < 4; ++k) BOOST_TEST(std::abs(table.param_at(k * M_PI / 2) - 0.25 * k) <= 1e-12);
  // Angle from the arc length: the point at length phi is (cos phi, sin phi).
  for (int k = 0; k <= 100; ++k) {
    const double phi = 2 * M_PI * k / 100;
    const Eigen::Vector2d P = circle.point(table.param_at(phi));
    BOOST_TEST((P - Eigen::Vector2d(std::cos(phi), std::sin(phi))).norm() <= 1e-11);
  }
  BOOST_CHECK_THROW(table.param_at(7.0), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(periodic_curve_length) {
  // A periodic interpolant of a circle: its length is close to 2 pi and equals OCCT's for the periodic
  // OCCT curve.
  PointList<2> Q;
  for (int k = 0; k < 40; ++k) Q.emplace_back(std::cos(2 * M_PI * k / 40), std::sin(2 * M_PI * k / 40));
  const Curve2 c = interpolate_closed<2>(Q, 3);
  const double L = arc_length(c);
  BOOST_TEST(std::abs(L - 2 * M_PI) <= 1e-5);  // interpolation error of a cubic at 40 points ~ h^4
  const Geom2dAdaptor_Curve ad(occt::to_occt(c));
  BOOST_TEST(std::abs(L - GCPnts_AbscissaPoint::Length(ad, c.first_param(), c.last_param(), 1e-12)) <= 1e-9 * L);
}
