#pragma once
// Batched surface evaluation with a per-patch cache: each knot patch is converted once to a
// bivariate polynomial in local parameters (s, t) in [-1, 1]^2 about the patch centre (mixed Taylor
// coefficients of the homogeneous surface), then each point costs (p+1)(q+1) fused multiply-adds per
// coordinate. One evaluator per thread; the surface must outlive the evaluator.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "src/core/bspline_surface.hpp"

namespace cg {

template <int Dim>
class SurfaceEvaluator {
 public:
  using Point = typename BSplineSurface<Dim>::Point;
  using HPoint = typename BSplineSurface<Dim>::HPoint;

  explicit SurfaceEvaluator(const BSplineSurface<Dim>& surface);

  Point point(double u, double v);
  /// Point and first partials S_u, S_v.
  void d1(double u, double v, Point& P, Point& Su, Point& Sv);
  /// uv holds n (u, v) pairs.
  void points(const double* uv, std::size_t n, Point* P);

 private:
  const double* locate(double& u, double& v, double& su, double& sv);
  void build_patch(int iu, int iv);

  const BSplineSurface<Dim>* s_;
  int pu_, pv_, nspan_u_, nspan_v_;
  std::vector<double> coeffs_;  // per patch: (pu+1) x (pv+1) x (Dim+1), index (k*(pv+1)+l)*(Dim+1)
  std::vector<unsigned char> built_;
  int cu_ = -1, cv_ = -1;  // current spans
  double ulo_ = 0, uhi_ = -1, vlo_ = 0, vhi_ = -1, umid_ = 0, vmid_ = 0, uscale_ = 0, vscale_ = 0;
};

extern template class SurfaceEvaluator<1>;
extern template class SurfaceEvaluator<2>;
extern template class SurfaceEvaluator<3>;

}  // namespace cg
