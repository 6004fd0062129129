#pragma once
// A deterministic alternative to the Monte Carlo search of Lang & Schroecker 1999, Sec. 5 for plane
// curves: the angle error along the edge, integrated by the sampler's Gauss-Legendre rule, minimised over
// the homogeneous thread-1 points by Levenberg-Marquardt (Gauss-Newton with adaptive damping; Nocedal &
// Wright, Numerical Optimization, 10.3). Like the Monte Carlo method it keeps the degree (m, 1) of the
// net: no degree elevation.
//
// The residual is the signed angle theta_k from the target direction d_k = eta t + side sqrt(1 - eta^2) n
// to x_v (side: that of the start net), not cos - eta: the cosine is blind to the side of the tangent, and
// with eta != 0 a least-squares descent on it let x_v shrink through zero to the mirror direction (seen:
// local minima 56-107 deg off for eta = cos 60..80 deg). With V_k = Y0 x_v(u_k) = sum_i B_i(u_k)
// (q_i,c - x_k q_i,w) linear in thread 1 the Jacobian is exact: d theta_k / d q_i = B_i(u_k) g_k^T [I, -x_k],
// g_k = (a d_perp - b d) / (a^2 + b^2), a = d . V_k, b = d_perp . V_k.
// The objective is invariant under scaling thread 1 and under adding a multiple of thread 0 to it; the
// damping term mu (diag(J^T J) + eps I) keeps those directions out of the steps.
// Optionally (minimax = true) the weights are then reweighted by Lawson's rule (w_k <- w_k |r_k|, renormalised),
// which drives the least-squares solution towards the smallest MAXIMUM deviation, the figure the paper
// reports.
#include "src/ortho/edge_angles.hpp"

namespace cg::ortho {

struct AngleLeastSquaresOptions {
  int max_iterations = 200;       ///< Levenberg-Marquardt iterations per (re)weighting
  double tolerance = 1e-14;       ///< stop when the relative decrease of the objective is below this
  /// Start from the solution of the linearised problem (see angle_least_squares.cpp) instead of the given
  /// net; the given net then only fixes the side and the mean length of x_v.
  bool linear_start = true;
  int lawson_rounds = 0;          ///< minimax reweighting rounds after the first solve (0: plain least squares)
  int panels = 16, nodes_per_panel = 8;  ///< quadrature nodes (the minimax works on these nodes)
};

struct AngleLeastSquaresReport {
  int iterations = 0;             ///< accepted + rejected LM steps, all rounds
  double start_score = 0, score = 0;  ///< score (18) (squared cosine deviation, as the Monte Carlo method)
  bool converged = false;         ///< the last round stopped on the tolerance, not the iteration limit
};

struct AngleLeastSquaresResult {
  ContinuationNet<2> net;
  AngleLeastSquaresReport report;
};

/// Polishes thread 1 of `start` (any start: the translated net, a Monte Carlo result). Throws
/// InvalidGeometry for a start net with non-positive thread-1 weights; steps that would make a weight
/// non-positive are rejected.
AngleLeastSquaresResult fit_edge_angles(const ContinuationNet<2>& start, const PerformanceMap& eta,
                                        const AngleLeastSquaresOptions& options = {});

}  // namespace cg::ortho
