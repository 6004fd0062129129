// Textbook values from /work/shared/notes/kernel-references.md, sections "Basis functions",
// "B-spline curve", "NURBS curve", "Rational quarter circle", "Nine-point unit circle" and "Surfaces".
// Each value is checked with de Boor (BSplineCurve / BSplineSurface) and with the batched evaluators.
// Tolerances follow the precision the reference states: values given to 6 decimals -> 1e-6, to 4
// decimals -> 1e-4 (the half unit of the last digit, rounded up), exact fractions -> 1e-14 relative
// to the value's magnitude (a few ulps of the O(p) sums), and the nine-point circle's
// "|C| = 1 and curvature 1 to 1e-15" as stated (plus 1e-14 for its 15-digit point).
#define BOOST_TEST_MODULE textbook
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "src/core/basis.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/knots.hpp"
#include "src/core/surface_evaluator.hpp"
#include "src/modify/knot_insertion.hpp"

using namespace cg;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

namespace {

constexpr double kExact = 1e-14;

// Exact reference values: |a - b| <= tol * max(1, |b|) (relative above 1, absolute below).
template <class A, class B>
bool near(const A& a, const B& b, double tol) {
  return (a - b).norm() <= tol * std::max(1.0, b.norm());
}

// Values given to d decimals: absolute, |a - b| <= tol (per component at most half a unit of the
// last digit, so the 2D/3D norm stays below one unit).
template <class A, class B>
bool decimals(const A& a, const B& b, double tol) {
  return (a - b).norm() <= tol;
}

// De Boor derivatives up to `order`; the span-cached evaluator must agree with them to `tol`
// relative (1e-12 for inexact values: a few ulps of the O(p) sums, different summation order).
template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> both_ways(const BSplineCurve<Dim>& c, double u, int order,
                                                         double tol) {
  const auto d = c.derivatives(u, order);
  CurveEvaluator<Dim> ev(c);
  typename BSplineCurve<Dim>::Point P, D1, D2;
  ev.d2(u, P, D1, D2);
  BOOST_TEST(near(P, d[0], tol));
  if (order >= 1) BOOST_TEST(near(D1, d[1], tol));
  if (order >= 2) BOOST_TEST(near(D2, d[2], tol));
  return d;
}

const std::vector<V2> kBookPoles{{5, 5}, {10, 10}, {20, 15}, {35, 15}, {45, 10}, {50, 5}};
const std::vector<double> kBookKnots{0, 0, 0, 0, 0.33, 0.66, 1, 1, 1, 1};

double curvature(const V2& d1, const V2& d2) {
  return std::abs(d1.x() * d2.y() - d1.y() * d2.x()) / std::pow(d1.norm(), 3);
}

}  // namespace

BOOST_AUTO_TEST_CASE(basis_functions_ex_2_3_and_2_4) {
  const std::vector<double> U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
  const int p = 2, n = static_cast<int>(U.size()) - p - 2;  // 8 poles, n = 7
  const double u = 2.5;
  const int span = find_span(U.data(), n, p, u);
  BOOST_TEST(span == 4);
  BOOST_TEST(SpanTable(U.data(), n, p, 0.0, false).find(u) == 4);
  double N[3];
  basis_funs(span, u, p, U.data(), N);
  const double expect0[3] = {1.0 / 8, 6.0 / 8, 1.0 / 8};
  for (int j = 0; j < 3; ++j) BOOST_TEST(std::abs(N[j] - expect0[j]) <= kExact);
  double ders[3 * 3];
  ders_basis_funs(span, u, p, 2, U.data(), ders);
  const double expect[3][3] = {{1.0 / 8, 6.0 / 8, 1.0 / 8}, {-0.5, 0.0, 0.5}, {1.0, -2.0, 1.0}};
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j < 3; ++j) BOOST_TEST(std::abs(ders[k * 3 + j] - expect[k][j]) <= kExact, "k " << k << " j " << j);
  BOOST_TEST(knot_multiplicity(U, 0.5) == 0);
  BOOST_TEST(knot_multiplicity(U, 2.0) == 1);
  BOOST_TEST(knot_multiplicity(U, 4.0) == 2);
  BOOST_TEST(knot_multiplicity(U, 5.0) == 3);
}

