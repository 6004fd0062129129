#include "src/grid/wall_patches.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/blade/section.hpp"
#include "src/core/basis.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/modify/bezier_decomposition.hpp"
#include "src/ortho/edge_angles.hpp"
#include "src/core/format.hpp"

namespace cg::grid {

namespace {

using ortho::BernsteinPoly;
using ortho::bernstein_value;

constexpr int kLDegree = 2;     // degree l of L: one free coefficient between the two fixed ends
constexpr int kFitSamples = 17;  // samples per segment for the thickness fit

// gamma(t) = (zeta_c . n) / Y0: the edge speed per unit L (g = L gamma), on the left normal n.
double edge_speed_per_L(const ortho::OrthogonalContinuation& c, double t) {
  return c.edge_speed(t) / bernstein_value(c.factors.L, t)[0];
}

// Fits L (degree kLDegree) and Q (degree M - m) of eq. (14) to h = L gamma / (1 - Q) = target (signed).
ortho::ContinuationFactors fit_factors(const BezierCurve<2>& seg, const ortho::EdgeDirectionPoly& dir, double target,
                                       double& fit_error) {
  const int m = seg.degree(), dz = ortho::bernstein_degree(dir.zeta);
  const int M = std::max(m, dz + kLDegree), q = M - m;
  // gamma at the samples, from a probe continuation with L = 1, Q = 0.
  const ortho::OrthogonalContinuation probe = ortho::continue_orthogonally(seg, dir, ortho::ContinuationFactors{});
  std::vector<double> t(kFitSamples), gamma(kFitSamples);
  for (int j = 0; j < kFitSamples; ++j) {
    t[static_cast<std::size_t>(j)] = static_cast<double>(j) / (kFitSamples - 1);
    gamma[static_cast<std::size_t>(j)] = edge_speed_per_L(probe, t[static_cast<std::size_t>(j)]);
    require(gamma[static_cast<std::size_t>(j)] != 0, "wall patches: zero edge speed (a cusp in the section)");
  }
  ortho::ContinuationFactors f;
  f.L = BernsteinPoly::Zero(1, kLDegree + 1);
  f.Q = BernsteinPoly::Zero(1, q + 1);
  f.L(0, 0) = target / gamma.front();
  f.L(0, kLDegree) = target / gamma.back();
  // Unknowns: interior coefficients of L (kLDegree - 1) and of Q (q - 1 when q >= 2).
  const int nl = kLDegree - 1, nq = std::max(0, q - 1);
  Eigen::MatrixXd A(kFitSamples, nl + nq);
  Eigen::VectorXd rhs(kFitSamples);
  double BL[kMaxDegree + 1], BQ[kMaxDegree + 1];
  for (int j = 0; j < kFitSamples; ++j) {
    all_bernstein(kLDegree, t[static_cast<std::size_t>(j)], BL);
    all_bernstein(q, t[static_cast<std::size_t>(j)], BQ);
    const double g = gamma[static_cast<std::size_t>(j)];
    // L gamma + target Q = target
    for (int i = 1; i < kLDegree; ++i) A(j, i - 1) = BL[i] * g;
    for (int i = 1; i < q; ++i) A(j, nl + i - 1) = target * BQ[i];
    rhs[j] = target - g * (BL[0] * f.L(0, 0) + BL[kLDegree] * f.L(0, kLDegree));
  }
  if (A.cols() > 0) {
    const Eigen::VectorXd x = A.colPivHouseholderQr().solve(rhs);
    for (int i = 1; i < kLDegree; ++i) f.L(0, i) = x[i - 1];
    for (int i = 1; i < q; ++i) f.Q(0, i) = x[nl + i - 1];
    if (f.Q.maxCoeff() > 0.5) {  // keep thread-1 weights safely positive: drop Q, refit L alone
      f.Q.setZero();
      const Eigen::VectorXd xl = A.leftCols(nl).colPivHouseholderQr().solve(rhs);
      for (int i = 1; i < kLDegree; ++i) f.L(0, i) = xl[i - 1];
    }
  }
  for (int j = 0; j < kFitSamples; ++j) {
    const double h = bernstein_value(f.L, t[static_cast<std::size_t>(j)])[0] * gamma[static_cast<std::size_t>(j)] /
                     (1 - bernstein_value(f.Q, t[static_cast<std::size_t>(j)])[0]);
    fit_error = std::max(fit_error, std::abs(h / target - 1));
  }
  return f;
}

}  // namespace

WallPatches::WallPatches(const BSplineCurve<2>& curve, double thickness) : curve_(curve), thickness_(thickness) {
  require(thickness > 0 && std::isfinite(thickness), "wall patches: the thickness must be positive");
  require(curve.is_closed(1e-9 * (1 + curve.homogeneous_poles().cwiseAbs().maxCoeff())),
          "wall patches: the section curve must be closed");
  // Outer side: a clockwise curve (negative enclosed area) has its outside on the left.
  side_ = blade::section_properties(curve).area < 0 ? 1.0 : -1.0;
  const BezierDecomposition<2> d = decompose_to_bezier(curve);
  breaks_ = d.breaks;
  const int n = static_cast<int>(d.segments.size());
  // Joints must be tangent-continuous, or the normal lines of neighbouring patches differ.
  for (int k = 0; k < n; ++k) {
    const auto& a = d.segments[static_cast<std::size_t>(k)];
    const auto& b = d.segments[static_cast<std::size_t>((k + 1) % n)];
    const Eigen::Vector2d ta = a.derivatives(1.0, 1)[1].normalized(), tb = b.derivatives(0.0, 1)[1].normalized();
    if ((ta - tb).norm() > 1e-7)
      throw InvalidGeometry("wall patches: the section curve has a corner at parameter " +
                            format_number(d.breaks[static_cast<std::size_t>(k) + 1]) +
                            " (tangents differ by " + format_number(std::asin(std::min(1.0, (ta - tb).norm() / 2)) * 360 / kPi) +
                            " deg); an orthogonal O-grid needs a tangent-continuous section");
  }
  std::vector<ortho::ContinuationFactors> factors;
  std::vector<ortho::EdgeDirectionPoly> dirs;
  for (const auto& seg : d.segments) {
    dirs.push_back(ortho::weight_reduced_edge_direction(seg));
    factors.push_back(fit_factors(seg, dirs.back(), side_ * thickness, fit_error_));
  }
  // One common factor so that every patch reaches the thickness (h(u) >= thickness, v <= 1 for the nodes).
  double min_ratio = HUGE_VAL;
  for (int k = 0; k < n; ++k) {
    const auto c = ortho::continue_orthogonally(d.segments[static_cast<std::size_t>(k)], dirs[static_cast<std::size_t>(k)],
                                                factors[static_cast<std::size_t>(k)]);
    for (int j = 0; j <= 4 * kFitSamples; ++j) {
      const double h = side_ * c.thread_distance(static_cast<double>(j) / (4 * kFitSamples));
      min_ratio = std::min(min_ratio, h / thickness);
    }
  }
  require(min_ratio > 0, "wall patches: a fitted patch turns to the inner side of the section");
  const double scale = min_ratio < 1 ? (1 + 1e-9) / min_ratio : 1.0;
  for (int k = 0; k < n; ++k) {
    factors[static_cast<std::size_t>(k)].L *= scale;
    patches_.push_back(ortho::continue_orthogonally(d.segments[static_cast<std::size_t>(k)], dirs[static_cast<std::size_t>(k)],
                                                    factors[static_cast<std::size_t>(k)]));
  }
}

std::pair<int, double> WallPatches::locate(double u) const {
  const double a = breaks_.front(), b = breaks_.back(), T = b - a;
  u = a + std::fmod(std::fmod(u - a, T) + T, T);
  auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
  int k = static_cast<int>(it - breaks_.begin()) - 1;
  k = std::clamp(k, 0, size() - 1);
  const double lo = breaks_[static_cast<std::size_t>(k)], hi = breaks_[static_cast<std::size_t>(k) + 1];
  return {k, std::clamp((u - lo) / (hi - lo), 0.0, 1.0)};
}

Eigen::Vector2d WallPatches::point(double u, double s) const {
  const auto [k, t] = locate(u);
  const ortho::OrthogonalContinuation& c = patch(k);
  const double v = c.v_at_distance(t, side_ * s);
  return c.patch.point(t, std::clamp(v, 0.0, 1.0));
}

Eigen::Vector2d WallPatches::outer_normal(double u) const {
  const auto [k, t] = locate(u);
  return side_ * patch(k).edge_normal(t);
}

int WallPatches::max_degree() const {
  int d = 0;
  for (const auto& p : patches_) d = std::max(d, p.degree);
  return d;
}

double WallPatches::max_wall_angle_deviation_deg(int samples_per_patch) const {
  double worst = 0;
  for (const auto& p : patches_)
    worst = std::max(worst, ortho::measure_edge_angles(p.patch, ortho::orthogonal_map, samples_per_patch).max_deviation_deg);
  return worst;
}

}  // namespace cg::grid
