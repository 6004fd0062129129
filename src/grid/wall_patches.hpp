#pragma once
// The exact wall-orthogonal continuation of a closed plane section curve: the curve is split into its
// rational Bezier segments (The NURBS Book A5.6, src/modify/bezier_decomposition.hpp) and each segment
// gets the orthogonal continuation of Lang & Schroecker 1999 (src/ortho/orthogonal_continuation.hpp):
// eq. (16)'s direction z~ (for the polynomial segments of interpolated sections s = 0 and z~ = D x_u has
// degree m - 1, so a cubic segment with a quadratic L gives a patch of degree (4, 1); rational segments get
// Lemma 4.2's degree) and the free polynomials L, Q of eq. (14) chosen for the grid:
//  - every line u = const of a patch is the straight normal segment x + n v g / (1 - v Q) (see
//    orthogonal_continuation.hpp), so the patch reaches thickness h(u) = g / (1 - Q) at v = 1;
//  - L and Q are fitted (linear least squares on their Bernstein coefficients) to h(u) = thickness, with
//    the end values fixed so that g = thickness and Q = 0 at both segment ends: the boundary lines of
//    neighbouring patches are then the same rational line, and the patches agree along every joint;
//  - all L are finally scaled by one common factor >= 1 so that h(u) >= thickness everywhere (grid nodes
//    at wall distance s <= thickness then lie inside every patch, v in [0, 1]).
// Grid nodes are patch points at v = v_at_distance(u, s): on the exact normal line through the wall
// point, exactly s away from the wall.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/ortho/orthogonal_continuation.hpp"

namespace cg::grid {

class WallPatches {
 public:
  /// `curve`: a closed (periodic or closed clamped), tangent-continuous plane curve; `thickness` > 0 in
  /// the curve's units; the patches lie on the outer side of the curve (the side away from the enclosed
  /// area). Throws InvalidGeometry for an open curve or a tangent discontinuity at a segment joint.
  WallPatches(const BSplineCurve<2>& curve, double thickness);

  const BSplineCurve<2>& curve() const { return curve_; }
  double thickness() const { return thickness_; }
  /// +1 when the outer side is the left of the curve's direction (a clockwise curve), -1 otherwise.
  double outer_side() const { return side_; }
  int size() const { return static_cast<int>(patches_.size()); }
  const ortho::OrthogonalContinuation& patch(int k) const { return patches_[static_cast<std::size_t>(k)]; }
  /// Segment k covers curve parameters [breaks[k], breaks[k+1]].
  const std::vector<double>& breaks() const { return breaks_; }

  /// Segment and local parameter t in [0, 1] of a curve parameter (wrapped into the period).
  std::pair<int, double> locate(double u) const;
  /// The patch point at curve parameter u and wall distance s in [0, thickness], on the outer side.
  Eigen::Vector2d point(double u, double s) const;
  /// Unit normal towards the outer side at curve parameter u.
  Eigen::Vector2d outer_normal(double u) const;

  /// Largest patch degree in u.
  int max_degree() const;
  /// Largest |h(u) / thickness - 1| of the fitted L, Q before the common scaling, on the fit samples.
  double thickness_fit_error() const { return fit_error_; }
  /// Largest deviation from 90 deg of the angle between x_u and x_v along the wall, from the patches'
  /// own surface derivatives at `samples_per_patch` points per patch.
  double max_wall_angle_deviation_deg(int samples_per_patch = 9) const;

 private:
  BSplineCurve<2> curve_;
  double thickness_ = 0, side_ = 1, fit_error_ = 0;
  std::vector<double> breaks_;
  std::vector<ortho::OrthogonalContinuation> patches_;
};

}  // namespace cg::grid
