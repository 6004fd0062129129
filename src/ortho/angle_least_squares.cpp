#include "src/ortho/angle_least_squares.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "src/core/error.hpp"

namespace cg::ortho {

namespace {

constexpr int kDim = 2;
using Sampler = EdgeAngleSampler<kDim>;

// Target directions d_k = eta_k t_k + side sqrt(1 - eta_k^2) n_k (n = left normal): the performance map
// fixes the cosine only, so the side of the curve the patch lies on is taken from the start net.
std::vector<Eigen::Vector2d> target_directions(const Sampler& s, const Eigen::Matrix3Xd& q) {
  Sampler::Vectors V;
  s.edge_vectors(q, V);
  double det = 0;
  for (int k = 0; k < s.size(); ++k) {
    const Eigen::Vector2d& t = s.unit_tangent(k);
    det += s.quadrature_weight(k) * (t.x() * V(1, k) - t.y() * V(0, k)) / std::max(V.col(k).norm(), 1e-300);
  }
  const double side = det >= 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> d;
  for (int k = 0; k < s.size(); ++k) {
    const Eigen::Vector2d& t = s.unit_tangent(k);
    const double e = s.target(k);
    d.push_back(e * t + side * std::sqrt(1 - e * e) * Eigen::Vector2d(-t.y(), t.x()));
  }
  return d;
}

// Weighted residuals r_k = sqrt(w_k) theta_k, theta_k = atan2(d_k x V_k, d_k . V_k) the signed angle
// from the target direction to x_v, and (optionally) their Jacobian for thread 1 `q` (3 x (m+1),
// flattened column-wise): d theta / d V = (a d_perp - b d) / |V|^2 with a = d . V, b = d_perp . V.
double residuals(const Sampler& s, const std::vector<Eigen::Vector2d>& dir, const std::vector<double>& weights,
                 const Eigen::Matrix3Xd& q, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
  Sampler::Vectors V;
  s.edge_vectors(q, V);
  const int n = s.size(), m = s.degree();
  r.resize(n);
  if (J) J->setZero(n, 3 * (m + 1));
  for (int k = 0; k < n; ++k) {
    const double sw = std::sqrt(weights[static_cast<std::size_t>(k)]);
    const Eigen::Vector2d& d = dir[static_cast<std::size_t>(k)];
    const Eigen::Vector2d dp(-d.y(), d.x());
    const double a = d.dot(V.col(k)), b = dp.dot(V.col(k)), len2 = a * a + b * b;
    r[k] = sw * std::atan2(b, a);
    if (!J || !(len2 > 1e-300)) continue;
    const Eigen::Vector2d g = (a * dp - b * d) / len2;
    const Eigen::Vector2d& x = s.edge_point(k);
    for (int i = 0; i <= m; ++i) {
      const double c = sw * s.bernstein(i, k);
      (*J)(k, 3 * i + 0) = c * g.x();
      (*J)(k, 3 * i + 1) = c * g.y();
      (*J)(k, 3 * i + 2) = -c * g.dot(x);
    }
  }
  return r.squaredNorm();
}

// The linearised problem: with the target directions fixed, the angle error at node k is ~ b_k / a_k
// (b = d_perp . V, a = d . V), and both are linear in thread 1. Minimise sum w_k (b_k / rho_k)^2 subject
// to sum w_k a_k / rho_k = sum w_k (the mean normal speed of the start kept; rho_k = |V_k| of the start)
// plus eps |q - q0|^2, which picks the solution nearest the start among the equivalent ones (thread 1
// + lambda thread 0 gives the same V). One symmetric KKT solve.
Eigen::Matrix3Xd linear_start(const Sampler& s, const std::vector<Eigen::Vector2d>& dir, const Eigen::Matrix3Xd& q0) {
  const int n = s.size(), m = s.degree(), N = 3 * (m + 1);
  Sampler::Vectors V;
  s.edge_vectors(q0, V);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, N);
  Eigen::RowVectorXd c = Eigen::RowVectorXd::Zero(N);
  double h = 0;
  for (int k = 0; k < n; ++k) {
    const double rho = std::max(V.col(k).norm(), 1e-300), w = s.quadrature_weight(k);
    const Eigen::Vector2d& d = dir[static_cast<std::size_t>(k)];
    const Eigen::Vector2d dp(-d.y(), d.x());
    const Eigen::Vector2d& x = s.edge_point(k);
    for (int i = 0; i <= m; ++i) {
      const double b = s.bernstein(i, k);
      A.block<1, 3>(k, 3 * i) << dp.x(), dp.y(), -dp.dot(x);
      A.block<1, 3>(k, 3 * i) *= std::sqrt(w) * b / rho;
      c.segment<3>(3 * i) += (w * b / rho) * Eigen::RowVector3d(d.x(), d.y(), -d.dot(x));
    }
    h += w;
  }
  const Eigen::MatrixXd AtA = A.transpose() * A;
  const double eps = 1e-10 * AtA.trace() / N;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N + 1, N + 1);
  K.topLeftCorner(N, N) = 2 * (AtA + eps * Eigen::MatrixXd::Identity(N, N));
  K.block(0, N, N, 1) = c.transpose();
  K.block(N, 0, 1, N) = c;
  Eigen::VectorXd rhs(N + 1);
  rhs.head(N) = 2 * eps * Eigen::Map<const Eigen::VectorXd>(q0.data(), N);
  rhs[N] = h;
  const Eigen::VectorXd sol = K.fullPivLu().solve(rhs);
  Eigen::Matrix3Xd q = Eigen::Map<const Eigen::Matrix3Xd>(sol.data(), 3, m + 1);
  if ((q.row(2).array() > 0).all() && q.allFinite()) return q;
  return q0;  // a weight went non-positive: Levenberg-Marquardt starts from the given net instead
}

