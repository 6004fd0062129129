#include "src/modify/pole_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/knots.hpp"
#include "src/core/rational.hpp"  // binomial

namespace cg::bundle {
namespace {

using Index = Eigen::Index;
using std::size_t;

bool is_clamped(const PoleBundle& b) {
  const auto& U = b.knots;
  const size_t p = static_cast<size_t>(b.degree);
  return !b.periodic && U[0] == U[p] && U[U.size() - 1] == U[U.size() - 1 - p];
}

int floor_div(int a, int n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }

// ---- raw algorithms on non-periodic data (inputs already checked) -------------------------------------

// The NURBS Book A5.1 (CurveKnotIns): u inserted r times; s = current multiplicity of u, s + r <= p.
PoleBundle insert_raw(const PoleBundle& b, double u, int r) {
  const int p = b.degree, np = b.num_poles() - 1, mp = np + p + 1;
  const auto& UP = b.knots;
  const auto& P = b.poles;
  // k: last index with UP[k] <= u, so the s copies of u (if any) are UP[k-s+1..k].
  const int k = static_cast<int>(std::upper_bound(UP.begin(), UP.end(), u) - UP.begin()) - 1;
  const int s = knot_multiplicity(UP, u);
  PoleBundle q{p, std::vector<double>(static_cast<size_t>(mp + r + 1)), Eigen::MatrixXd(P.rows(), np + r + 1), false};
  auto& UQ = q.knots;
  auto& Q = q.poles;
  for (int i = 0; i <= k; ++i) UQ[static_cast<size_t>(i)] = UP[static_cast<size_t>(i)];
  for (int i = 1; i <= r; ++i) UQ[static_cast<size_t>(k + i)] = u;
  for (int i = k + 1; i <= mp; ++i) UQ[static_cast<size_t>(i + r)] = UP[static_cast<size_t>(i)];
  for (int i = 0; i <= k - p; ++i) Q.col(i) = P.col(i);
  for (int i = k - s; i <= np; ++i) Q.col(i + r) = P.col(i);
  Eigen::MatrixXd R = P.middleCols(k - p, p - s + 1);
  int L = 0;
  for (int j = 1; j <= r; ++j) {
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const double alpha = (u - UP[static_cast<size_t>(L + i)]) /
                           (UP[static_cast<size_t>(i + k + 1)] - UP[static_cast<size_t>(L + i)]);
      R.col(i) = alpha * R.col(i + 1) + (1.0 - alpha) * R.col(i);
    }
    Q.col(L) = R.col(0);
    Q.col(k + r - j - s) = R.col(p - j - s);
  }
  for (int i = L + 1; i < k - s; ++i) Q.col(i) = R.col(i - L);
  return q;
}

// The NURBS Book A5.4 (RefineKnotVectCurve): X non-decreasing, inside [U[p], U[n+1]].
PoleBundle refine_raw(const PoleBundle& b, const std::vector<double>& X) {
  if (X.empty()) return b;
  const int p = b.degree, n = b.num_poles() - 1, m = n + p + 1, r = static_cast<int>(X.size()) - 1;
  const auto& U = b.knots;
  const auto& P = b.poles;
  const int a = find_span(U.data(), n, p, X.front());
  const int c = find_span(U.data(), n, p, X.back()) + 1;
  PoleBundle q{p, std::vector<double>(static_cast<size_t>(m + r + 2)), Eigen::MatrixXd(P.rows(), n + r + 2), false};
  auto& Ub = q.knots;
  auto& Q = q.poles;
  for (int j = 0; j <= a - p; ++j) Q.col(j) = P.col(j);
  for (int j = c - 1; j <= n; ++j) Q.col(j + r + 1) = P.col(j);
  for (int j = 0; j <= a; ++j) Ub[static_cast<size_t>(j)] = U[static_cast<size_t>(j)];
  for (int j = c + p; j <= m; ++j) Ub[static_cast<size_t>(j + r + 1)] = U[static_cast<size_t>(j)];
  int i = c + p - 1, k = c + p + r;
  for (int j = r; j >= 0; --j) {
    const double x = X[static_cast<size_t>(j)];
    while (x <= U[static_cast<size_t>(i)] && i > a) {
      Q.col(k - p - 1) = P.col(i - p - 1);
      Ub[static_cast<size_t>(k)] = U[static_cast<size_t>(i)];
      --k;
      --i;
    }
    Q.col(k - p - 1) = Q.col(k - p);
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = Ub[static_cast<size_t>(k + l)] - x;
      if (alfa == 0.0) {
        Q.col(ind - 1) = Q.col(ind);
      } else {
        alfa /= Ub[static_cast<size_t>(k + l)] - U[static_cast<size_t>(i - p + l)];
        Q.col(ind - 1) = alfa * Q.col(ind - 1) + (1.0 - alfa) * Q.col(ind);
      }
    }
    Ub[static_cast<size_t>(k)] = x;
    --k;
  }
  return q;
}

