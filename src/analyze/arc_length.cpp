#include "src/analyze/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "src/analyze/gauss_legendre.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/newton.hpp"

namespace cg {

namespace {

constexpr int kGaussPoints = 10;

// Nodes and weights of the kGaussPoints-point Gauss-Legendre rule on [-1, 1] (Newton on P_n, computed
// once to full precision rather than typed in).
struct GaussRule {
  std::array<double, kGaussPoints> x, w;
  GaussRule() { gauss_legendre(kGaussPoints, x.data(), w.data()); }
};

const GaussRule& gauss() {
  static const GaussRule rule;
  return rule;
}

// The integrand w(C(u)) |C'(u)| (w = 1 when no weight is given).
template <int Dim>
struct Integrand {
  const BSplineCurve<Dim>& curve;
  typename ArcLength<Dim>::Weight weight;
  double operator()(double u) const {
    typename BSplineCurve<Dim>::Point d[2];
    curve.derivatives(u, 1, d);
    return weight ? weight(d[0]) * d[1].norm() : d[1].norm();
  }
};

template <int Dim>
double gauss_panel(const Integrand<Dim>& speed, double a, double b) {
  const GaussRule& g = gauss();
  const double h = 0.5 * (b - a), m = 0.5 * (a + b);
  double s = 0;
  for (int i = 0; i < kGaussPoints; ++i)
    s += g.w[static_cast<std::size_t>(i)] * speed(m + h * g.x[static_cast<std::size_t>(i)]);
  return s * h;
}

// Recursive bisection until the panel and its halves agree to tol (the halves' sum is returned, its
// error being far below the difference for a smooth integrand).
template <int Dim>
double adaptive(const Integrand<Dim>& c, double a, double b, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss_panel(c, a, m), right = gauss_panel(c, m, b);
  const double sum = left + right;
  // The floor 1e-14 |sum| stops refinement at the rounding level of a panel whose speed is far above
  // the average (its share of the absolute tolerance may be below its own rounding noise).
  if (std::abs(sum - whole) <= std::max(tol, 1e-14 * std::abs(sum)) || depth >= 40 || !(m > a && m < b)) return sum;
  return adaptive(c, a, m, left, 0.5 * tol, depth + 1) + adaptive(c, m, b, right, 0.5 * tol, depth + 1);
}

// a, the knots strictly inside (a, b), b: the panels on which the speed is smooth.
template <int Dim>
std::vector<double> span_breaks(const BSplineCurve<Dim>& c, double a, double b) {
  std::vector<double> breaks{a};
  for (double k : c.knots())
    if (k > breaks.back() && k < b) breaks.push_back(k);
  if (b > a) breaks.push_back(b);
  return breaks;
}

// Length of each panel between consecutive breaks to rel_tol of their sum (abs_tol receives the
// absolute tolerance). A first pass of one rule per panel estimates the total, which fixes the
// absolute tolerance; each panel gets the share of it proportional to its parameter length.
template <int Dim>
std::vector<double> span_lengths(const Integrand<Dim>& c, const std::vector<double>& breaks, double rel_tol,
                                 double& abs_tol) {
  require(rel_tol >= 1e-15 && rel_tol < 1,
          "arc length tolerance " + format_number(rel_tol) + " out of range [1e-15, 1)");
  std::vector<double> len(breaks.size() - 1);
  double estimate = 0;
  for (std::size_t i = 0; i < len.size(); ++i) estimate += len[i] = gauss_panel(c, breaks[i], breaks[i + 1]);
  abs_tol = rel_tol * estimate;
  const double width = breaks.back() - breaks.front();
  for (std::size_t i = 0; i < len.size(); ++i)
    len[i] = adaptive(c, breaks[i], breaks[i + 1], len[i], abs_tol * (breaks[i + 1] - breaks[i]) / width, 0);
  return len;
}

}  // namespace

template <int Dim>
ArcLength<Dim>::ArcLength(BSplineCurve<Dim> curve, double rel_tol, Weight weight)
    : ArcLength(std::move(curve), std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                rel_tol, weight) {}

template <int Dim>
ArcLength<Dim>::ArcLength(BSplineCurve<Dim> curve, double a, double b, double rel_tol, Weight weight)
    : curve_(std::move(curve)), weight_(weight) {
  require(curve_.num_poles() > 0, "arc length of an empty curve");
  if (std::isnan(a) && std::isnan(b)) {
    a = curve_.first_param();
    b = curve_.last_param();
  } else {
    require(a < b && a >= curve_.first_param() && b <= curve_.last_param(),
            "arc length interval [" + format_number(a) + ", " + format_number(b) + "] must satisfy first = " +
                format_number(curve_.first_param()) + " <= a < b <= last = " + format_number(curve_.last_param()));
  }
  breaks_ = span_breaks(curve_, a, b);
  const std::vector<double> len = span_lengths(Integrand<Dim>{curve_, weight_}, breaks_, rel_tol, tol_);
  cumulative_.assign(breaks_.size(), 0.0);
  for (std::size_t i = 0; i < len.size(); ++i) cumulative_[i + 1] = cumulative_[i] + len[i];
}

template <int Dim>
double ArcLength<Dim>::integrate(double a, double b) const {
  if (b == a) return 0;
  const double share = std::max(tol_ * std::abs(b - a) / (breaks_.back() - breaks_.front()), 1e-16 * tol_);
  const Integrand<Dim> f{curve_, weight_};
  return adaptive(f, a, b, gauss_panel(f, a, b), share, 0);
}

template <int Dim>
double ArcLength<Dim>::length_to(double u) const {
  const double a = breaks_.front(), b = breaks_.back();
  const double eps = 1e-12 * (b - a);
  // Per-query check: the message is only built when it fails (no allocation on the hot path).
  if (!(u >= a - eps && u <= b + eps)) {
    const ValueRangeText t = format_value_range(u, a, b);
    throw InvalidGeometry("parameter " + t.value + " outside the curve domain [" + t.lo + ", " + t.hi + "]");
  }
  u = std::clamp(u, a, b);
  if (u == b) return cumulative_.back();
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin()) - 1;
  return cumulative_[i] + integrate(breaks_[i], u);
}