// Levenberg-Marquardt on the weighted residuals; returns true when it stopped on the tolerance.
bool levenberg_marquardt(const Sampler& s, const std::vector<Eigen::Vector2d>& dir, const std::vector<double>& weights,
                         Eigen::Matrix3Xd& q,
                         const AngleLeastSquaresOptions& opt, int& iterations) {
  const int n = 3 * (s.degree() + 1);
  Eigen::VectorXd r, r_trial;
  Eigen::MatrixXd J;
  double f = residuals(s, dir, weights, q, r, &J);
  double mu = 1e-3;
  const double scale2 = q.squaredNorm() / n;  // eps I in units of the point size
  for (int it = 0; it < opt.max_iterations; ++it) {
    ++iterations;
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    Eigen::MatrixXd D = A.diagonal().asDiagonal();
    D.diagonal().array() += 1e-12 * A.diagonal().maxCoeff() + 1e-30 / scale2;
    const Eigen::VectorXd step = (A + mu * D).ldlt().solve(-g);
    Eigen::Matrix3Xd q_trial = q;
    for (int i = 0; i < q.cols(); ++i) q_trial.col(i) += step.segment<3>(3 * i);
    const bool valid = (q_trial.row(2).array() > 0).all() && q_trial.allFinite();
    const double f_trial = valid ? residuals(s, dir, weights, q_trial, r_trial, nullptr) : HUGE_VAL;
    if (f_trial < f) {
      const double decrease = (f - f_trial) / std::max(f, 1e-300);
      q = q_trial;
      f = residuals(s, dir, weights, q, r, &J);
      mu = std::max(mu / 3, 1e-12);
      if (decrease < opt.tolerance) return true;
    } else {
      mu *= 4;
      if (mu > 1e12) return true;  // no descent direction left at this resolution: a minimum
    }
  }
  return false;
}

}  // namespace

AngleLeastSquaresResult fit_edge_angles(const ContinuationNet<2>& start, const PerformanceMap& eta,
                                        const AngleLeastSquaresOptions& opt) {
  require(opt.max_iterations >= 1 && opt.lawson_rounds >= 0, "fit_edge_angles: bad iteration counts");
  start.surface();  // validates thread 1
  const Sampler s(start.curve, eta, opt.panels, opt.nodes_per_panel);
  AngleLeastSquaresResult out{start, {}};
  Sampler::Vectors V;
  s.edge_vectors(start.thread1, V);
  out.report.start_score = s.score(V);

  std::vector<double> w(static_cast<std::size_t>(s.size()));
  for (int k = 0; k < s.size(); ++k) w[static_cast<std::size_t>(k)] = s.quadrature_weight(k);
  Eigen::Matrix3Xd q = start.thread1;
  const std::vector<Eigen::Vector2d> dir = target_directions(s, q);
  if (opt.linear_start) q = linear_start(s, dir, q);
  out.report.converged = levenberg_marquardt(s, dir, w, q, opt, out.report.iterations);
  // Lawson's iteratively reweighted least squares towards the minimax solution: nodes with large
  // deviations gain weight (w_k <- w_k |theta_k| / sum).
  Eigen::Matrix3Xd best = q;
  double best_max = HUGE_VAL;
  Eigen::VectorXd r;
  const std::vector<double> unit(w.size(), 1.0);
  for (int round = 0; round <= opt.lawson_rounds; ++round) {
    residuals(s, dir, unit, q, r, nullptr);
    const double worst = r.cwiseAbs().maxCoeff();
    if (worst < best_max) {
      best_max = worst;
      best = q;
    }
    if (round == opt.lawson_rounds) break;
    double sum = 0;
    for (int k = 0; k < s.size(); ++k) {
      w[static_cast<std::size_t>(k)] *= std::abs(r[k]) + 1e-3 * worst;
      sum += w[static_cast<std::size_t>(k)];
    }
    for (double& x : w) x /= sum;
    out.report.converged = levenberg_marquardt(s, dir, w, q, opt, out.report.iterations);
  }
  out.net.thread1 = best;
  s.edge_vectors(best, V);
  out.report.score = s.score(V);
  return out;
}

}  // namespace cg::ortho
