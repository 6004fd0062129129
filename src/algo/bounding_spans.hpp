#pragma once
// Per-span Bézier pieces of B-spline curves and surfaces and the axis-aligned boxes of their poles.
//
// A knot span of a NURBS curve with positive weights lies in the convex hull of its p+1 Cartesian
// Bézier poles (strong convex hull property, The NURBS Book 4.2 P4.3 after decomposition 5.6), so the
// box of those poles bounds the span; the same holds for the (p+1)(q+1) poles of a surface patch.
// Subdividing a piece (de Casteljau, The NURBS Book A1.5) tightens the bound quadratically.
// These helpers are the common ground of projection, ray casting and curve-curve intersection; the
// Bézier kernels themselves (span conversion, de Casteljau) are the shared ones of src/core/bezier_ops.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "src/core/bezier_ops.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// Axis-aligned box; empty (lo > hi) until a point is added.
template <int Dim>
struct BoundingBox {
  using Point = Eigen::Matrix<double, Dim, 1>;
  Point lo = Point::Constant(std::numeric_limits<double>::infinity());
  Point hi = Point::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return !(lo.array() <= hi.array()).all(); }
  void add(const Point& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const BoundingBox& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
  /// Euclidean distance from p to the box (0 inside): a lower bound of the distance from p to anything
  /// the box contains.
  double distance(const Point& p) const {
    return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).norm();
  }
  bool overlaps(const BoundingBox& b, double tol = 0.0) const {
    return ((lo.array() - tol) <= b.hi.array()).all() && ((b.lo.array() - tol) <= hi.array()).all();
  }
  /// Clips the ray/line o + s d, s in [s0, s1], to the box (slab method). Returns false when the
  /// clipped interval is empty; otherwise narrows [s0, s1] to the part inside the box grown by tol.
  bool clip_ray(const Point& o, const Point& d, double& s0, double& s1, double tol = 0.0) const;
};

/// Box of the Cartesian points of `count` homogeneous poles stored consecutively (Dim+1 doubles each).
template <int Dim>
BoundingBox<Dim> homogeneous_pole_box(const double* hpoles, int count);

/// One non-empty knot span of a curve as a rational Bézier piece.
template <int Dim>
struct CurveBezierSpan {
  double a = 0, b = 0;  // parameter interval of the span
  int span = 0;         // knot span index (U[span] = a)
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> hpoles;  // p+1 homogeneous Bézier poles
  BoundingBox<Dim> box;                                   // box of the Cartesian Bézier poles
};

/// Bézier decomposition of every non-empty span of the curve's domain, in parameter order.
template <int Dim>
std::vector<CurveBezierSpan<Dim>> curve_bezier_spans(const BSplineCurve<Dim>& curve);

/// Per-span boxes of the Bézier poles (tighter than the boxes of the p+1 B-spline poles), in order.
template <int Dim>
std::vector<BoundingBox<Dim>> curve_span_boxes(const BSplineCurve<Dim>& curve);

/// One non-empty knot patch [u0, u1] x [v0, v1] of a surface as a rational tensor Bézier patch.
template <int Dim>
struct SurfaceBezierPatch {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  int span_u = 0, span_v = 0;
  /// (pu+1)(pv+1) homogeneous poles, pole (k, l) in column k * (pv+1) + l.
  Eigen::Matrix<double, Dim + 1, Eigen::Dynamic> hpoles;
  BoundingBox<Dim> box;
};

/// Bézier decomposition of every non-empty patch of the surface's domain (u-major order).
template <int Dim>
std::vector<SurfaceBezierPatch<Dim>> surface_bezier_patches(const BSplineSurface<Dim>& surface);

/// Per-patch boxes of the Bézier poles, in the order of surface_bezier_patches.
template <int Dim>
std::vector<BoundingBox<Dim>> surface_patch_boxes(const BSplineSurface<Dim>& surface);

extern template struct BoundingBox<1>;
extern template struct BoundingBox<2>;
extern template struct BoundingBox<3>;

}  // namespace cg