template <int Dim>
double ArcLength<Dim>::param_at(double s) const {
  const double L = total();
  if (!(s >= -tol_ && s <= L + tol_)) {
    const ValueRangeText t = format_value_range(s, 0, L);
    throw InvalidGeometry("arc length " + t.value + " outside [0, " + t.hi + "]");
  }
  if (s <= 0) return breaks_.front();
  if (s >= L) return breaks_.back();
  std::size_t i =
      static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin()) - 1;
  i = std::min(i, breaks_.size() - 2);
  double lo = breaks_[i], hi = breaks_[i + 1];
  const double span_len = cumulative_[i + 1] - cumulative_[i];
  if (span_len <= 0) return lo;
  const double x0 = lo, base = cumulative_[i];
  const double u = lo + (hi - lo) * (s - base) / span_len;
  // L(u) - s increases with u (derivative: the speed); bracketed Newton stops at |L(u) - s| <= tol.
  return newton::solve_bracketed(
      [&](double x, double& dL) {
        dL = Integrand<Dim>{curve_, weight_}(x);
        return base + integrate(x0, x) - s;
      },
      lo, hi, -1, u, 4e-16 * (std::abs(lo) + std::abs(hi) + (hi - lo)), tol_, 200);
}

template <int Dim>
double arc_length(const BSplineCurve<Dim>& curve, double a, double b, double rel_tol) {
  require(a <= b, "arc length needs a <= b, got a = " + format_number(a) + ", b = " + format_number(b));
  a = curve.check_param(a);
  if (b != curve.last_param()) b = curve.check_param(b);  // a periodic curve would wrap its end to the start
  if (a == b) return 0;
  double abs_tol;
  const std::vector<double> len =
      span_lengths(Integrand<Dim>{curve, nullptr}, span_breaks(curve, a, b), rel_tol, abs_tol);
  double sum = 0;
  for (double l : len) sum += l;
  return sum;
}

template <int Dim>
double arc_length(const BSplineCurve<Dim>& curve, double rel_tol) {
  return ArcLength<Dim>(curve, rel_tol).total();
}

template <int Dim>
double param_at_arc_length(const BSplineCurve<Dim>& curve, double u0, double s, double rel_tol) {
  const ArcLength<Dim> table(curve, rel_tol);
  return table.param_at(table.length_to(u0) + s);
}

template class ArcLength<1>;
template class ArcLength<2>;
template class ArcLength<3>;
#define CG_ARC_LENGTH_INSTANTIATE(D)                                             \
  template double arc_length<D>(const BSplineCurve<D>&, double, double, double); \
  template double arc_length<D>(const BSplineCurve<D>&, double);                 \
  template double param_at_arc_length<D>(const BSplineCurve<D>&, double, double, double);
CG_ARC_LENGTH_INSTANTIATE(1)
CG_ARC_LENGTH_INSTANTIATE(2)
CG_ARC_LENGTH_INSTANTIATE(3)

}  // namespace cg
