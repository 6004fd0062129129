#pragma once
// Planar rational Bézier pieces for subdivision-based curve intersection: Bézier decomposition of a
// 2D NURBS curve, de Casteljau sub-ranges, bounding boxes, tangent-direction cones and fat-line
// clipping (Sederberg & Nishita, "Curve intersection using Bézier clipping", CAD 22(9), 1990).
//
// A piece keeps its homogeneous poles (w*x, w*y, w) in a fixed-size array, so the recursion never
// allocates, and the global parameter range [lo, hi] of the curve it came from.
#include <Eigen/Core>
#include <cstring>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg::detail {

struct BezierPiece2 {
  int degree = 0;
  double lo = 0.0, hi = 0.0;  // global curve parameters of local 0 and 1
  double h[kMaxDegree + 1][3];  // homogeneous poles; rows beyond `degree` are unused (not copied)

  BezierPiece2() = default;
  BezierPiece2(const BezierPiece2& o) { assign(o); }
  BezierPiece2& operator=(const BezierPiece2& o) {
    assign(o);
    return *this;
  }
  void assign(const BezierPiece2& o) {
    degree = o.degree;
    lo = o.lo;
    hi = o.hi;
    std::memcpy(h, o.h, sizeof(double) * 3 * static_cast<std::size_t>(o.degree + 1));
  }

  double x(int i) const { return h[i][0] / h[i][2]; }
  double y(int i) const { return h[i][1] / h[i][2]; }
  Eigen::Vector2d pole(int i) const { return {x(i), y(i)}; }
  double param(double local) const { return lo + local * (hi - lo); }
};

/// The rational Bézier segments of every non-empty knot span of `curve` (periodic curves: one period),
/// with their global parameter ranges, written straight into the fixed-size pieces by the shared span
/// conversion (span_bezier_poles, src/core/bezier_ops.hpp) without allocating.
std::vector<BezierPiece2> bezier_pieces(const BSplineCurve<2>& curve);

/// Keeps the local sub-range [a, b] of the piece (0 <= a < b <= 1) (restrict_bezier).
void restrict_piece(BezierPiece2& piece, double a, double b);
/// Splits at local 1/2 (split_bezier): `left` receives [lo, mid], `right` [mid, hi], sharing the exact
/// mid value.
void halve_piece(const BezierPiece2& piece, BezierPiece2& left, BezierPiece2& right);

struct Box2 {
  double x0, y0, x1, y1;
  double diagonal() const;
  bool overlaps(const Box2& o, double margin) const {
    return x0 <= o.x1 + margin && o.x0 <= x1 + margin && y0 <= o.y1 + margin && o.y0 <= y1 + margin;
  }
};
/// Box of the Cartesian poles: contains the piece (convex hull property, positive weights).
Box2 piece_box(const BezierPiece2& piece);

/// Angular interval [lo, hi] (radians, hi - lo < pi when `narrow`) containing every tangent direction
/// of the piece. The hodograph of a rational Bézier curve with positive weights is a non-negative
/// combination of the pole differences P_j - P_i (i < j), hence of consecutive differences, so the
/// cone of the control polygon's legs bounds it.
struct DirectionCone {
  bool narrow = false;
  double lo = 0.0, hi = 0.0;
};
DirectionCone piece_cone(const BezierPiece2& piece);
/// Cone of the control polygons of two pieces joined end to start (self-intersection junctions).
DirectionCone joined_cone(const BezierPiece2& first, const BezierPiece2& second);
/// True when no direction of cone a is parallel (either sense) to a direction of cone b: then two
/// pieces meet at most once (a second meeting point would need a common chord direction).
bool cones_separated(const DirectionCone& a, const DirectionCone& b);

/// Local parameter range [a, b] of `target` that can lie within `margin` of the fat line of `line`
/// (the strip parallel to its end-to-end chord that contains its poles). Returns false when no part
/// can, i.e. the pieces cannot meet. Rational targets are clipped through the two polynomial
/// inequalities w(t) (d(t) - dmin) >= 0 and w(t) (dmax - d(t)) >= 0 on the homogeneous poles.
/// When `line` is degenerate (all poles coincide) the full range is returned.
bool clip_by_fat_line(const BezierPiece2& line, const BezierPiece2& target, double margin, double& a, double& b);

}  // namespace cg::detail
