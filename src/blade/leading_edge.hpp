#pragma once
// Leading and trailing edge of a closed blade section given by points, by the cascade convention of
// the section's edge circles: the chord line joins the centres of the leading- and trailing-edge
// circles, the LE and TE are the points where that line leaves the profile, and the chord is
// |LE - TE|. (NASA CR-168015 states the C3X stagger, 59.89 deg, for this line; the fitted centres give
// 59.90 deg.)
//
// Why not "LE = the point farthest from the TE": on strongly cambered, blunt vanes the suction side
// bulges beyond the nose circle, and the farthest point lies on that bulge (C3X: 19 mm from the nose
// apex, chord 146.7 mm instead of 144.9 mm), as does the extreme point along the chord line.
#include <Eigen/Core>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg::blade {

/// A circle fitted to one edge of a section.
struct EdgeCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
};

/// Least-squares circle through points (>= 3): Kasa's algebraic fit, then Gauss-Newton on the geometric
/// distances |p - centre| - R.
EdgeCircle fit_circle(const std::vector<Eigen::Vector2d>& points);

struct LeadingTrailingEdge {
  double le_param = 0;
  double te_param = 0;
  EdgeCircle le_circle, te_circle;
};

/// LE/TE of a closed (periodic) section curve:
///  1. the ends: the two samples (16 per knot span) farthest apart; the TE end is the thinner one (width
///     across that extent within 5 % of it from the end), as the TE circle is the smaller one;
///  2. each edge circle: around each end (samples within 30 % of the extent), the stretch of curve whose
///     tangent turns by 60 deg over the shortest arc length (the smallest mean radius of curvature,
///     i.e. the edge circle) gets a least-squares circle (Kasa's algebraic fit, then Gauss-Newton on
///     the geometric distances);
///  3. LE and TE: the outermost roots of n . (C(u) - centre) = 0 on the line through both centres (exact
///     Bernstein root isolation + Newton, src/algo/ray_curve.hpp).
/// Throws InvalidGeometry for a non-periodic curve; AlgorithmFailure if the line does not cross the
/// profile beyond both centres (not a blade-like section).
LeadingTrailingEdge detect_leading_trailing_edge(const BSplineCurve<2>& closed_curve);

/// Step 3 alone, for known edge circles: LE and TE where the line through both centres leaves the
/// profile. Throws AlgorithmFailure as above.
LeadingTrailingEdge edge_points(const BSplineCurve<2>& closed_curve, const EdgeCircle& le, const EdgeCircle& te);

}  // namespace cg::blade