// Clamped piece on [a, c] of data in which a and c already have multiplicity >= p (or are clamped ends):
// the poles between them and the knots strictly inside.
PoleBundle slice(const PoleBundle& b, double a, double c) {
  const int p = b.degree;
  const auto& U = b.knots;
  const int ka = static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;  // last a
  const int kc = static_cast<int>(std::lower_bound(U.begin(), U.end(), c) - U.begin());      // first c
  PoleBundle q{p, {}, b.poles.middleCols(ka - p, kc - ka + p), false};
  q.knots.assign(static_cast<size_t>(p + 1), a);
  q.knots.insert(q.knots.end(), U.begin() + ka + 1, U.begin() + kc);
  q.knots.insert(q.knots.end(), static_cast<size_t>(p + 1), c);
  return q;
}

// Knots that bring each of the values to multiplicity >= p (sorted values, each inside the domain).
void append_to_multiplicity_p(const PoleBundle& b, double x, std::vector<double>& X) {
  const int s = knot_multiplicity(b.knots, x);
  for (int i = s; i < b.degree; ++i) X.push_back(x);
}

// Non-periodic segment on [a, c], first <= a < c <= last.
PoleBundle segment_raw(const PoleBundle& b, double a, double c) {
  std::vector<double> X;
  append_to_multiplicity_p(b, a, X);
  append_to_multiplicity_p(b, c, X);
  return slice(refine_raw(b, X), a, c);
}

