#include "src/fit/collocation.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/knots.hpp"

namespace cg {

Eigen::MatrixXd solve_collocation(int p, const std::vector<double>& U, bool periodic, const std::vector<double>& params,
                                  const std::vector<int>& order, const Eigen::MatrixXd& rhs) {
  const int num_basis = static_cast<int>(U.size()) - p - 1;
  const int n = periodic ? num_basis - p : num_basis;  // unknown poles
  require(n >= 1 && static_cast<int>(params.size()) == n && static_cast<int>(order.size()) == n && rhs.rows() == n,
          "collocation needs as many conditions as poles (" + std::to_string(n) + "), got " +
              std::to_string(params.size()));
  const double a = U[static_cast<std::size_t>(p)], b = U[static_cast<std::size_t>(num_basis)];
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(n * (p + 1)));
  double ders[(kMaxDegree + 1) * (kMaxDegree + 1)];
  for (int r = 0; r < n; ++r) {
    double t = params[static_cast<std::size_t>(r)];
    const int k = order[static_cast<std::size_t>(r)];
    require(k >= 0 && k <= p, "derivative order " + std::to_string(k) + " out of range [0, degree]");
    if (periodic) {
      t = a + std::fmod(t - a, b - a);
      if (t < a) t += b - a;
    } else {
      if (!(t >= a && t <= b)) {
        const ValueRangeText r = format_value_range(t, a, b);
        throw InvalidGeometry("interpolation parameter " + r.value + " outside the knot domain [" + r.lo + ", " + r.hi + "]");
      }
    }
    const int s = find_span(U.data(), num_basis - 1, p, t);
    ders_basis_funs(s, t, p, k, U.data(), ders);
    for (int j = 0; j <= p; ++j) {
      const double v = ders[k * (p + 1) + j];
      if (v != 0.0) triplets.emplace_back(r, (s - p + j) % n, v);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());  // periodic wrap-around duplicates are summed
  A.makeCompressed();
  // With ordered parameters, Schoenberg-Whitney means every pole's basis function (or derivative) is
  // non-zero at its own row's parameter: a non-zero diagonal.
  if (!periodic)
    for (int r = 0; r < n; ++r)
      if (A.coeff(r, r) == 0.0)
        throw InvalidGeometry("interpolation parameter " + format_number(params[static_cast<std::size_t>(r)]) +
                              " lies outside the support of basis function " + std::to_string(r) +
                              " (Schoenberg-Whitney condition violated)");
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success)
    throw InvalidGeometry(
        "interpolation system is singular: the parameters violate the Schoenberg-Whitney "
        "condition for these knots");
  Eigen::MatrixXd x = lu.solve(rhs);
  // A nearly singular system (parameters almost outside a basis support) shows as a large residual.
  const double scale = rhs.cwiseAbs().maxCoeff() + x.cwiseAbs().maxCoeff() * A.coeffs().cwiseAbs().maxCoeff();
  if (!x.allFinite() || (A * x - rhs).cwiseAbs().maxCoeff() > 1e-9 * scale)
    throw InvalidGeometry(
        "interpolation system is numerically singular: the parameters violate the "
        "Schoenberg-Whitney condition for these knots");
  return x;
}

}  // namespace cg
