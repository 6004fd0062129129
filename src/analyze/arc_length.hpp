#pragma once
// Arc length of B-spline curves and its inverse.
//
// Length: adaptive Gauss-Legendre quadrature of |C'(u)| on each knot span separately (the speed is
// smooth inside a span and only C^(p-k) across knots, so spans are the natural panels): a 10-point
// rule on a panel is compared with the sum over its two halves, halves are refined until they agree
// to the panel's share of the tolerance (Davis & Rabinowitz, Methods of Numerical Integration, 6.2).
// Inverse: Newton's method on L(u) - s with a bisection safeguard on the span that brackets s.
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

/// Arc length table of one curve: lengths of all knot spans, cumulated, so that length_to(u) and
/// param_at(s) only integrate inside one span. A value type: it owns a copy of its curve (so it never
/// dangles and may be copied), and every member is const and thread-safe.
///
/// With a weight w the table integrates w(C(u)) |C'(u)| instead of |C'(u)| (e.g. 1 / r for the
/// conformal meridional coordinate m' = integral dm / r); w must be smooth and positive on the curve.
template <int Dim>
class ArcLength {
 public:
  using Point = typename BSplineCurve<Dim>::Point;
  using Weight = double (*)(const Point&);

  /// rel_tol: relative accuracy of every length (>= 1e-15; default 1e-12 of the total length).
  explicit ArcLength(BSplineCurve<Dim> curve, double rel_tol = 1e-12, Weight weight = nullptr);
  /// The table on [a, b] (first <= a < b <= last of a non-periodic or periodic curve's base period).
  ArcLength(BSplineCurve<Dim> curve, double a, double b, double rel_tol = 1e-12, Weight weight = nullptr);

  const BSplineCurve<Dim>& curve() const { return curve_; }
  double first() const { return breaks_.front(); }
  double last() const { return breaks_.back(); }
  double total() const { return cumulative_.back(); }
  /// Length from first() to u (u clamped to [first(), last()] within 1e-12 of its length).
  double length_to(double u) const;
  /// Length between a and b (negative when b < a).
  double length(double a, double b) const { return length_to(b) - length_to(a); }
  /// Parameter u with length_to(u) = s, to |length_to(u) - s| <= rel_tol * total (or the parameter
  /// resolution). Throws InvalidGeometry when s is outside [0, total()].
  double param_at(double s) const;

 private:
  double integrate(double a, double b) const;
  BSplineCurve<Dim> curve_;
  Weight weight_ = nullptr;
  double tol_;                      // absolute tolerance (rel_tol * total)
  std::vector<double> breaks_;      // distinct knots in [first, last]
  std::vector<double> cumulative_;  // length from first to breaks_[i]
};

/// Length of the curve between parameters a and b (a <= b, both in the domain) to relative tolerance.
template <int Dim>
double arc_length(const BSplineCurve<Dim>& curve, double a, double b, double rel_tol = 1e-12);
/// Length of the whole curve.
template <int Dim>
double arc_length(const BSplineCurve<Dim>& curve, double rel_tol = 1e-12);
/// Parameter at arc length s measured from u0 (s in [0, arc_length(curve, u0, last)]).
template <int Dim>
double param_at_arc_length(const BSplineCurve<Dim>& curve, double u0, double s, double rel_tol = 1e-12);

extern template class ArcLength<1>;
extern template class ArcLength<2>;
extern template class ArcLength<3>;
#define CG_ARC_LENGTH_EXTERN(D)                                                         \
  extern template double arc_length<D>(const BSplineCurve<D>&, double, double, double); \
  extern template double arc_length<D>(const BSplineCurve<D>&, double);                 \
  extern template double param_at_arc_length<D>(const BSplineCurve<D>&, double, double, double);
CG_ARC_LENGTH_EXTERN(1)
CG_ARC_LENGTH_EXTERN(2)
CG_ARC_LENGTH_EXTERN(3)
#undef CG_ARC_LENGTH_EXTERN

}  // namespace cg
