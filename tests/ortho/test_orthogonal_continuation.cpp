// Exact orthogonal continuation (Lang & Schroecker 1999, Sec. 3-4): for random plane rational Bezier
// curves of degree 2..5 (weights in [0.2, 5]) and random free polynomials L, Q of eq. (14), the patch
//  - contains the curve as its edge v = 0 (1e-13 of the curve's size: de Casteljau vs the surface
//    evaluator, a few ulps of the pole scale),
//  - meets it orthogonally: |cos(x_u, x_v)| < 1e-12 along the edge, evaluated by our surface derivatives
//    and independently by OCCT's Geom_BSplineSurface::D1 on the same poles (both are rounding-level
//    computations of an identity, ~1e-15 seen),
//  - has the predicted degree: 2m + l - 2 (Sec. 3) and Lemma 4.2's m + s - 2 / m + s - 1 (Sec. 4) for
//    weight polynomials with s distinct zeros of chosen multiplicities,
//  - has straight, normal lines u = const parametrised as x + n v g / (1 - v Q) (the closed form the
//    grid uses), checked against the surface to 1e-12 of the size.
#define BOOST_TEST_MODULE orthogonal_continuation
#include <boost/test/unit_test.hpp>

#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <complex>

#include "adaptors/occt_convert.hpp"
#include "src/core/error.hpp"
#include "src/ortho/orthogonal_continuation.hpp"
#include "support/random_geometry.hpp"

using namespace cg;
using namespace cg::ortho;

namespace {

BezierCurve<2> random_curve(test::Rng& r, int m, bool rational = true) {
  std::vector<Eigen::Vector2d> P;
  std::vector<double> w;
  for (int i = 0; i <= m; ++i) {
    // A wavy but regular control polygon: x increasing, random y.
    P.emplace_back(i + r.uniform(-0.3, 0.3), r.uniform(-1.5, 1.5));
    w.push_back(rational ? r.uniform(0.2, 5.0) : 1.0);
  }
  return BezierCurve<2>(P, w);
}

BernsteinPoly random_poly(test::Rng& r, int degree, double lo, double hi) {
  BernsteinPoly p(1, degree + 1);
  for (int i = 0; i <= degree; ++i) p(0, i) = r.uniform(lo, hi);
  return p;
}

double size_of(const BezierCurve<2>& c) {
  double s = 0;
  for (int i = 0; i <= c.degree(); ++i) s = std::max(s, c.pole(i).norm());
  return s;
}

// |cos| of the angle between x_u and x_v at (u, 0), ours and OCCT's; the edge point error.
struct EdgeCheck {
  double cos_ours = 0, cos_occt = 0, edge_error = 0, min_xv = 1e300;
};

EdgeCheck check_edge(const OrthogonalContinuation& c, int samples) {
  // The same patch in 3D (z = 0) for OCCT.
  const auto& s = c.patch;
  Eigen::Matrix<double, 4, Eigen::Dynamic> h = Eigen::Matrix<double, 4, Eigen::Dynamic>::Zero(4, s.homogeneous_poles().cols());
  h.topRows(2) = s.homogeneous_poles().topRows(2);
  h.row(3) = s.homogeneous_poles().row(2);
  const auto s3 = BSplineSurface<3>::from_homogeneous(s.degree_u(), s.degree_v(), s.knots_u(), s.knots_v(),
                                                      s.num_poles_u(), s.num_poles_v(), h);
  const Handle(Geom_BSplineSurface) occ = occt::to_occt(s3);
  EdgeCheck e;
  for (int k = 0; k <= samples; ++k) {
    const double u = static_cast<double>(k) / samples;
    Eigen::Vector2d d[4];
    s.derivatives(u, 0.0, 1, d);  // d[0] = S, d[1] = S_v, d[2] = S_u
    e.cos_ours = std::max(e.cos_ours, std::abs(d[2].dot(d[1])) / (d[2].norm() * d[1].norm()));
    e.edge_error = std::max(e.edge_error, (d[0] - c.curve.point(u)).norm());
    e.min_xv = std::min(e.min_xv, d[1].norm() / d[2].norm());
    gp_Pnt P;
    gp_Vec Du, Dv;
    occ->D1(u, 0.0, P, Du, Dv);
    e.cos_occt = std::max(e.cos_occt, std::abs(Du.Dot(Dv)) / (Du.Magnitude() * Dv.Magnitude()));
  }
  return e;
}

// Straight normal lines: x(u, v) = x(u) + n(u) v g / (1 - v Q) and v_at_distance inverts it.
double check_normal_lines(const OrthogonalContinuation& c) {
  double err = 0;
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
    for (double v : {0.25, 0.5, 1.0}) {
      const double Q = bernstein_value(c.factors.Q, u)[0];
      const double s = v * c.edge_speed(u) / (1 - v * Q);
      const Eigen::Vector2d expect = c.curve.point(u) + s * c.edge_normal(u);
      err = std::max(err, (c.patch.point(u, v) - expect).norm());
      err = std::max(err, std::abs(c.v_at_distance(u, s) - v) * std::abs(s));
    }
  return err;
}

}  // namespace

