#include "src/blade/span_spline.hpp"

#include <algorithm>
#include <string>

#include "src/core/error.hpp"

namespace cg::blade::detail {

SpanSpline::SpanSpline(std::vector<double> spans) : spans_(std::move(spans)) {
  const std::size_t K = spans_.size();
  require(K >= 1, "span interpolation needs at least one span");
  for (std::size_t k = 1; k < K; ++k)
    require(spans_[k] > spans_[k - 1], "span interpolation: spans must increase strictly");
  moments_.assign(K * K, 0.0);
  if (K < 3) return;  // constant or linear: no curvature
  // Natural spline: M_0 = M_{K-1} = 0 and for interior i
  //   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1}), d_i = (y_{i+1} - y_i) / h_i,
  // solved (Thomas algorithm) once per unit data vector e_k.
  const std::size_t m = K - 2;
  std::vector<double> h(K - 1);
  for (std::size_t i = 0; i + 1 < K; ++i) h[i] = spans_[i + 1] - spans_[i];
  for (std::size_t k = 0; k < K; ++k) {
    auto y = [&](std::size_t i) { return i == k ? 1.0 : 0.0; };
    std::vector<double> a(m), b(m), c(m), r(m);
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t i = j + 1;
      a[j] = h[i - 1];
      b[j] = 2 * (h[i - 1] + h[i]);
      c[j] = h[i];
      r[j] = 6 * ((y(i + 1) - y(i)) / h[i] - (y(i) - y(i - 1)) / h[i - 1]);
    }
    for (std::size_t j = 1; j < m; ++j) {
      const double f = a[j] / b[j - 1];
      b[j] -= f * c[j - 1];
      r[j] -= f * r[j - 1];
    }
    std::vector<double> M(m);
    for (std::size_t j = m; j-- > 0;) M[j] = (r[j] - (j + 1 < m ? c[j] * M[j + 1] : 0.0)) / b[j];
    for (std::size_t j = 0; j < m; ++j) moments_[(j + 1) * K + k] = M[j];
  }
}

std::vector<double> SpanSpline::weights(double s) const {
  const std::size_t K = spans_.size();
  std::vector<double> w(K, 0.0);
  if (K == 1) {
    w[0] = 1;
    return w;
  }
  // Interval [i, i + 1] holding s (the end intervals also take s beyond the ends: linear continuation,
  // as the end moments are zero).
  const std::size_t i = static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(std::upper_bound(spans_.begin(), spans_.end(), s) - spans_.begin() - 1, 0,
                                 static_cast<std::ptrdiff_t>(K) - 2));
  const double h = spans_[i + 1] - spans_[i];
  // Beyond the ends the spline continues along its end tangent (natural end: zero second derivative).
  const bool before = s < spans_.front(), after = s > spans_.back();
  const double se = before ? spans_.front() : after ? spans_.back() : s;
  const double A = (spans_[i + 1] - se) / h, B = 1 - A;
  w[i] += A;
  w[i + 1] += B;
  if (K >= 3) {
    // y(s) = A y_i + B y_{i+1} + ((A^3 - A) M_i + (B^3 - B) M_{i+1}) h^2 / 6 inside the interval.
    const double ca = (A * A * A - A) * h * h / 6, cb = (B * B * B - B) * h * h / 6;
    for (std::size_t k = 0; k < K; ++k) w[k] += ca * moments_[i * K + k] + cb * moments_[(i + 1) * K + k];
  }
  if (before || after) {
    // dy/ds = (y_{i+1} - y_i) / h + (-(3 A^2 - 1) M_i + (3 B^2 - 1) M_{i+1}) h / 6.
    const double d = s - se;
    w[i] -= d / h;
    w[i + 1] += d / h;
    if (K >= 3) {
      const double da = -(3 * A * A - 1) * h / 6, db = (3 * B * B - 1) * h / 6;
      for (std::size_t k = 0; k < K; ++k) w[k] += d * (da * moments_[i * K + k] + db * moments_[(i + 1) * K + k]);
    }
  }
  return w;
}

double SpanSpline::value(const std::vector<double>& y, double s) const {
  require(y.size() == spans_.size(), "span interpolation: one value per span is needed, got " +
                                         std::to_string(y.size()) + " for " + std::to_string(spans_.size()));
  const std::vector<double> w = weights(s);
  double v = 0;
  for (std::size_t k = 0; k < y.size(); ++k) v += w[k] * y[k];
  return v;
}

}  // namespace cg::blade::detail
