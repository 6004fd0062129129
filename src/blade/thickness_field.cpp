#include "src/blade/thickness_field.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade {
namespace {

// Fritsch-Carlson slopes: harmonic-mean type, zero at extrema, so the interpolant stays monotone.
std::vector<double> monotone_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> d(n - 1), m(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) d[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  m[0] = d[0];
  m[n - 1] = d[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (d[i - 1] * d[i] <= 0) continue;
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;  // Fritsch & Butland weights
    m[i] = (w1 + w2) / (w1 / d[i - 1] + w2 / d[i]);
  }
  // End slopes limited as in Fritsch & Carlson (no overshoot in the end intervals).
  for (std::size_t e : {std::size_t(0), n - 1}) {
    const double de = e == 0 ? d[0] : d[n - 2];
    if (m[e] * de <= 0) m[e] = 0;
    else if (std::abs(m[e]) > 3 * std::abs(de)) m[e] = 3 * de;
  }
  return m;
}

}  // namespace

double monotone_cubic(const std::vector<double>& x, const std::vector<double>& y, double t) {
  require(!x.empty() && x.size() == y.size(), "monotone_cubic: need as many values as abscissae (>= 1)");
  if (x.size() == 1 || t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin()) - 1;
  if (y[i] == y[i + 1]) return y[i];  // flat: both slopes are 0 (exactly, not to the Hermite sum's rounding)
  const std::vector<double> m = monotone_slopes(x, y);
  const double h = x[i + 1] - x[i], s = (t - x[i]) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s), h01 = s * s * (3 - 2 * s),
               h11 = s * s * (s - 1);
  return h00 * y[i] + h10 * h * m[i] + h01 * y[i + 1] + h11 * h * m[i + 1];
}

ThicknessField ThicknessField::constant(double thickness) {
  require(std::isfinite(thickness) && thickness > 0, "wall thickness must be > 0 mm, got " + format_number(thickness));
  ThicknessField f;
  f.values_ = {{thickness}};
  f.min_ = f.max_ = thickness;
  return f;
}

ThicknessField ThicknessField::table(std::vector<double> spans, std::vector<double> chords,
                                     std::vector<std::vector<double>> values) {
  require(!spans.empty() && !chords.empty(), "thickness table: needs at least one span and one chord");
  for (std::size_t i = 1; i < spans.size(); ++i)
    require(spans[i] > spans[i - 1], "thickness table: spans must be strictly increasing");
  for (std::size_t j = 1; j < chords.size(); ++j)
    require(chords[j] > chords[j - 1], "thickness table: chords must be strictly increasing");
  require(values.size() == spans.size(), "thickness table: one row of values per span (" +
                                             std::to_string(spans.size()) + "), got " + std::to_string(values.size()));
  ThicknessField f;
  f.min_ = HUGE_VAL;
  f.max_ = -HUGE_VAL;
  for (std::size_t i = 0; i < values.size(); ++i) {
    require(values[i].size() == chords.size(), "thickness table: row " + std::to_string(i) + " needs " +
                                                   std::to_string(chords.size()) + " values");
    for (double v : values[i]) {
      require(std::isfinite(v) && v > 0, "thickness table: values must be > 0 mm, got " + format_number(v));
      f.min_ = std::min(f.min_, v);
      f.max_ = std::max(f.max_, v);
    }
  }
  f.spans_ = std::move(spans);
  f.chords_ = std::move(chords);
  f.values_ = std::move(values);
  return f;
}

double ThicknessField::constant_over(double lo, double hi) const {
  if (spans_.empty()) return values_.empty() ? std::nan("") : values_[0][0];
  // Nodes a..b: the last one at or below lo (else the first) to the first at or above hi (else the last).
  const std::size_t n = chords_.size();
  const std::size_t a = static_cast<std::size_t>(
      std::max<std::ptrdiff_t>(0, std::upper_bound(chords_.begin(), chords_.end(), lo) - chords_.begin() - 1));
  const std::size_t b = std::min(n - 1, static_cast<std::size_t>(std::lower_bound(chords_.begin(), chords_.end(), hi) - chords_.begin()));
  const double v = values_[0][a];
  for (const std::vector<double>& row : values_)
    for (std::size_t j = a; j <= b; ++j)
      if (row[j] != v) return std::nan("");
  return v;
}

double ThicknessField::at(double span, double chord) const {
  if (spans_.empty()) return values_.empty() ? 0.0 : values_[0][0];
  // Along span only the rows i-1 .. i+2 around span's interval [spans_[i], spans_[i+1]]: the
  // interpolant there uses the slopes at i and i + 1, which depend on the neighbouring intervals only
  // (and, at the table's ends, on the end interval), so the window gives the same value as all rows.
  const std::size_t n = spans_.size();
  const std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(
      0, std::upper_bound(spans_.begin(), spans_.end(), span) - spans_.begin() - 1));
  const std::size_t lo = i == 0 ? 0 : i - 1, hi = std::min(n, i + 3);
  const std::vector<double> window(spans_.begin() + static_cast<std::ptrdiff_t>(lo), spans_.begin() + static_cast<std::ptrdiff_t>(hi));
  std::vector<double> along_span(hi - lo);
  for (std::size_t k = lo; k < hi; ++k) along_span[k - lo] = monotone_cubic(chords_, values_[k], chord);
  return monotone_cubic(window, along_span, span);
}

}  // namespace cg::blade