BOOST_AUTO_TEST_CASE(bspline_curve_points_and_derivatives) {
  const BSplineCurve<2> c(3, kBookKnots, kBookPoles);
  const double tol = 1e-6;  // reference values given to 6 decimals
  BOOST_TEST(decimals(both_ways(c, 0.3, 0, 1e-12)[0], V2(18.617581, 13.377160), tol));
  BOOST_TEST(decimals(both_ways(c, 0.5, 0, 1e-12)[0], V2(27.645492, 14.691702), tol));
  BOOST_TEST(decimals(both_ways(c, 0.6, 0, 1e-12)[0], V2(32.143206, 14.328136), tol));
  const auto d = both_ways(c, 0.35, 2, 1e-12);
  BOOST_TEST(decimals(d[0], V2(20.879273, 13.963507), tol));
  BOOST_TEST(decimals(d[1], V2(45.200154, 9.987463), tol));
  BOOST_TEST(decimals(d[2], V2(-1.334434, -68.746857), tol));
}

BOOST_AUTO_TEST_CASE(bspline_curve_knot_insertion_keeps_the_curve) {
  const BSplineCurve<2> c(3, kBookKnots, kBookPoles);
  const BSplineCurve<2> r = insert_knot(c, 0.5);
  const std::vector<double> U{0, 0, 0, 0, 0.33, 0.5, 0.66, 1, 1, 1, 1};
  BOOST_TEST(r.knots() == U, boost::test_tools::per_element());
  // Poles listed to 7 significant digits: 1e-6 absolute on values up to 50.
  const std::vector<V2> P{{5, 5},        {10, 10},          {17.5757576, 13.7878788}, {27.5, 15},
                          {37.5373134, 13.7313433}, {45, 10}, {50, 5}};
  BOOST_TEST(r.num_poles() == 7);
  for (int i = 0; i < std::min(7, r.num_poles()); ++i)
    BOOST_TEST((r.pole(i) - P[static_cast<std::size_t>(i)]).norm() <= 1e-6, "pole " << i);
  // The curve is unchanged: 1e-12 relative to the pole scale 50 (a few ulps of the convex combinations).
  for (int k = 0; k <= 20; ++k) {
    const double u = k / 20.0;
    BOOST_TEST((r.point(u) - c.point(u)).norm() <= 1e-12 * 50);
  }
}

BOOST_AUTO_TEST_CASE(bspline_curve_integer_knots_exact) {
  const BSplineCurve<2> c(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, kBookPoles);
  BOOST_TEST(near(both_ways(c, 1.0, 0, kExact)[0], V2(20, 13.75), kExact));
  BOOST_TEST(near(both_ways(c, 1.5, 0, kExact)[0], V2(27.5, 14.6875), kExact));
  BOOST_TEST(near(both_ways(c, 2.0, 0, kExact)[0], V2(35, 13.75), kExact));
}

BOOST_AUTO_TEST_CASE(nurbs_curve_points_and_derivatives) {
  const BSplineCurve<2> c(3, kBookKnots, kBookPoles, {0.5, 1, 0.75, 1, 0.25, 1});
  const double tol = 1e-4;  // reference values given to 4 decimals (the point at 0.2 states +-1e-4)
  const auto a = both_ways(c, 0.2, 2, 1e-12);
  BOOST_TEST(decimals(a[0], V2(13.818182, 11.510417), tol));
  BOOST_TEST(decimals(a[1], V2(40.0602, 17.3878), tol));
  BOOST_TEST(decimals(a[2], V2(104.4062, -29.3673), tol));
  const auto b = both_ways(c, 0.5, 3, 1e-12);
  BOOST_TEST(decimals(b[0], V2(28.1775, 14.7859), tol));
  BOOST_TEST(decimals(b[1], V2(39.7272, 2.2563), tol));
  BOOST_TEST(decimals(b[2], V2(-116.9255, -49.7368), tol));
  BOOST_TEST(decimals(b[3], V2(125.5276, 196.8866), tol));
}

