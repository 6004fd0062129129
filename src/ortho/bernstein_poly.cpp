#include "src/ortho/bernstein_poly.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "src/core/basis.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/knots.hpp"
#include "src/core/rational.hpp"

namespace cg::ortho {

Eigen::VectorXd bernstein_value(const BernsteinPoly& p, double t) {
  const int n = bernstein_degree(p);
  require(n >= 0 && n <= 2 * kMaxDegree, "Bernstein polynomial degree out of range");
  double B[2 * kMaxDegree + 1];
  all_bernstein(n, t, B);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(p.rows());
  for (int i = 0; i <= n; ++i) v += B[i] * p.col(i);
  return v;
}

void bernstein_basis_d1(int degree, double t, double* B, double* dB) {
  require(degree >= 0 && degree <= 2 * kMaxDegree, "Bernstein polynomial degree out of range");
  if (degree == 0) {
    B[0] = 1;
    dB[0] = 0;
    return;
  }
  // d/dt B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}).
  all_bernstein(degree - 1, t, B);
  for (int i = 0; i <= degree; ++i)
    dB[i] = degree * ((i > 0 ? B[i - 1] : 0.0) - (i < degree ? B[i] : 0.0));
  all_bernstein(degree, t, B);
}

BernsteinPoly bernstein_product(const BernsteinPoly& a, const BernsteinPoly& b) {
  require(a.rows() == 1, "bernstein_product: the first factor must be scalar");
  const int p = bernstein_degree(a), q = bernstein_degree(b);
  BernsteinPoly c = BernsteinPoly::Zero(b.rows(), p + q + 1);
  for (int i = 0; i <= p; ++i)
    for (int j = 0; j <= q; ++j)
      c.col(i + j) += (binomial(p, i) * binomial(q, j) / binomial(p + q, i + j)) * a(0, i) * b.col(j);
  return c;
}

BernsteinPoly bernstein_derivative(const BernsteinPoly& p) {
  const int n = bernstein_degree(p);
  if (n == 0) return BernsteinPoly::Zero(p.rows(), 1);
  BernsteinPoly d(p.rows(), n);
  for (int i = 0; i < n; ++i) d.col(i) = n * (p.col(i + 1) - p.col(i));
  return d;
}

BernsteinPoly bernstein_elevate(const BernsteinPoly& p, int degree) {
  const int n = bernstein_degree(p);
  require(degree >= n, "bernstein_elevate: target degree below the current degree");
  // Multiplying by the constant 1 = sum_i B_i^t is elevation by t.
  return bernstein_product(BernsteinPoly::Ones(1, degree - n + 1), p);
}

BernsteinPoly bernstein_reduce(const BernsteinPoly& p, int degree, double* residual) {
  const int n = bernstein_degree(p);
  require(degree >= 0 && degree <= n, "bernstein_reduce: target degree outside [0, current degree]");
  // Elevation matrix E (n+1) x (degree+1): column j = coefficients of B_j^degree written with degree n.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n + 1, degree + 1);
  for (int j = 0; j <= degree; ++j) {
    BernsteinPoly unit = BernsteinPoly::Zero(1, degree + 1);
    unit(0, j) = 1;
    E.col(j) = bernstein_elevate(unit, n).transpose();
  }
  const Eigen::MatrixXd r = E.colPivHouseholderQr().solve(p.transpose()).transpose();
  if (residual) {
    const double scale = std::max(p.cwiseAbs().maxCoeff(), 1e-300);
    *residual = (r * E.transpose() - p).cwiseAbs().maxCoeff() / scale;
  }
  return r;
}

Eigen::VectorXd bernstein_to_power(const BernsteinPoly& p) {
  require(p.rows() == 1, "bernstein_to_power: scalar polynomial expected");
  const int n = bernstein_degree(p);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(n + 1);
  for (int k = 0; k <= n; ++k) {
    double s = 0;
    for (int i = 0; i <= k; ++i) s += (((k - i) % 2) ? -1.0 : 1.0) * binomial(k, i) * p(0, i);
    c[k] = binomial(n, k) * s;
  }
  return c;
}

BernsteinPoly power_to_bernstein(const Eigen::VectorXd& c, int degree) {
  require(c.size() >= 1 && degree >= c.size() - 1, "power_to_bernstein: degree below the polynomial's");
  BernsteinPoly b = BernsteinPoly::Zero(1, degree + 1);
  for (int i = 0; i <= degree; ++i)
    for (int k = 0; k <= std::min<int>(i, static_cast<int>(c.size()) - 1); ++k)
      b(0, i) += binomial(i, k) / binomial(degree, k) * c[k];
  return b;
}

Eigen::MatrixXd bernstein_collocation(const Eigen::VectorXd& t, int degree) {
  require(degree >= 0 && degree <= 2 * kMaxDegree, "Bernstein interpolation degree out of range");
  Eigen::MatrixXd A(t.size(), degree + 1);
  double B[2 * kMaxDegree + 1];
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    all_bernstein(degree, t[k], B);
    for (int i = 0; i <= degree; ++i) A(k, i) = B[i];
  }
  return A;
}

Eigen::VectorXd chebyshev_nodes01(int count) {
  Eigen::VectorXd t(count);
  if (count == 1) {
    t[0] = 0.5;
    return t;
  }
  // Chebyshev-Lobatto points (the ends included), increasing.
  for (int k = 0; k < count; ++k) t[k] = 0.5 - 0.5 * std::cos(kPi * k / (count - 1));
  return t;
}

BernsteinPoly bernstein_solve_collocation(const Eigen::MatrixXd& collocation, const Eigen::MatrixXd& values) {
  return collocation.partialPivLu().solve(values).transpose();
}

}  // namespace cg::ortho
