#include "src/blade/curve_integral.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"

namespace cg::blade::detail {

// 8-point Gauss-Legendre nodes/weights on [-1, 1] (Abramowitz & Stegun 25.4.30).
const double kGaussLegendre8Nodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                        -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                        0.7966664774136267,  0.9602898564975363};
const double kGaussLegendre8Weights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                          0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                          0.2223810344533745, 0.1012285362903763};

namespace {

constexpr int kCellsPerSpan = 4;
const double* const kNodes = kGaussLegendre8Nodes;
const double* const kWeights = kGaussLegendre8Weights;

}  // namespace

double CurveIntegral::integrand(const BSplineCurve<2>& curve, double u) const {
  Eigen::Vector2d d[2];
  curve.derivatives(u, 1, d);
  const double speed = d[1].norm();
  return f_ == Integrand::ArcLength ? speed : speed / d[0].y();
}

double CurveIntegral::integrate_cell(const BSplineCurve<2>& curve, double lo, double hi) const {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double s = 0;
  for (int k = 0; k < 8; ++k) s += kWeights[k] * integrand(curve, mid + half * kNodes[k]);
  return s * half;
}

CurveIntegral::CurveIntegral(const BSplineCurve<2>& curve, double a, double b, Integrand f) : f_(f) {
  require(b > a, "curve integral: empty parameter interval");
  require(!curve.is_periodic(), "curve integral: the curve must be non-periodic (a streamline)");
  // The knots inside (a, b): the integrand is smooth between them.
  std::vector<double> cuts{a};
  for (double k : curve.knots())
    if (k > a && k < b) cuts.push_back(k);
  cuts.push_back(b);
  cuts.erase(std::unique(cuts.begin(), cuts.end(), [&](double x, double y) { return y - x <= 1e-14 * (b - a); }),
             cuts.end());
  if (cuts.back() != b) cuts.back() = b;
  breaks_.clear();
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    for (int c = 0; c < kCellsPerSpan; ++c) breaks_.push_back(cuts[i] + (cuts[i + 1] - cuts[i]) * c / kCellsPerSpan);
  breaks_.push_back(b);
  // The table with the batched evaluator (sorted parameters: one span conversion each), same rule as
  // integrate_cell.
  CurveEvaluator<2> ev(curve);
  auto value = [&](double u) {
    Eigen::Vector2d P, D;
    ev.d1(u, P, D);
    return f_ == Integrand::ArcLength ? D.norm() : D.norm() / P.y();
  };
  cumulative_.assign(breaks_.size(), 0.0);
  rate_.resize(breaks_.size());
  for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
    const double mid = 0.5 * (breaks_[i] + breaks_[i + 1]), half = 0.5 * (breaks_[i + 1] - breaks_[i]);
    double sum = 0;
    for (int k = 0; k < 8; ++k) sum += kWeights[k] * value(mid + half * kNodes[k]);
    cumulative_[i + 1] = cumulative_[i] + sum * half;
    rate_[i] = value(breaks_[i]);
  }
  rate_.back() = value(breaks_.back());
}

double CurveIntegral::at(const BSplineCurve<2>& curve, double u) const {
  u = std::clamp(u, breaks_.front(), breaks_.back());
  auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
  std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - breaks_.begin()) - 1));
  if (i + 1 >= breaks_.size()) return cumulative_.back();
  if (u == breaks_[i]) return cumulative_[i];
  return cumulative_[i] + integrate_cell(curve, breaks_[i], u);
}

double CurveIntegral::inverse(const BSplineCurve<2>& curve, double value) const {
  value = std::clamp(value, 0.0, cumulative_.back());
  auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), value);
  std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - cumulative_.begin()) - 1));
  if (i + 1 >= breaks_.size()) return breaks_.back();
  double lo = breaks_[i], hi = breaks_[i + 1];
  const double base = cumulative_[i];
  // Start from the cubic Hermite interpolant of u(value) on the cell; Newton, falling back to bisection
  // when a step leaves the bracket (the integrand is positive, so at() is increasing).
  const double cell = cumulative_[i + 1] - base;
  double u = lo;
  if (cell > 0) {
    const double t = (value - base) / cell, h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t),
                 h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    u = h00 * lo + h01 * hi + cell * (h10 / rate_[i] + h11 / rate_[i + 1]);
    if (!(u > lo && u < hi)) u = lo + (hi - lo) * t;
  }
  const double tol = 1e-15 * (std::abs(breaks_.back()) + (breaks_.back() - breaks_.front()));
  for (int iter = 0; iter < 60; ++iter) {
    const double g = base + integrate_cell(curve, breaks_[i], u) - value;
    if (std::abs(g) <= 1e-13 * cumulative_.back()) return u;  // ~1e-11 mm on engine-size streamlines
    if (g > 0) hi = u; else lo = u;
    const double d = integrand(curve, u);
    double next = d > 0 ? u - g / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) <= tol) return next;
    u = next;
  }
  return u;
}

}  // namespace cg::blade::detail