// Degree elevation of clamped data by blossoming (Ramshaw; The NURBS Book sec. 5.5 states the result
// that A5.9 computes). The elevated knot vector raises every distinct knot's multiplicity by t, and pole j
// of the elevated spline is the degree-q blossom of the polynomial piece on any non-empty span among
// Uh[j .. j+q] at (Uh[j+1], ..., Uh[j+q]), q = p + t. A degree-p polynomial's degree-q blossom is the
// average of its degree-p blossom over the p-element subsets of the arguments, each evaluated by the
// de Boor triangle. A5.9's knot-removal step extrapolates and loses up to 1e-5 of the pole scale on knot
// vectors with span ratios ~1e4 (measured against OCCT); here every value is a de Boor evaluation near
// its own span, accurate to ~1e-15 on the same cases.
PoleBundle elevate_raw(const PoleBundle& B, int t) {
  const int p = B.degree, q = p + t;
  const auto& U = B.knots;
  const int n = B.num_poles() - 1;
  const Index rows = B.poles.rows();
  const DistinctKnots d = distinct_knots(U);
  PoleBundle out{q, {}, Eigen::MatrixXd(), false};
  for (std::size_t i = 0; i < d.values.size(); ++i) out.knots.insert(out.knots.end(), static_cast<size_t>(d.mults[i] + t), d.values[i]);
  const auto& Uh = out.knots;
  const int nq = static_cast<int>(Uh.size()) - q - 1;
  out.poles.resize(rows, nq);

  Eigen::MatrixXd D(rows, p + 1);
  Eigen::VectorXd sum(rows);
  std::vector<double> vals, xs(static_cast<size_t>(p));
  std::vector<int> mult, count;
  const double total = binomial(q, p);
  // Degree-p blossom of span k at xs (de Boor triangle), added to sum with the given weight.
  auto add_blossom = [&](int k, double weight) {
    D = B.poles.middleCols(k - p, p + 1);
    for (int r = 1; r <= p; ++r) {
      const double xr = xs[static_cast<size_t>(r - 1)];
      for (int i = p; i >= r; --i) {
        const double lo = U[static_cast<size_t>(k - p + i)], hi = U[static_cast<size_t>(k + i + 1 - r)];
        const double alpha = (xr - lo) / (hi - lo);
        D.col(i) = (1.0 - alpha) * D.col(i - 1) + alpha * D.col(i);
      }
    }
    sum += weight * D.col(p);
  };
  for (int j = 0; j < nq; ++j) {
    // Non-empty span of Uh among [j, j+q] closest to the middle of the arguments.
    int l = -1;
    for (int off = 0; off <= q && l < 0; ++off)
      for (int cand : {j + q / 2 - off, j + q / 2 + off + 1})
        if (l < 0 && cand >= j && cand <= j + q && cand + 1 < static_cast<int>(Uh.size()) &&
            Uh[static_cast<size_t>(cand)] < Uh[static_cast<size_t>(cand + 1)])
          l = cand;
    const double left = Uh[static_cast<size_t>(l)], right = Uh[static_cast<size_t>(l + 1)], mid = 0.5 * (left + right);
    const int k = find_span(U.data(), n, p, left);  // the same span in the original knots
    // Distinct argument values, farthest from the span first: the last de Boor levels use the narrowest
    // knot intervals, so the arguments nearest the span go there.
    vals.clear();
    mult.clear();
    for (int a = 0; a < q; ++a) {
      const double x = Uh[static_cast<size_t>(j + 1 + a)];
      if (!vals.empty() && vals.back() == x) ++mult.back();
      else vals.push_back(x), mult.push_back(1);
    }
    std::vector<size_t> order(vals.size());
    for (size_t a = 0; a < order.size(); ++a) order[a] = a;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return std::abs(vals[a] - mid) > std::abs(vals[b] - mid); });
    // The p-element sub-multisets of the arguments; each stands for prod C(mult, count) subsets.
    count.assign(vals.size(), 0);
    sum.setZero();
    auto enumerate = [&](auto&& self, size_t v, int left_over, double weight) -> void {
      if (v == order.size()) {
        if (left_over != 0) return;
        int c = 0;
        for (size_t o : order)
          for (int e = 0; e < count[o]; ++e) xs[static_cast<size_t>(c++)] = vals[o];
        add_blossom(k, weight);
        return;
      }
      const size_t o = order[v];
      for (int cnt = std::min(mult[o], left_over); cnt >= 0; --cnt) {
        count[o] = cnt;
        self(self, v + 1, left_over - cnt, weight * binomial(mult[o], cnt));
      }
      count[o] = 0;
    };
    enumerate(enumerate, 0, p, 1.0);
    out.poles.col(j) = sum / total;
  }
  return out;
}

// Non-periodic clamped bundle on [t0 - T, t0 + 2T] equal to the periodic bundle b there: three periods of
// the infinite knot/pole sequences, clamped at both ends. Every pole of the base period window lies
// strictly inside, so the clamping does not touch it.
PoleBundle periodic_extension(const PoleBundle& b) {
  const int p = b.degree, n = b.num_period_poles();
  const double T = b.period();
  const int N = 3 * n + p;  // poles of the extension
  PoleBundle e{p, std::vector<double>(static_cast<size_t>(N + p + 1)), Eigen::MatrixXd(b.poles.rows(), N), false};
  for (int i = 0; i <= N + p; ++i) {
    const int j = i - n;  // index in the infinite sequence whose base window is the stored data
    const int q = floor_div(j - p, n);
    e.knots[static_cast<size_t>(i)] = b.knots[static_cast<size_t>(p + (j - p - q * n))] + q * T;
  }
  for (int i = 0; i < N; ++i) e.poles.col(i) = b.poles.col(i % n);
  return segment_raw(e, e.knots[static_cast<size_t>(p)], e.knots[static_cast<size_t>(N)]);
}

