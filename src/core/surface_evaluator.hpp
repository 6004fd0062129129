#pragma once
// Batched surface evaluation with a per-patch cache: each knot patch is converted once to a
// bivariate polynomial in local parameters (s, t) in [-1, 1]^2 about the patch centre (mixed Taylor
// coefficients of the homogeneous surface), then each point costs (p+1)(q+1) fused multiply-adds per
// coordinate. Batched points() first contracts the patch in u to a polynomial in t and keeps it while
// u and the patch stay the same, so walking a grid row by row (u outer, v inner) costs (q+1)
// multiply-adds per point. Ownership and threads as CurveEvaluator: it shares ownership of an immutable
// copy of the surface (never dangles); evaluation mutates the cache, so one evaluator per thread.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

#include "src/core/bspline_surface.hpp"

namespace cg {

template <int Dim>
class SurfaceEvaluator {
 public:
  using Point = typename BSplineSurface<Dim>::Point;
  using HPoint = typename BSplineSurface<Dim>::HPoint;

  explicit SurfaceEvaluator(const BSplineSurface<Dim>& surface);
  explicit SurfaceEvaluator(std::shared_ptr<const BSplineSurface<Dim>> surface);
  const BSplineSurface<Dim>& surface() const { return *s_; }

  Point point(double u, double v);
  /// Point and first partials S_u, S_v.
  void d1(double u, double v, Point& P, Point& Su, Point& Sv);
  /// uv holds n (u, v) pairs.
  void points(const double* uv, std::size_t n, Point* P);

 private:
  // Moves the current patch to the one containing (u, v) (wrapping periodic directions, throwing
  // outside the domain) and builds its coefficients on first use.
  void relocate(double& u, double& v);
  void build_patch(int iu, int iv);
  // The hot loop of points(); degrees fixed at compile time for PU, PV >= 1 (0: runtime degrees).
  template <int PU, int PV>
  void eval_batch(const double* uv, std::size_t n, Point* P);

  std::shared_ptr<const BSplineSurface<Dim>> s_;
  int pu_, pv_, nspan_u_, nspan_v_;
  SpanTable spans_u_, spans_v_;
  std::vector<double> coeffs_;  // per patch: (pu+1) x (pv+1) x (Dim+1), index (k*(pv+1)+l)*(Dim+1)
  std::vector<unsigned char> built_;
  int cu_ = -1, cv_ = -1;  // current spans
  SpanTable::Span su_{0.0, -1.0, 0.0, 0.0}, sv_{0.0, -1.0, 0.0, 0.0};  // current span data
  std::size_t cur_ = 0;  // offset of the current patch's coefficients in coeffs_
};

extern template class SurfaceEvaluator<1>;
extern template class SurfaceEvaluator<2>;
extern template class SurfaceEvaluator<3>;

}  // namespace cg
