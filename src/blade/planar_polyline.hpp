#pragma once
// Segment intersection tests on sampled planar curves (internal to the blade model): used to find
// crossing streamlines, candidate cuts of stations with streamlines and self-intersecting sections.
#include <Eigen/Core>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

struct SegmentHit {
  int i = 0, j = 0;    // segment indices in the first and second polyline
  double s = 0, t = 0; // local parameters in [0, 1] on each segment
};

/// Intersection of segments [a0, a1] and [b0, b1]: local parameters s, t in [-eps, 1 + eps]
/// (eps widens the test so a cut exactly at a sample point is not missed). Parallel segments never hit.
bool segment_intersection(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                          const Eigen::Vector2d& b1, double eps, double& s, double& t);

/// All crossings between the polylines a and b (O(n m) with bounding-box rejection).
std::vector<SegmentHit> polyline_crossings(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b,
                                           double eps);

/// True when no two non-adjacent edges of the closed polygon (last point joined to the first) intersect;
/// otherwise writes the first offending edge pair to edge_a, edge_b.
bool polygon_is_simple(const std::vector<Eigen::Vector2d>& points, int& edge_a, int& edge_b);

/// Signed area of the closed polygon (last point joined to the first): > 0 when counter-clockwise.
double polygon_signed_area(const std::vector<Eigen::Vector2d>& points);

/// Parameters sampling the curve with `per_span` points per non-empty knot span (ends included).
std::vector<double> sample_params(const BSplineCurve<2>& curve, int per_span);

}  // namespace cg::blade::detail
