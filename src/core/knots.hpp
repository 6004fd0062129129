#pragma once
// Knot vectors: validation, span search, multiplicities, distinct-knot form.
// A knot vector is always stored in full ("flat"), with its end knots: m + 1 = n + p + 2 values for
// n + 1 poles of degree p (The NURBS Book, eq. 2.3), so no convention about missing end knots exists.
#include <vector>

namespace cg {

/// Largest supported degree (as in OCCT). Fixed so evaluation can use stack buffers.
constexpr int kMaxDegree = 25;

/// Checks degree in [1, kMaxDegree], knots.size() == num_poles + degree + 1, non-decreasing knots,
/// interior multiplicities <= degree (end multiplicities <= degree + 1) and a non-empty domain.
/// Throws InvalidGeometry naming the problem.
void validate_knots(const std::vector<double>& knots, int degree, int num_poles);

/// Span index i with U[i] <= u < U[i+1], clamped to [p, n] (The NURBS Book A2.1); n = num_poles - 1.
/// u at or beyond the domain ends maps to the first/last non-empty span.
int find_span(const double* U, int n, int p, double u);

/// As find_span, but first tries `hint` and its right neighbour (O(1) for sorted parameters).
int find_span_hint(const double* U, int n, int p, double u, int hint);

/// Precomputed span data of one knot vector for repeated searches (the batched evaluators): a table
/// of equal-length parameter buckets, each holding the range of spans it overlaps, makes a search O(1)
/// for near-uniform knots and a short branch-free binary search otherwise; per span it keeps the
/// parameter interval and the map to the local parameter t = (u - mid) * scale in [-1, 1].
class SpanTable {
 public:
  struct Span {
    double lo, hi;      // u in [lo, hi) belongs to this span (empty spans: lo == hi)
    double mid, scale;  // t = (u - mid) * scale
  };
  SpanTable() = default;
  /// U holds n + p + 2 knots and must outlive the table. The end spans also accept parameters up to
  /// `eps` outside the domain (the first one only if not `periodic`; wrapped periodic parameters may
  /// round up onto the domain end, so the last one always does).
  SpanTable(const double* U, int n, int p, double eps, bool periodic);
  /// Same result as find_span(U, n, p, u).
  int find(double u) const;
  const Span& span(int s) const { return spans_[static_cast<std::size_t>(s - p_)]; }

 private:
  const double* U_ = nullptr;
  int n_ = 0, p_ = 0;
  double a_ = 0, b_ = 0, inv_h_ = 0;
  std::vector<int> bucket_;  // bucket_[k] = span of the bucket start a + k * h, k = 0 .. buckets
  std::vector<Span> spans_;  // index s - p
};

/// Number of knots equal to u within `tol`.
int knot_multiplicity(const std::vector<double>& U, double u, double tol = 0.0);

/// Distinct knot values and their multiplicities (OCCT's representation).
struct DistinctKnots {
  std::vector<double> values;
  std::vector<int> mults;
};
DistinctKnots distinct_knots(const std::vector<double>& U, double tol = 0.0);
std::vector<double> flat_knots(const std::vector<double>& values, const std::vector<int>& mults);

/// Unwrapped knots of a periodic B-spline of degree p: from one period of flat knots
/// t_0 <= ... <= t_{n-1} < t_0 + T, returns U[p + j] = t_{j mod n} + floor(j / n) * T, j = -p .. n + p.
std::vector<double> unwrap_periodic_knots(int p, const std::vector<double>& period_knots, double period);

/// Clamped knot vector on [a, b] with uniformly spaced interior knots for num_poles poles.
std::vector<double> uniform_clamped_knots(int degree, int num_poles, double a = 0.0, double b = 1.0);

}  // namespace cg
