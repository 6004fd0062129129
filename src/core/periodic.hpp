#pragma once
// Consistency check of unwrapped periodic B-spline data (shared by curves and surfaces).
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace cg {

/// Unwrapped periodic data of degree p with `count` poles along one direction: the last p poles
/// repeat the first p (pole_distance(i, count - p + i) ~ 0) and knots continue by the period.
template <class PoleDistance>
void check_unwrapped_periodic(const std::vector<double>& U, int p, Eigen::Index count, PoleDistance pole_distance,
                              double scale, const char* what) {
  const Eigen::Index n = count - p;  // distinct poles per period
  require(n >= 1, std::string("periodic ") + what + " needs more poles than its degree");
  const double T = U[static_cast<std::size_t>(count)] - U[static_cast<std::size_t>(p)];
  const double tol = 1e-12 * (1.0 + scale);
  for (int i = 0; i < p; ++i)
    require(pole_distance(i, n + i) <= tol, std::string("periodic ") + what + ": the last degree poles must repeat the first ones");
  for (std::size_t k = 0; k + static_cast<std::size_t>(n) < U.size(); ++k)
    require(std::abs(U[k + static_cast<std::size_t>(n)] - U[k] - T) <= 1e-12 * T,
            std::string("periodic ") + what + ": knots must continue by the period");
}

}  // namespace cg
