#pragma once
// Derivatives of a rational curve/surface from the derivatives of its homogeneous form.
#include <Eigen/Core>

namespace cg {

inline double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

/// Cartesian derivatives C^(k), k = 0..n, from homogeneous derivatives Cw^(k) = (A^(k), w^(k))
/// (The NURBS Book A4.2). `hom` and `out` have n+1 entries.
template <int Dim>
void rational_curve_derivatives(const Eigen::Matrix<double, Dim + 1, 1>* hom, int n,
                                Eigen::Matrix<double, Dim, 1>* out) {
  const double w0 = hom[0][Dim];
  for (int k = 0; k <= n; ++k) {
    Eigen::Matrix<double, Dim, 1> v = hom[k].template head<Dim>();
    for (int i = 1; i <= k; ++i) v -= binomial(k, i) * hom[i][Dim] * out[k - i];
    out[k] = v / w0;
  }
}

}  // namespace cg
