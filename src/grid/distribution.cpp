#include "src/grid/distribution.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/core/error.hpp"

namespace cg::grid {

namespace {


// Root of f on [lo, hi] by bisection (f(lo) and f(hi) of opposite signs): robust and plenty fast here.
template <class F>
double bisect(F&& f, double lo, double hi) {
  double flo = f(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm < 0) == (flo < 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double geometric_length(double first, double ratio, int cells) {
  if (std::abs(ratio - 1) < 1e-12) return first * cells;
  return first * (std::pow(ratio, cells) - 1) / (ratio - 1);
}

std::vector<double> geometric_then_uniform(double first, double ratio, int cells, double length) {
  require(first > 0 && ratio >= 1 && cells >= 1 && length > 0, "geometric_then_uniform: invalid arguments");
  const double lo = first * cells, hi = geometric_length(first, ratio, cells);
  if (length < lo * (1 - 1e-12) || length > hi * (1 + 1e-12)) {
    const ValueRangeText t = format_value_range(length, lo, hi);
    throw InvalidGeometry("the thickness " + t.value + " mm cannot be reached with " + std::to_string(cells) +
                          " cells from a first cell of " + format_number(first) + " mm growing by at most " + format_number(ratio) +
                          ": it must lie in [" + t.lo + ", " + t.hi + "] mm");
  }
  // The smallest k (number of geometric cells) whose uniform rest spacing is <= first ratio^k; then it
  // is > first ratio^(k-1) as well (the rest spacing is a weighted mean of the previous ones).
  int k = 0;
  double geo = 0, uniform = length / cells;
  while (k < cells && uniform > first * std::pow(ratio, k)) {
    geo += first * std::pow(ratio, k);
    ++k;
    uniform = k < cells ? (length - geo) / (cells - k) : 0.0;
  }
  std::vector<double> s(static_cast<std::size_t>(cells) + 1, 0.0);
  for (int c = 0; c < cells; ++c)
    s[static_cast<std::size_t>(c) + 1] = s[static_cast<std::size_t>(c)] + (c < k ? first * std::pow(ratio, c) : uniform);
  s.back() = length;
  return s;
}

std::vector<double> geometric_fill(double first, int cells, double length, double* ratio_out) {
  require(first > 0 && cells >= 1 && length > 0, "geometric_fill: invalid arguments");
  double r = 1.0;
  if (std::abs(first * cells - length) > 1e-14 * length) {
    auto f = [&](double q) { return geometric_length(first, q, cells) - length; };
    double lo = 1.0, hi = 1.0;
    if (first * cells < length) {
      while (f(hi) < 0) hi *= 2;  // geometric_length grows without bound in q
    } else {
      lo = 0.0;  // f(0) = first - length < 0 for one cell shorter than the whole
      require(first < length, "geometric_fill: the first cell " + format_number(first) + " mm is longer than the whole " + format_number(length) + " mm");
    }
    r = bisect(f, lo, hi);
  }
  std::vector<double> s(static_cast<std::size_t>(cells) + 1, 0.0);
  double d = first;
  for (int c = 0; c < cells; ++c, d *= r) s[static_cast<std::size_t>(c) + 1] = s[static_cast<std::size_t>(c)] + d;
  const double scale = length / s.back();  // remove the bisection's last-bit residue
  for (double& x : s) x *= scale;
  if (ratio_out) *ratio_out = r;
  return s;
}

namespace {

std::vector<double> vinokur(int cells, double length, double d0, double d1) {
  std::vector<double> s(static_cast<std::size_t>(cells) + 1);
  // Vinokur: A = sqrt(d1 / d0) skews, B = 1 / (N sqrt(d0 d1)) (spacings relative to the length) picks the
  // symmetric function u(xi); t = u / (A + (1 - A) u).
  const double a = std::sqrt(d1 / d0), b = length / (cells * std::sqrt(d0 * d1));
  const bool linear = std::abs(b - 1) < 1e-9;
  const double dy = linear ? 0.0
                    : b > 1 ? bisect([&](double y) { return std::sinh(y) / y - b; }, 1e-12, 2 * std::asinh(b) + 10)
                            : bisect([&](double y) { return std::sin(y) / y - b; }, 1e-12, kPi - 1e-12);
  auto u_of = [&](double xi) -> double {
    if (linear) return xi;
    if (b > 1) return 0.5 * (1 + std::tanh(dy * (xi - 0.5)) / std::tanh(0.5 * dy));
    return 0.5 * (1 + std::tan(dy * (xi - 0.5)) / std::tan(0.5 * dy));
  };
  for (int k = 0; k <= cells; ++k) {
    const double u = u_of(static_cast<double>(k) / cells);
    s[static_cast<std::size_t>(k)] = length * u / (a + (1 - a) * u);
  }
  s.front() = 0;
  s.back() = length;
  return s;
}

}  // namespace

std::vector<double> two_sided_stretching(int cells, double length, double d0, double d1) {
  require(cells >= 1 && length > 0 && d0 > 0 && d1 > 0, "two_sided_stretching: invalid arguments");
  // Vinokur's function matches the end slopes; the end CELLS of a strongly stretched distribution differ
  // from them by up to ~25 %. A fixed-point correction of the requested spacings fixes that (converges in
  // a few steps; the spacings must leave room for the cells in between, else the best effort is kept).
  double a = d0, b = d1;
  std::vector<double> s = vinokur(cells, length, a, b);
  for (int it = 0; it < 50 && cells >= 2; ++it) {
    const double e0 = s[1] - s[0], e1 = s[static_cast<std::size_t>(cells)] - s[static_cast<std::size_t>(cells) - 1];
    if (std::abs(e0 / d0 - 1) < 1e-9 && std::abs(e1 / d1 - 1) < 1e-9) break;
    a *= d0 / e0;
    b *= d1 / e1;
    s = vinokur(cells, length, a, b);
  }
  return s;
}

std::vector<double> smooth_periodic(const std::vector<double>& v, double sigma) {
  require(sigma > 0 && !v.empty(), "smooth_periodic: invalid arguments");
  const int n = static_cast<int>(v.size()), half = static_cast<int>(std::ceil(3 * sigma));
  std::vector<double> out(v.size());
  for (int k = 0; k < n; ++k) {
    double sum = 0, wsum = 0;
    for (int d = -half; d <= half; ++d) {
      const double w = std::exp(-0.5 * d * d / (sigma * sigma));
      sum += w * v[static_cast<std::size_t>(((k + d) % n + n) % n)];
      wsum += w;
    }
    out[static_cast<std::size_t>(k)] = sum / wsum;
  }
  return out;
}

std::vector<double> equidistribute(const std::vector<double>& density, int cells, double length) {
  require(density.size() >= 2 && cells >= 1 && length > 0, "equidistribute: invalid arguments");
  const std::size_t n = density.size();
  const double h = length / static_cast<double>(n - 1);
  std::vector<double> cum(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) {
    require(density[k] > 0 && density[k - 1] > 0, "equidistribute: the density must be positive");
    cum[k] = cum[k - 1] + 0.5 * h * (density[k] + density[k - 1]);
  }
  std::vector<double> s(static_cast<std::size_t>(cells) + 1);
  std::size_t seg = 1;
  for (int c = 0; c <= cells; ++c) {
    const double target = cum.back() * c / cells;
    while (seg < n - 1 && cum[seg] < target) ++seg;
    // Inside [seg-1, seg] the density is linear, the integral quadratic: solve for the position.
    const double d0 = density[seg - 1], d1 = density[seg], rest = target - cum[seg - 1];
    const double slope = (d1 - d0) / h;
    double x;
    if (std::abs(slope) < 1e-14 * std::max(d0, d1) / h) {
      x = rest / d0;
    } else {
      x = (-d0 + std::sqrt(std::max(0.0, d0 * d0 + 2 * slope * rest))) / slope;
    }
    s[static_cast<std::size_t>(c)] = std::clamp((static_cast<double>(seg - 1) + x / h) * h, 0.0, length);
  }
  s.front() = 0;
  s.back() = length;
  return s;
}

}  // namespace cg::grid
