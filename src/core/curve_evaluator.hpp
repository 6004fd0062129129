#pragma once
// Batched curve evaluation with a per-span cache (the idea of SISL's span hint and OCCT's
// BSplCLib_Cache): each knot span is converted once to a polynomial in the local parameter
// t = (u - mid) / half in [-1, 1] (Taylor coefficients of the homogeneous curve at the span
// midpoint), then every point costs one Horner pass. Centring halves the coefficient growth of
// an expansion at the span start, which keeps the result within a few ulps of de Boor.
//
// Ownership and threads: the evaluator shares ownership of an immutable copy of its curve (built from
// a const reference it copies the curve once; from a shared_ptr it shares it), so it never dangles.
// Evaluation mutates the span cache: one evaluator per thread. A copy is an independent evaluator.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

template <int Dim>
class CurveEvaluator {
 public:
  using Point = typename BSplineCurve<Dim>::Point;
  using HPoint = typename BSplineCurve<Dim>::HPoint;

  explicit CurveEvaluator(const BSplineCurve<Dim>& curve);
  explicit CurveEvaluator(std::shared_ptr<const BSplineCurve<Dim>> curve);

  Point point(double u);
  void d1(double u, Point& P, Point& D1);
  void d2(double u, Point& P, Point& D1, Point& D2);

  /// Batched forms: parameters in any order; sorted parameters reuse the span without a search.
  void points(const double* u, std::size_t n, Point* P);
  void points_d1(const double* u, std::size_t n, Point* P, Point* D1);
  void points_d2(const double* u, std::size_t n, Point* P, Point* D1, Point* D2);
  std::vector<Point> points(const std::vector<double>& u);

  const BSplineCurve<Dim>& curve() const { return *curve_; }

 private:
  // Moves the current span to the one containing u (wrapping u for periodic curves, throwing when
  // u is outside the domain) and builds its coefficients on first use. The slow path of eval_batch.
  void relocate(double& u);
  void build_span(int span);
  // The hot loop: derivatives up to Order at n parameters, degree fixed at compile time for P >= 1
  // (P = 0: runtime degree). Unused outputs may be null.
  template <int P, int Order>
  void eval_batch(const double* u, std::size_t n, Point* P0, Point* D1, Point* D2);
  template <int Order>
  void dispatch(const double* u, std::size_t n, Point* P0, Point* D1, Point* D2);

  std::shared_ptr<const BSplineCurve<Dim>> curve_;
  int p_, n_;
  bool rational_, periodic_;
  double first_, last_, eps_;
  SpanTable spans_;
  std::vector<double> coeffs_;  // per span (span - p): (p+1) x (Dim+1)
  std::vector<unsigned char> built_;
  int span_ = -1;
  // Current span (u in [lo, hi) maps to t = (u - mid) * scale), coefficients at coeffs_[cur_]
  // (an offset, not a pointer, so a copied evaluator stays valid).
  SpanTable::Span sp_{0.0, -1.0, 0.0, 0.0};
  std::size_t cur_ = 0;
};

extern template class CurveEvaluator<1>;
extern template class CurveEvaluator<2>;
extern template class CurveEvaluator<3>;

}  // namespace cg
