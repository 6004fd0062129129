#include "src/core/knots.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

void validate_knots(const std::vector<double>& U, int p, int num_poles) {
  require(p >= 1 && p <= kMaxDegree,
          "degree " + std::to_string(p) + " out of range [1, " + std::to_string(kMaxDegree) + "]");
  require(num_poles >= p + 1, "need at least degree + 1 = " + std::to_string(p + 1) + " poles, got " +
                                  std::to_string(num_poles));
  const std::size_t expected = static_cast<std::size_t>(num_poles + p + 1);
  require(U.size() == expected, "knot count " + std::to_string(U.size()) + " must equal poles + degree + 1 = " +
                                    std::to_string(expected));
  // Plain ifs in the loops: the messages are only built on failure.
  for (std::size_t i = 0; i < U.size(); ++i) {
    if (!std::isfinite(U[i])) throw InvalidGeometry("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && U[i] < U[i - 1])
      throw InvalidGeometry("knots must be non-decreasing: knot " + std::to_string(i) + " = " + format_number(U[i]) +
                            " < knot " + std::to_string(i - 1) + " = " + format_number(U[i - 1]));
  }
  require(U[num_poles] > U[p], "empty parameter domain [U[p], U[n+1]]");
  // Interior multiplicity > p would make the curve discontinuous.
  std::size_t i = 0;
  while (i < U.size()) {
    std::size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    const int mult = static_cast<int>(j - i + 1);
    const bool at_end = (i == 0) || (j == U.size() - 1);
    if (mult > (at_end ? p + 1 : p))
      throw InvalidGeometry("knot " + format_number(U[i]) + " has multiplicity " + std::to_string(mult) +
                            ", allowed at most " + std::to_string(at_end ? p + 1 : p));
    i = j + 1;
  }
}

int find_span(const double* U, int n, int p, double u) {
  if (u >= U[n + 1]) {
    int s = n;  // last non-empty span
    while (s > p && U[s] == U[s + 1]) --s;
    return s;
  }
  if (u <= U[p]) {
    int s = p;
    while (s < n && U[s] == U[s + 1]) ++s;
    return s;
  }
  // Binary search for U[s] <= u < U[s+1], s in [p, n] (U[p] < u < U[n+1] here). Branch-free
  // halving (the comparison selects the base by a conditional move): for parameters in random order
  // the branches of std::upper_bound mispredict half the time, which costs more than the search.
  const double* base = U + p;
  int len = n + 1 - p;  // candidates base[0 .. len-1]; base[0] <= u
  while (len > 1) {
    const int half = len / 2;
    base = base[half] <= u ? base + half : base;
    len -= half;
  }
  return static_cast<int>(base - U);
}

int find_span_hint(const double* U, int n, int p, double u, int hint) {
  if (hint >= p && hint <= n) {
    if (U[hint] <= u && u < U[hint + 1]) return hint;
    if (hint < n && U[hint + 1] <= u && u < U[hint + 2]) return hint + 1;
  }
  return find_span(U, n, p, u);
}

SpanTable::SpanTable(const double* U, int n, int p, double eps, bool periodic)
    : U_(U), n_(n), p_(p), a_(U[p]), b_(U[n + 1]) {
  spans_.resize(static_cast<std::size_t>(n - p + 1));
  for (int s = p; s <= n; ++s) {
    Span& sp = spans_[static_cast<std::size_t>(s - p)];
    sp.lo = U[s];
    sp.hi = U[s + 1];
    sp.mid = 0.5 * (U[s] + U[s + 1]);
    sp.scale = U[s + 1] > U[s] ? 2.0 / (U[s + 1] - U[s]) : 0.0;
  }
  const int first = find_span(U, n, p, a_), last = find_span(U, n, p, b_);
  if (!periodic) spans_[static_cast<std::size_t>(first - p)].lo = a_ - eps;
  spans_[static_cast<std::size_t>(last - p)].hi = b_ + eps + 1e-300;
  // Twice as many buckets as spans (capped): most buckets then overlap one or two spans.
  const int buckets = std::min(2 * (n - p + 1), 1 << 16);
  const double h = (b_ - a_) / buckets;
  inv_h_ = 1.0 / h;
  bucket_.resize(static_cast<std::size_t>(buckets + 1));
  for (int k = 0; k <= buckets; ++k) bucket_[static_cast<std::size_t>(k)] = find_span(U, n, p, a_ + k * h);
}

int SpanTable::find(double u) const {
  if (!(u > a_ && u < b_)) return find_span(U_, n_, p_, u);  // domain ends, outside, NaN
  std::size_t k = static_cast<std::size_t>((u - a_) * inv_h_);
  if (k + 1 >= bucket_.size()) k = bucket_.size() - 2;
  // Largest s in [bucket_[k], bucket_[k+1]] with U[s] <= u (branch-free halving as in find_span).
  const double* base = U_ + bucket_[k];
  int len = bucket_[k + 1] - bucket_[k] + 1;
  while (len > 1) {
    const int half = len / 2;
    base = base[half] <= u ? base + half : base;
    len -= half;
  }
  const int s = static_cast<int>(base - U_);
  // The bucket index is rounded: verify, and fall back to the full search in the rare miss.
  if (U_[s] <= u && u < U_[s + 1]) return s;
  return find_span(U_, n_, p_, u);
}

int knot_multiplicity(const std::vector<double>& U, double u, double tol) {
  int m = 0;
  for (double k : U)
    if (std::abs(k - u) <= tol) ++m;
  return m;
}

DistinctKnots distinct_knots(const std::vector<double>& U, double tol) {
  DistinctKnots d;
  for (double k : U) {
    if (!d.values.empty() && std::abs(k - d.values.back()) <= tol) {
      ++d.mults.back();
    } else {
      d.values.push_back(k);
      d.mults.push_back(1);
    }
  }
  return d;
}

std::vector<double> flat_knots(const std::vector<double>& values, const std::vector<int>& mults) {
  require(values.size() == mults.size(), "distinct knots and multiplicities differ in length");
  std::vector<double> U;
  for (std::size_t i = 0; i < values.size(); ++i) {
    require(mults[i] >= 1, "knot multiplicity must be >= 1");
    U.insert(U.end(), static_cast<std::size_t>(mults[i]), values[i]);
  }
  return U;
}

std::vector<double> unwrap_periodic_knots(int p, const std::vector<double>& t, double T) {
  const int n = static_cast<int>(t.size());
  require(n >= 1 && p >= 1, "periodic knots need at least one knot per period and degree >= 1");
  require(std::isfinite(T) && T > 0.0, "period must be positive");
  for (int i = 1; i < n; ++i) require(t[static_cast<std::size_t>(i)] >= t[static_cast<std::size_t>(i - 1)], "periodic knots must be non-decreasing");
  require(t.back() < t.front() + T, "periodic knots must lie within one period");
  std::vector<double> U(static_cast<std::size_t>(n + 2 * p + 1));
  for (int j = -p; j <= n + p; ++j) {
    const int q = j >= 0 ? j / n : -((-j + n - 1) / n);
    U[static_cast<std::size_t>(j + p)] = t[static_cast<std::size_t>(j - q * n)] + q * T;
  }
  return U;
}

std::vector<double> uniform_clamped_knots(int p, int num_poles, double a, double b) {
  require(num_poles >= p + 1, "need at least degree + 1 poles for a clamped knot vector");
  require(b > a, "uniform knots need a < b");
  std::vector<double> U(static_cast<std::size_t>(num_poles + p + 1));
  const int spans = num_poles - p;
  for (int i = 0; i <= p; ++i) {
    U[static_cast<std::size_t>(i)] = a;
    U[U.size() - 1 - static_cast<std::size_t>(i)] = b;
  }
  for (int j = 1; j < spans; ++j) U[static_cast<std::size_t>(p + j)] = a + (b - a) * j / spans;
  return U;
}

}  // namespace cg

namespace cg {

void check_derivative_order(int order, const char* what) {
  if (order < 0 || order > kMaxDegree)
    throw InvalidGeometry(std::string(what) + " derivative order " + std::to_string(order) + " outside [0, " +
                          std::to_string(kMaxDegree) + "]");
}

}  // namespace cg
