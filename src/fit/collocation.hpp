#pragma once
// Square collocation systems of B-spline interpolation (The NURBS Book A9.1 generalised): row r states
// that the order[r]-th derivative of the spline at params[r] equals rhs.row(r). Shared by global,
// end-derivative, periodic interpolation and skinning (which interpolates homogeneous pole columns of
// any width, hence the dense rhs instead of typed points).
#include <Eigen/Core>
#include <vector>

namespace cg {

/// Solves for the poles (one row per pole, rhs.cols() coordinates) of a spline of degree p on the full
/// knot vector U. Non-periodic: U.size() - p - 1 poles, one per row. Periodic (U unwrapped, see
/// unwrap_periodic_knots): n = U.size() - 2p - 1 distinct poles, basis j acting on pole j mod n, and
/// parameters wrapped into [U[p], U[p+n]). Uses Eigen::SparseLU on the banded matrix.
/// Throws InvalidGeometry when the matrix is structurally or numerically singular (Schoenberg-Whitney
/// violated: a row's parameter outside the support of its pole's basis function).
Eigen::MatrixXd solve_collocation(int p, const std::vector<double>& U, bool periodic, const std::vector<double>& params,
                                  const std::vector<int>& order, const Eigen::MatrixXd& rhs);

}  // namespace cg
