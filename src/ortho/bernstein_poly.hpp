#pragma once
// Polynomial vectors in Bernstein form on [0, 1], the algebra of the edge-orthogonal constructions
// (Lang & Schroecker 1999, Sec. 3-4): products (eq. 13, 14), derivatives, degree elevation, the exact
// degree reduction of a polynomial whose leading power coefficient vanishes, interpolation at
// Chebyshev nodes and conversion to the power basis (for the zeros of the weight polynomial).
// Column i holds the coefficient of B_i^n(u) = C(n, i) u^i (1 - u)^(n - i); one row per component.
// Construction-time helpers: they allocate (Eigen dynamic matrices) and are not meant for inner loops.
#include <Eigen/Core>

#include "src/core/knots.hpp"

namespace cg::ortho {

using BernsteinPoly = Eigen::MatrixXd;

inline int bernstein_degree(const BernsteinPoly& p) { return static_cast<int>(p.cols()) - 1; }

/// Value at t (all_bernstein, The NURBS Book A1.3). Any t (extrapolates outside [0, 1]).
Eigen::VectorXd bernstein_value(const BernsteinPoly& p, double t);
/// Value and first derivative at t of a polynomial with R rows, without heap allocation.
template <int R>
void bernstein_value_d1(const BernsteinPoly& p, double t, Eigen::Matrix<double, R, 1>& value,
                        Eigen::Matrix<double, R, 1>& derivative);

/// a * b for a scalar polynomial a (one row) and a polynomial vector b: degree deg a + deg b,
/// c_k = sum_{i+j=k} C(p,i) C(q,j) / C(p+q,k) a_i b_j (Farin, Curves and Surfaces for CAGD, 5.x).
BernsteinPoly bernstein_product(const BernsteinPoly& a, const BernsteinPoly& b);

/// Derivative d/dt: degree n - 1, coefficients n (b_{i+1} - b_i). A constant gives the zero
/// polynomial of degree 0.
BernsteinPoly bernstein_derivative(const BernsteinPoly& p);

/// The same polynomial written with degree `degree` >= its current degree (repeated elevation).
BernsteinPoly bernstein_elevate(const BernsteinPoly& p, int degree);

/// The same polynomial with `degree` < current degree, when it has that lower degree: the least-squares
/// inverse of elevation (exact for a consistent system). `residual` (optional) receives the largest
/// coefficient difference between p and the re-elevated result, relative to the largest coefficient
/// of p: ~1e-16 when p really has the lower degree.
BernsteinPoly bernstein_reduce(const BernsteinPoly& p, int degree, double* residual = nullptr);

/// Bernstein coefficients (degree `degree` >= c.size() - 1) of sum_k c_k t^k:
/// b_i = sum_{k<=i} C(i, k) / C(n, k) c_k.
BernsteinPoly power_to_bernstein(const Eigen::VectorXd& c, int degree);

/// Power-basis coefficients c_k (p(t) = sum c_k t^k) of a scalar polynomial (one row).
Eigen::VectorXd bernstein_to_power(const BernsteinPoly& p);

/// The polynomial vector of degree `degree` whose values at degree + 1 Chebyshev nodes of [0, 1] are
/// f(t) (rows of f's result = components). Well conditioned for the low degrees used here.
template <class F>
BernsteinPoly bernstein_interpolate(int degree, int rows, F&& f);

// --- implementation of the templates ---
void bernstein_basis_d1(int degree, double t, double* B, double* dB);  // B_i^n(t), d/dt B_i^n(t)

template <int R>
void bernstein_value_d1(const BernsteinPoly& p, double t, Eigen::Matrix<double, R, 1>& value,
                        Eigen::Matrix<double, R, 1>& derivative) {
  const int n = bernstein_degree(p);
  double B[2 * kMaxDegree + 1], dB[2 * kMaxDegree + 1];
  bernstein_basis_d1(n, t, B, dB);
  value.setZero();
  derivative.setZero();
  for (int i = 0; i <= n; ++i) {
    value += B[i] * p.col(i).template head<R>();
    derivative += dB[i] * p.col(i).template head<R>();
  }
}

Eigen::MatrixXd bernstein_collocation(const Eigen::VectorXd& t, int degree);
Eigen::VectorXd chebyshev_nodes01(int count);
BernsteinPoly bernstein_solve_collocation(const Eigen::MatrixXd& collocation, const Eigen::MatrixXd& values);

template <class F>
BernsteinPoly bernstein_interpolate(int degree, int rows, F&& f) {
  const Eigen::VectorXd t = chebyshev_nodes01(degree + 1);
  Eigen::MatrixXd values(degree + 1, rows);
  for (int k = 0; k <= degree; ++k) values.row(k) = f(t[k]).transpose();
  return bernstein_solve_collocation(bernstein_collocation(t, degree), values);
}

}  // namespace cg::ortho