BOOST_AUTO_TEST_CASE(squared_direction_random_curves) {
  test::Rng r(20240612);
  int cases = 0;
  for (int m = 2; m <= 5; ++m)
    for (int trial = 0; trial < 25; ++trial) {
      const BezierCurve<2> k = random_curve(r, m, trial % 5 != 0);
      const int l = trial % 3;
      const int q = r.integer(0, m + l - 2);
      ContinuationFactors f;
      f.L = random_poly(r, l, 0.3, 2.0);
      f.Q = random_poly(r, q, -0.5, 0.5);
      const OrthogonalContinuation c = continue_orthogonally(k, f, EdgeDirection::Squared);
      BOOST_TEST_CONTEXT("m " << m << " l " << l << " q " << q << " trial " << trial) {
        BOOST_TEST(c.direction.predicted_degree == 2 * m - 2);
        BOOST_TEST(bernstein_degree(c.direction.zeta) == 2 * m - 2);
        // The dropped coefficient of degree 2m - 1 really vanishes (Sec. 3, after eq. 13).
        BOOST_TEST(c.direction.identity_residual < 1e-13);
        BOOST_TEST(c.degree == 2 * m + l - 2);
        BOOST_TEST(c.patch.degree_u() == 2 * m + l - 2);
        BOOST_TEST(c.patch.degree_v() == 1);
        const EdgeCheck e = check_edge(c, 200);
        BOOST_TEST(e.cos_ours < 1e-12);
        BOOST_TEST(e.cos_occt < 1e-12);
        BOOST_TEST(e.edge_error < 1e-13 * size_of(k));
        BOOST_TEST(e.min_xv > 1e-6);  // a genuine continuation, not the trivial x_v = 0
        BOOST_TEST(check_normal_lines(c) < 1e-12 * size_of(k));
      }
      ++cases;
    }
  BOOST_TEST(cases == 100);
}

BOOST_AUTO_TEST_CASE(lowest_degree_nontrivial_solution) {
  // "The non-trivial solution of the lowest possible degree 2m - 2 is given by L = lambda" (Sec. 3):
  // for m = 2 this is no elevation at all.
  test::Rng r(7);
  const BezierCurve<2> k = random_curve(r, 2);
  const OrthogonalContinuation c = continue_orthogonally(k, ContinuationFactors{});
  BOOST_TEST(c.degree == 2);
  BOOST_TEST(check_edge(c, 100).cos_ours < 1e-12);
}

namespace {

// A degree-m curve whose weight polynomial is c prod (u - z)^nu, zeros with negative real part so that
// every power (hence Bernstein) coefficient is positive: positive weights.
BezierCurve<2> curve_with_weight_zeros(test::Rng& r, int m, const std::vector<std::complex<double>>& zeros,
                                       const std::vector<int>& mult) {
  std::vector<std::complex<double>> c{1.0};
  for (std::size_t k = 0; k < zeros.size(); ++k)
    for (int j = 0; j < mult[k]; ++j) {
      std::vector<std::complex<double>> next(c.size() + 1, 0.0);
      for (std::size_t i = 0; i < c.size(); ++i) {
        next[i + 1] += c[i];
        next[i] -= zeros[k] * c[i];
      }
      c = next;
    }
  Eigen::VectorXd power(static_cast<Eigen::Index>(c.size()));
  for (std::size_t i = 0; i < c.size(); ++i) power[static_cast<Eigen::Index>(i)] = c[i].real();
  const BernsteinPoly w = power_to_bernstein(power, m);
  std::vector<Eigen::Vector2d> P;
  std::vector<double> wv;
  for (int i = 0; i <= m; ++i) {
    P.emplace_back(i + r.uniform(-0.3, 0.3), r.uniform(-1.5, 1.5));
    wv.push_back(w(0, i) / w(0, 0));
  }
  return BezierCurve<2>(P, wv);
}

}  // namespace