// Periodic bundle (stored form) read from a clamped extension whose knots contain t0 exactly and the seam
// copy t0 + T as computed by periodic_extension.
PoleBundle periodic_window(const PoleBundle& e, double t0, double T) {
  const int p = e.degree;
  const auto& U = e.knots;
  const int f = static_cast<int>(std::lower_bound(U.begin(), U.end(), t0) - U.begin());
  const double seam = t0 + T;
  int n = 0;
  while (f + n < static_cast<int>(U.size()) && U[static_cast<size_t>(f + n)] < seam) ++n;
  if (U[static_cast<size_t>(f)] != t0 || f - p < 0 || f - p + n + p > e.num_poles())
    throw AlgorithmFailure("periodic window: extension does not cover one period");
  const std::vector<double> period_knots(U.begin() + f, U.begin() + f + n);
  PoleBundle q{p, unwrap_periodic_knots(p, period_knots, T), Eigen::MatrixXd(e.poles.rows(), n + p), true};
  q.poles.leftCols(n) = e.poles.middleCols(f - p, n);
  q.poles.rightCols(p) = q.poles.leftCols(p);  // the wrap poles are exact copies
  return q;
}

// Throws unless every value of the sorted list X, with its count in X, keeps multiplicity <= p.
void check_multiplicities(const PoleBundle& b, const std::vector<double>& X) {
  const int p = b.degree;
  const std::vector<double> own = b.periodic ? std::vector<double>(b.knots.begin() + p, b.knots.begin() + p + b.num_period_poles())
                                             : b.knots;
  for (size_t i = 0; i < X.size();) {
    size_t j = i;
    while (j < X.size() && X[j] == X[i]) ++j;
    const int s = knot_multiplicity(own, X[i]);
    const int total = s + static_cast<int>(j - i);
    if (total > p)
      throw InvalidGeometry("knot " + format_number(X[i]) + " would get multiplicity " + std::to_string(total) +
                            " (has " + std::to_string(s) + ", inserting " + std::to_string(j - i) +
                            "), more than the degree " + std::to_string(p));
    i = j;
  }
}

// Periodic refinement: the copies x - T, x, x + T of every knot go into the clamped three-period
// extension (copies on its clamped ends are outside the window and skipped), then the base window is read.
PoleBundle refine_periodic(const PoleBundle& b, const std::vector<double>& X) {
  const double t0 = b.first(), T = b.period();
  const PoleBundle e = periodic_extension(b);
  std::vector<double> all;
  all.reserve(3 * X.size());
  for (int q = -1; q <= 1; ++q)
    for (double x : X) {
      const double y = x + q * T;
      if (y > e.first() && y < e.last()) all.push_back(y);
    }
  return periodic_window(refine_raw(e, all), t0, T);
}

}  // namespace

double checked_param(const PoleBundle& b, double u, const char* what) {
  const double a = b.first(), c = b.last();
  if (!std::isfinite(u)) throw InvalidGeometry(std::string(what) + " is not finite");
  if (b.periodic) {
    if (u >= a && u < c) return u;
    const double T = c - a;
    double r = std::fmod(u - a, T);
    if (r < 0) r += T;
    const double w = a + r;
    return w < c ? w : a;  // a + r may round up to the seam copy
  }
  const double eps = 1e-12 * (c - a);
  if (!(u >= a - eps && u <= c + eps)) {
    const ValueRangeText t = format_value_range(u, a, c);
    throw InvalidGeometry(std::string(what) + " " + t.value + " outside the domain [" + t.lo + ", " + t.hi + "]");
  }
  return std::clamp(u, a, c);
}

PoleBundle insert_knot(const PoleBundle& b, double u, int times) {
  require(times >= 1, "knot insertion count " + std::to_string(times) + " must be >= 1");
  u = checked_param(b, u, "inserted knot");
  check_multiplicities(b, std::vector<double>(static_cast<size_t>(times), u));
  if (b.periodic) return refine_periodic(b, std::vector<double>(static_cast<size_t>(times), u));
  return insert_raw(b, u, times);
}

PoleBundle refine_knots(const PoleBundle& b, const std::vector<double>& X) {
  for (size_t i = 1; i < X.size(); ++i)
    require(X[i] >= X[i - 1], "refinement knots must be non-decreasing: knot " + std::to_string(i) + " = " + format_number(X[i]) +
                                  " < " + format_number(X[i - 1]));
  if (X.empty()) return b;
  std::vector<double> Y(X.size());
  for (size_t i = 0; i < X.size(); ++i) Y[i] = checked_param(b, X[i], "refinement knot");
  std::sort(Y.begin(), Y.end());  // wrapping may reorder knots of a periodic curve
  check_multiplicities(b, Y);
  return b.periodic ? refine_periodic(b, Y) : refine_raw(b, Y);
}

