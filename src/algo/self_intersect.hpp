#pragma once
// Self-intersections of a planar NURBS curve, by the engine of intersect_curves run on the curve's
// Bézier segments against each other: every pair of distinct segments, and each segment against
// itself (split until its tangent cone is narrower than pi, when it cannot loop). Consecutive pieces
// share an end point and a closed curve's start meets its end: those meetings (and contacts on an arc
// that never leaves a tiny ball, as at a cusp) are not self-intersections.
#include <Eigen/Core>
#include <vector>

#include "src/algo/intersect_curves.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg {

/// C(s1) = C(s2) = point with s1 < s2.
struct SelfIntersection {
  double s1 = 0.0;
  double s2 = 0.0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  ContactKind kind = ContactKind::transversal;
};

struct SelfIntersections {
  std::vector<SelfIntersection> points;      // sorted by s1
  std::vector<CurveCurveOverlap> overlaps;   // the curve retracing itself: [s0, s1] runs along [t0, t1]
};

/// All self-intersections of `curve` with distance tolerance tol (> 0, as in intersect_curves).
SelfIntersections self_intersections(const BSplineCurve<2>& curve, double tol = kIntersectionTolerance);

}  // namespace cg