BOOST_AUTO_TEST_CASE(weight_reduced_direction_lemma_4_2) {
  test::Rng r(99);
  struct Case {
    int m;
    std::vector<std::complex<double>> zeros;
    std::vector<int> mult;
  };
  using C = std::complex<double>;
  const std::vector<Case> cases = {
      {2, {C(-1.5, 0)}, {2}},                              // geometric weights: s = 1
      {3, {C(-0.8, 0)}, {3}},                              // s = 1, m = 3
      {4, {C(-2.0, 0)}, {4}},                              // s = 1, m = 4
      {5, {C(-1.2, 0)}, {5}},                              // s = 1, m = 5 (ring radius ~eps^(1/5))
      {3, {C(-0.5, 0), C(-3.0, 0)}, {2, 1}},               // s = 2
      {4, {C(-0.5, 0), C(-2.5, 0)}, {2, 2}},               // s = 2
      {4, {C(-0.7, 0.9), C(-0.7, -0.9)}, {2, 2}},          // a double complex pair: s = 2
      {5, {C(-1.0, 0.5), C(-1.0, -0.5), C(-0.4, 0)}, {2, 2, 1}},  // s = 3
      {3, {C(-0.6, 0)}, {2}},                              // deg Y0 = 2 < m: bound m + s - 1
      {4, {C(-0.9, 0), C(-2.0, 0)}, {1, 1}},               // deg Y0 = 2 < m, simple zeros
  };
  for (const Case& t : cases) {
    int d = 0;
    for (int v : t.mult) d += v;
    const int s = static_cast<int>(t.zeros.size());
    const int predicted = d == t.m ? t.m + s - 2 : t.m + s - 1;
    for (int trial = 0; trial < 3; ++trial) {
      const BezierCurve<2> k = curve_with_weight_zeros(r, t.m, t.zeros, t.mult);
      const EdgeDirectionPoly z = weight_reduced_edge_direction(k);
      BOOST_TEST_CONTEXT("m " << t.m << " s " << s << " deg Y0 " << d) {
        BOOST_TEST(z.weight_zeros.weight_degree == d);
        BOOST_TEST(z.weight_zeros.distinct() == s);
        BOOST_TEST(z.predicted_degree == predicted);
        BOOST_TEST(bernstein_degree(z.zeta) == predicted);
        BOOST_TEST(z.identity_residual < 1e-9);
        BOOST_TEST(predicted < 2 * t.m - 2);  // really lower than Sec. 3
        // L = 1, Q = 0: the patch degree is max(m, deg z~) (Lemma 3.1), often m: no elevation.
        const OrthogonalContinuation c = continue_orthogonally(k, z, ContinuationFactors{});
        BOOST_TEST(c.degree == std::max(t.m, predicted));
        const EdgeCheck e = check_edge(c, 200);
        BOOST_TEST(e.cos_ours < 1e-12);
        BOOST_TEST(e.cos_occt < 1e-12);
        BOOST_TEST(e.min_xv > 1e-6);
        BOOST_TEST(check_normal_lines(c) < 1e-12 * size_of(k));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(integral_curves_need_no_elevation) {
  // Y0 = 1: s = 0, z~ = D x_u of degree m - 1; the "2-parameter variety of integral orthogonal
  // continuations without degree elevation" of Sec. 4 (L constant, Q = 0 or constant).
  test::Rng r(3);
  for (int m = 2; m <= 5; ++m) {
    const BezierCurve<2> k = random_curve(r, m, false);
    const EdgeDirectionPoly z = weight_reduced_edge_direction(k);
    BOOST_TEST(z.weight_zeros.distinct() == 0);
    BOOST_TEST(z.predicted_degree == m - 1);
    ContinuationFactors f;
    f.L(0, 0) = 0.7;
    f.Q(0, 0) = 0.2;
    const OrthogonalContinuation c = continue_orthogonally(k, z, f);
    BOOST_TEST(c.degree == m);
    BOOST_TEST(check_edge(c, 100).cos_ours < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(general_weights_fall_back_to_simple_zeros) {
  // Random weights: m distinct zeros, Lemma 4.2 gives m + m - 2 = 2m - 2, the same degree as Sec. 3.
  test::Rng r(11);
  for (int m = 2; m <= 5; ++m) {
    const BezierCurve<2> k = random_curve(r, m);
    const EdgeDirectionPoly z = weight_reduced_edge_direction(k);
    BOOST_TEST(z.weight_zeros.distinct() == z.weight_zeros.weight_degree);
    BOOST_TEST(bernstein_degree(z.zeta) <= 2 * m - 2);
    BOOST_TEST(check_edge(continue_orthogonally(k, z, ContinuationFactors{}), 100).cos_ours < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(invalid_factors_are_rejected) {
  test::Rng r(5);
  const BezierCurve<2> k = random_curve(r, 3);
  ContinuationFactors f;
  f.Q(0, 0) = 1.5;  // thread-1 weights Y0 (1 - Q) < 0
  BOOST_CHECK_THROW(continue_orthogonally(k, f), InvalidGeometry);
  f.Q = BernsteinPoly::Zero(2, 1);
  BOOST_CHECK_THROW(continue_orthogonally(k, f), InvalidGeometry);
  f = ContinuationFactors{};
  f.L = BernsteinPoly::Ones(1, 30);  // degree 2m - 2 + 29 > kMaxDegree
  BOOST_CHECK_THROW(continue_orthogonally(k, f), InvalidGeometry);
}