PoleBundle elevate_degree(const PoleBundle& b, int t) {
  require(t >= 1, "degree elevation step " + std::to_string(t) + " must be >= 1");
  require(b.degree + t <= kMaxDegree, "elevated degree " + std::to_string(b.degree + t) + " exceeds the maximum " +
                                          std::to_string(kMaxDegree));
  if (b.periodic) return periodic_window(elevate_raw(periodic_extension(b), t), b.first(), b.period());
  return elevate_raw(clamped(b), t);
}

PoleBundle segment(const PoleBundle& b, double a, double c) {
  require(std::isfinite(a) && std::isfinite(c) && a < c,
          "segment bounds must satisfy a < b, got [" + format_number(a) + ", " + format_number(c) + "]");
  if (!b.periodic) {
    a = checked_param(b, a, "segment start");
    c = checked_param(b, c, "segment end");
    require(a < c, "segment [" + format_number(a) + ", " + format_number(c) + "] is empty after clamping to the domain");
    return segment_raw(b, a, c);
  }
  const double T = b.period();
  if (c - a > T) {
    require(c - a <= T * (1.0 + 1e-12), "segment length " + format_number(c - a) + " exceeds the period " + format_number(T));
    c = a + T;
  }
  // Shift [a, c] so that a lies in the base period; the extension covers [t0 - T, t0 + 2T] ⊃ [a', a' + T].
  const PoleBundle e = periodic_extension(b);
  const double a1 = checked_param(b, a, "segment start");
  const double shift = a1 - a;
  const double c1 = std::min(c + shift, e.last());
  PoleBundle q = segment_raw(e, a1, c1);
  for (double& k : q.knots) k -= shift;
  const size_t p = static_cast<size_t>(q.degree);
  std::fill(q.knots.begin(), q.knots.begin() + static_cast<long>(p + 1), a);
  std::fill(q.knots.end() - static_cast<long>(p + 1), q.knots.end(), c);
  return q;
}

std::pair<PoleBundle, PoleBundle> split(const PoleBundle& b, double u) {
  const PoleBundle c = clamped(b);
  require(std::isfinite(u) && u > c.first() && u < c.last(),
          "split parameter " + format_number(u) + " must lie strictly inside the domain (" + format_number(c.first()) + ", " +
              format_number(c.last()) + ")");
  std::vector<double> X;
  append_to_multiplicity_p(c, u, X);
  const PoleBundle r = refine_raw(c, X);
  return {slice(r, r.first(), u), slice(r, u, r.last())};
}

PoleBundle clamped(const PoleBundle& b) {
  if (is_clamped(b)) return b;
  PoleBundle open = b;  // the unwrapped periodic form is a valid unclamped B-spline on [first, last]
  open.periodic = false;
  return segment_raw(open, b.first(), b.last());
}

PoleBundle reversed(const PoleBundle& b) {
  const int p = b.degree;
  const double a = b.first(), c = b.last();
  // Reflected value of a knot; the domain ends map exactly onto each other.
  auto reflect = [&](double u) { return u == a ? c : u == c ? a : std::clamp(a + (c - u), a, c); };
  if (!b.periodic) {
    const size_t m = b.knots.size() - 1;
    PoleBundle q{p, std::vector<double>(m + 1), b.poles.rowwise().reverse(), false};
    for (size_t i = 0; i <= m; ++i) {
      const double u = b.knots[m - i];
      q.knots[i] = (u < a || u > c) ? a + (c - u) : reflect(u);
    }
    return q;
  }
  // Periodic: reflect one period of knots, then realign so that the seam knot comes first again
  // (the reflected sequence starts s - 1 knots early when the seam multiplicity s > 1).
  const int n = b.num_period_poles();
  const std::vector<double> period(b.knots.begin() + p, b.knots.begin() + p + n);
  const int s = knot_multiplicity(period, a);
  std::vector<double> t(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) t[static_cast<size_t>(i)] = i < s ? a : reflect(period[static_cast<size_t>(n - 1 - i + s)]);
  PoleBundle q{p, unwrap_periodic_knots(p, t, c - a), Eigen::MatrixXd(b.poles.rows(), n + p), true};
  for (int j = 0; j < n + p; ++j) q.poles.col(j) = b.poles.col(((n + p + s - 2 - j) % n + n) % n);
  return q;
}

}  // namespace cg::bundle
