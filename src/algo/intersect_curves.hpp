#pragma once
// All intersections of two planar NURBS curves: transversal crossings, tangential contacts and
// overlapping (coincident) stretches.
//
// Method: Bézier decomposition of both curves, then per pair of Bézier segments a recursion that
// prunes by bounding boxes, clips by fat lines (Bézier clipping, Sederberg & Nishita 1990) and splits
// where clipping stalls. A pair whose tangent cones are separated holds at most one crossing
// (Sederberg & Meyers, "Loop detection in surface patch intersections", CAGD 5, 1988): it is solved
// by Newton on A(s) = B(t). Pruning uses only a rounding margin; a pair pruned by less than `tol` is
// searched for a tangential near-contact (the tangency system: parallel tangents, gap normal to them)
// and for curve ends or corners within `tol`. Pairs that shrink below the leaf size with overlapping
// cones solve the tangency system too: a contact is accepted when the gap is within `tol` and the
// curves do not cross on both sides of it. Stalled pairs whose one piece lies within `tol` of the
// other curve, with equal curvature, at 2(p+q)+3 samples are overlaps. Roots found by neighbouring
// pairs are merged.
#include <Eigen/Core>
#include <ostream>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

enum class ContactKind { transversal, tangent };

inline std::ostream& operator<<(std::ostream& os, ContactKind k) {
  return os << (k == ContactKind::tangent ? "tangent" : "transversal");
}

/// One isolated intersection: A(s) = B(t) = point.
struct CurveCurvePoint {
  double s = 0.0;
  double t = 0.0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  ContactKind kind = ContactKind::transversal;
};

/// A stretch where the curves coincide within the tolerance: A on [s0, s1] (s0 < s1) runs along B
/// from B(t0) to B(t1); t0 > t1 when the curves run in opposite senses.
struct CurveCurveOverlap {
  double s0 = 0.0, s1 = 0.0;
  double t0 = 0.0, t1 = 0.0;
};

struct CurveCurveIntersections {
  std::vector<CurveCurvePoint> points;       // sorted by s
  std::vector<CurveCurveOverlap> overlaps;   // sorted by s0, disjoint
};

/// Default distance tolerance: contacts and overlaps closer than this count as meeting.
constexpr double kIntersectionTolerance = 1e-9;

/// All intersections of a and b. `tol` (model units, > 0) is the gap below which a tangential
/// contact is reported and the distance within which stretches count as overlapping; crossings are
/// refined by Newton to rounding (parameters to ~1e-15 relative for transversal crossings).
/// Throws InvalidGeometry for empty curves or tol <= 0, AlgorithmFailure if the subdivision budget
/// (10^6 piece pairs) is exhausted.
CurveCurveIntersections intersect_curves(const BSplineCurve<2>& a, const BSplineCurve<2>& b,
                                         double tol = kIntersectionTolerance);

}  // namespace cg
