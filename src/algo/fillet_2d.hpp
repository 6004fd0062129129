#pragma once
// Planar fillets: the circle of radius r tangent to two curves near their corner, its exact arc and
// the input curves trimmed at the tangent points.
//
// Method: the centre of a circle of radius r tangent to a curve on its side s lies on the offset of
// the curve by s r (offset_exact.hpp convention: s = +1 is the left of the tangent). The offsets of
// both curves are approximated (approximate_raw_offset) and intersected (intersect_curves); each
// crossing is refined by Newton's method on the exact offsets, E1(u1) = E2(u2) with
// dE/du = (1 - s r k) C' (quadratic convergence, centre exact to rounding). Candidates are tried by
// distance from the corner: a candidate is the fillet when the circle touches each curve at its
// global closest point (CurveProjector: the circle does not cut either curve) inside the curve. The
// tangent points are the feet of the centre, the arc is a rational quadratic (fillet_arc.hpp).
#include <Eigen/Core>
#include <string>

#include "src/core/bspline_curve.hpp"

namespace cg {

struct Fillet2d {
  bool found = false;
  std::string reason;  ///< why no fillet exists (found = false)
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
  double param1 = 0, param2 = 0;  ///< tangent points: c1(param1), c2(param2)
  Eigen::Vector2d point1 = Eigen::Vector2d::Zero(), point2 = Eigen::Vector2d::Zero();
  Curve2 arc;       ///< exact arc from point1 to point2 (the short way, sweep < 180 deg), on [0, 1]
  Curve2 trimmed1;  ///< the part of c1 on the far side of param1 from the corner
  Curve2 trimmed2;  ///< the part of c2 on the far side of param2 from the corner
};

/// Fillet of radius r between c1 and c2 near `corner` (their meeting or crossing point, or a point
/// near it): the centre lies on side1 of c1 and side2 of c2 (+1: left of the curve's tangent,
/// -1: right); among the circles with that property the one whose centre is nearest to `corner` is
/// taken. Each curve is trimmed at its tangent point, keeping the part away from the corner (the
/// corner's own foot on the curve decides the side). Throws InvalidGeometry unless r > 0 and
/// side1, side2 are +-1; returns found = false with a reason when no such fillet exists.
Fillet2d fillet_2d(const Curve2& c1, const Curve2& c2, double radius, int side1, int side2,
                   const Eigen::Vector2d& corner);

/// Fillet at the corner of a chain: c1 ends where c2 starts (within 1e-9 of their size, else
/// InvalidGeometry). The fillet lies inside the corner (on the side toward which the chain turns);
/// trimmed1 runs from the start of c1 to the fillet, trimmed2 from the fillet to the end of c2, so
/// trimmed1, arc, trimmed2 form a G1 chain. found = false for a tangent-continuous join.
Fillet2d fillet_corner_2d(const Curve2& c1, const Curve2& c2, double radius);

}  // namespace cg
