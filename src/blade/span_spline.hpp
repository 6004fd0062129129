#pragma once
// Interpolation of section quantities over span (internal to the blade model): the natural cubic
// spline through the values at the defined sections' spans (C2, second derivative zero at both ends,
// so it continues linearly beyond them: the over-build). One section gives a constant, two a straight
// line. The spline is linear in the data, so it is kept as cardinal weights: value(s) = sum_k w_k(s) y_k,
// which lets whole profiles (pole or point lists) be interpolated with one set of weights.
// (de Boor, A Practical Guide to Splines, ch. IV: the tridiagonal system for the second derivatives.)
#include <vector>

namespace cg::blade::detail {

class SpanSpline {
 public:
  SpanSpline() = default;
  /// spans strictly increasing, at least one.
  explicit SpanSpline(std::vector<double> spans);

  std::size_t size() const { return spans_.size(); }
  const std::vector<double>& spans() const { return spans_; }
  /// Cardinal weights at span s (they sum to 1).
  std::vector<double> weights(double s) const;
  /// sum_k weights(s)[k] * y[k].
  double value(const std::vector<double>& y, double s) const;

 private:
  std::vector<double> spans_;
  // moments_(i, k): second derivative at spans_[i] of the cardinal spline of section k (row-major K x K).
  std::vector<double> moments_;
};

}  // namespace cg::blade::detail