BOOST_AUTO_TEST_CASE(rational_quarter_circle_ex_4_1) {
  const BSplineCurve<2> c(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, 1, 2});
  const auto d0 = both_ways(c, 0.0, 3, kExact);
  BOOST_TEST(near(d0[0], V2(1, 0), kExact));
  BOOST_TEST(near(d0[1], V2(0, 2), kExact));
  BOOST_TEST(near(d0[2], V2(-4, 0), kExact));
  BOOST_TEST(near(d0[3], V2(0, -12), kExact));
  const auto h = both_ways(c, 0.5, 2, kExact);
  BOOST_TEST(near(h[0], V2(3.0 / 5, 4.0 / 5), kExact));
  BOOST_TEST(near(h[1], V2(-32.0 / 25, 24.0 / 25), kExact));
  BOOST_TEST(near(h[2], V2(-64.0 / 125, -352.0 / 125), kExact));
  // C(u) = ((1-u^2)/(1+u^2), 2u/(1+u^2)) and curvature 1 on a grid.
  CurveEvaluator<2> ev(c);
  for (int k = 0; k <= 32; ++k) {
    const double u = k / 32.0;
    const V2 exact((1 - u * u) / (1 + u * u), 2 * u / (1 + u * u));
    const auto d = c.derivatives(u, 2);
    BOOST_TEST(near(d[0], exact, kExact));
    BOOST_TEST(near(ev.point(u), exact, kExact));
    BOOST_TEST(std::abs(curvature(d[1], d[2]) - 1.0) <= kExact);
  }
}

BOOST_AUTO_TEST_CASE(nine_point_unit_circle) {
  const double s = std::sqrt(2.0) / 2;
  const BSplineCurve<2> c(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                          {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                          {1, s, 1, s, 1, s, 1, s, 1});
  BOOST_TEST(near(both_ways(c, 1.0 / 16, 0, kExact)[0], V2(0.929788301062430, 0.368094709561873), kExact));
  BOOST_TEST(near(both_ways(c, 1.0 / 8, 0, kExact)[0], V2(s, s), kExact));
  BOOST_TEST(near(both_ways(c, 0.0, 1, kExact)[1], V2(0, 4 * std::sqrt(2.0)), kExact));
  // Stated: |C| = 1 and curvature 1 to 1e-15 at every parameter (de Boor and the evaluator).
  CurveEvaluator<2> ev(c);
  for (int k = 0; k <= 400; ++k) {
    const double u = k / 400.0;
    const auto d = c.derivatives(u, 2);
    BOOST_TEST(std::abs(d[0].norm() - 1.0) <= 1e-15, "u = " << u);
    BOOST_TEST(std::abs(curvature(d[1], d[2]) - 1.0) <= 1e-15, "u = " << u);
    V2 P, D1, D2;
    ev.d2(u, P, D1, D2);
    BOOST_TEST(std::abs(P.norm() - 1.0) <= 1e-15, "u = " << u);
    BOOST_TEST(std::abs(curvature(D1, D2) - 1.0) <= 1e-15, "u = " << u);
  }
}

BOOST_AUTO_TEST_CASE(biquadratic_bezier_surface) {
  // Net from the notes, first index along u.
  const std::vector<std::vector<V3>> P{{{0, 0, 0}, {0, 1, 0}, {0, 2, -3}},
                                       {{1, 0, 6}, {1, 1, 0}, {1, 2, 0}},
                                       {{2, 0, 0}, {2, 1, 0}, {2, 2, 3}}};
  const BSplineSurface<3> s(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, P);
  SurfaceEvaluator<3> ev(s);
  const struct {
    double u, v;
    V3 S;
  } cases[] = {{0.25, 0.25, {0.5, 0.5, 1.171875}},
               {0.5, 0.5, {1, 1, 0.75}},
               {0.75, 0.75, {1.5, 1.5, 0.984375}},
               {0.25, 0.75, {0.5, 1.5, -0.703125}}};
  std::vector<double> uv;
  for (const auto& k : cases) {
    BOOST_TEST(near(s.point(k.u, k.v), k.S, kExact));
    BOOST_TEST(near(ev.point(k.u, k.v), k.S, kExact));
    uv.push_back(k.u);
    uv.push_back(k.v);
  }
  V3 batch[4];
  ev.points(uv.data(), 4, batch);
  for (int i = 0; i < 4; ++i) BOOST_TEST(near(batch[i], cases[i].S, kExact));
}
