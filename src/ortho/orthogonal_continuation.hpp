#pragma once
// Exact orthogonal continuation of a plane rational Bezier curve (J. Lang, H.-P. Schroecker,
// "Edge-Orthogonal Patches through a Given Rational Bezier Curve", J. Geometry and Graphics 3(1), 1999).
//
// Given the curve k: x(u) = y_c(u) / Y0(u) of degree m (homogeneous y = (Y0 x, Y0), stored in the kernel's
// order (w x, w y, w)), the construction builds an integral patch Y(u, v) of degree (M, 1) with
// Y(u, 0) = y(u) and Y_v(u, 0) = z(u) (Lemma 3.1); its projection x(u, v) is a rational Bezier patch with
// x(u, 0) = k(u) and x_u . x_v = 0 along v = 0 (eq. 6).
//  - Sec. 3, eq. (13): z^(u) = D x_u(u) Y0(u)^2 with D the rotation by +90 deg in the plane that kills the
//    weight component. z^ is a polynomial of degree <= 2m - 2 (the degree-(2m-1) coefficient of
//    y_c' Y0 - y_c Y0' vanishes) and perpendicular to x_u.
//  - Sec. 4, eq. (16): z~(u) = D x_u(u) Y0(u) prod_sigma (u - u_sigma) over the s distinct zeros of Y0
//    (Lemma 4.1 makes it a polynomial); degree <= m + s - 1, <= m + s - 2 when deg Y0 = m (Lemma 4.2).
//  - eq. (14): z = L z^ - Q y with free polynomials L (degree l) and Q (degree <= M - m); the patch then
//    has degree M = max(m, deg z) = 2m + l - 2 for z^ with deg Q <= m + l - 2.
// Why it is orthogonal: x_v(u, 0) = (z_c Y0 - y_c z_w) / Y0^2 = L zeta_c / Y0 (the Q y term cancels), a
// multiple of D x_u. Since the patch is linear in v, every line u = const is the straight segment from
// x(u) along the normal n(u) = D x_u / |x_u|: x(u, v) = x(u) + n(u) v g(u) / (1 - v Q(u)) with
// g = L (zeta_c . n) / Y0 (derived in orthogonal_continuation.cpp). So L sets the length of the
// normal segments (g / (1 - Q) at v = 1) and Q their parametrisation in v.
#include <Eigen/Core>
#include <complex>
#include <vector>

#include "src/core/bezier_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/ortho/bernstein_poly.hpp"

namespace cg::ortho {

/// Which edge direction polynomial zeta the continuation uses.
enum class EdgeDirection {
  Squared,        ///< eq. (13): z^ = D x_u Y0^2, degree 2m - 2
  WeightReduced,  ///< eq. (16): z~ = D x_u Y0 prod (u - u_sigma), degree m + s - 2 (or m + s - 1)
};

/// The zeros of the weight polynomial Y0 (complex, with multiplicities) as used by eq. (15)-(16).
struct WeightZeros {
  int weight_degree = 0;                       ///< actual degree of Y0 (<= m)
  std::vector<std::complex<double>> zeros;     ///< distinct zeros u_sigma (cluster means)
  std::vector<int> multiplicities;             ///< nu_sigma, summing to weight_degree
  int distinct() const { return static_cast<int>(zeros.size()); }
};

/// An edge direction polynomial zeta (3 rows, kernel order; the weight row is zero) with its degree.
struct EdgeDirectionPoly {
  EdgeDirection kind = EdgeDirection::Squared;
  BernsteinPoly zeta;           ///< 3 x (degree + 1)
  int predicted_degree = 0;     ///< 2m - 2 (Sec. 3) or Lemma 4.2's bound
  /// Largest relative defect of the polynomial identity behind zeta: the vanishing leading coefficient
  /// of z^ (Sec. 3) or the divisibility of z^ prod (u - u_sigma) by Y0 (Sec. 4). ~1e-15 when exact.
  double identity_residual = 0;
  WeightZeros weight_zeros;     ///< filled for WeightReduced
};

/// eq. (13): z^ = D x_u Y0^2 of degree 2m - 2 (m >= 1).
EdgeDirectionPoly squared_edge_direction(const BezierCurve<2>& curve);

/// The zeros of Y0 (power-basis companion matrix; nearby eigenvalues of a multiple zero are merged and
/// the merge is accepted only if z~ below is then a polynomial to 1e-9).
/// eq. (16) / Lemma 4.2: z~ of degree m + s - 2 (deg Y0 = m) or m + s - 1 (deg Y0 < m). Falls back to
/// treating every zero as simple (then z~ is z^ / lead(Y0), s = deg Y0) when no merge is consistent.
EdgeDirectionPoly weight_reduced_edge_direction(const BezierCurve<2>& curve);

/// The free polynomials of eq. (14), scalar Bernstein polynomials on [0, 1] (one row each).
/// L must not vanish on [0, 1] (it scales the normal segments); Q < 1 on [0, 1] keeps the weights of
/// thread 1 positive (checked on its Bernstein coefficients).
struct ContinuationFactors {
  BernsteinPoly L = BernsteinPoly::Ones(1, 1);
  BernsteinPoly Q = BernsteinPoly::Zero(1, 1);
};

/// The rational Bezier patch of degree (M, 1) through the curve (Lemma 3.1 + eq. 14).
struct OrthogonalContinuation {
  BSplineSurface<2> patch;      ///< degree (M, 1) on [0, 1]^2, patch(u, 0) = curve(u)
  int degree = 0;               ///< M
  EdgeDirectionPoly direction;  ///< zeta
  ContinuationFactors factors;  ///< L, Q
  BezierCurve<2> curve;         ///< the input curve (degree m)

  /// Signed length g(u) of x_v(u, 0) along the left normal n(u) = D x_u / |x_u|.
  double edge_speed(double u) const;
  /// Distance from the edge of the thread-1 point at u (v = 1) along n(u): g / (1 - Q), signed.
  double thread_distance(double u) const;
  /// v at which the line u = const is at signed distance s from the edge: v = s / (g + s Q).
  double v_at_distance(double u, double s) const;
  /// Left unit normal n(u) = D x_u / |x_u|.
  Eigen::Vector2d edge_normal(double u) const;
};

/// Builds the continuation. Throws InvalidGeometry when L or Q have the wrong degree for the predicted
/// patch degree (deg Q > M - m is allowed only by raising M: the degree is max(m, deg zeta + l, m + q)),
/// when the patch degree exceeds kMaxDegree, or when a weight of thread 1 is not positive.
OrthogonalContinuation continue_orthogonally(const BezierCurve<2>& curve, const ContinuationFactors& factors,
                                             EdgeDirection kind = EdgeDirection::Squared);
/// As above with a precomputed edge direction (several continuations of one curve).
OrthogonalContinuation continue_orthogonally(const BezierCurve<2>& curve, const EdgeDirectionPoly& direction,
                                             const ContinuationFactors& factors);

/// Homogeneous Bernstein coefficients of a curve (3 x (m + 1), kernel order).
inline BernsteinPoly homogeneous_poly(const BezierCurve<2>& curve) { return curve.homogeneous_poles(); }

}  // namespace cg::ortho
