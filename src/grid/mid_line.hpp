#pragma once
// The mid-line of a blade section across its passage (internal to the cascade grid, section_grid.hpp):
// b(a) halfway between the section's two sides, from the midpoints of the cuts a = const (exact
// line-curve intersections, src/algo/ray_curve.hpp), smoothed by a least-squares cubic with 6 poles (The
// NURBS Book 9.4.1) and continued by its end tangents outside the section's extent. The periodic lines of
// the cascade are this line shifted by +-pitch/2 along b.
#include "src/core/bspline_curve.hpp"

namespace cg::grid::detail {

class MidLine {
 public:
  /// Throws InvalidGeometry when fewer than 8 cuts in (a_min, a_max) meet the section twice.
  MidLine(const BSplineCurve<2>& wall, double a_min, double a_max);
  /// b of the mid-line at a (any a).
  double y(double a) const;

 private:
  BSplineCurve<1> fit_;
  double lo_ = 0, hi_ = 0;
};

}  // namespace cg::grid::detail
