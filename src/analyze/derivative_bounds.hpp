#pragma once
// Upper bounds of the derivatives of a (rational) Bézier piece over its whole interval, for
// a-posteriori error bounds (e.g. the verified offset fit): a polynomial in Bernstein form lies in the
// convex hull of its coefficients (The NURBS Book 1.3, P1.4), and the k-th derivative of a degree-p
// Bézier on an interval of length h has the coefficients p!/(p-k)! / h^k times the k-th differences of
// the poles (eq. 1.10 iterated). A rational piece C = A / w (A the homogeneous numerator) follows from
// Leibniz' rule A^(k) = sum_i C(k, i) w^(i) C^(k-i) solved for C^(k) (The NURBS Book 4.2, eq. 4.8):
//   sup|C^(k)| <= (sup|A^(k)| + sum_{i=1..k} C(k, i) sup|w^(i)| sup|C^(k-i)|) / min w.
namespace cg {

/// sup |C^(k)(u)| over the piece, k = 0..3 (rigorous up to rounding).
struct DerivativeBounds {
  double sup[4] = {0, 0, 0, 0};
};

/// Bounds for the degree-p piece with p+1 homogeneous poles (Dim+1 doubles each, positive weights)
/// on a parameter interval of length h.
template <int Dim>
DerivativeBounds bezier_derivative_bounds(const double* hpoles, int p, double h);

extern template DerivativeBounds bezier_derivative_bounds<1>(const double*, int, double);
extern template DerivativeBounds bezier_derivative_bounds<2>(const double*, int, double);
extern template DerivativeBounds bezier_derivative_bounds<3>(const double*, int, double);

}  // namespace cg
