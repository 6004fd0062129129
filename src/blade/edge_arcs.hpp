#pragma once
// Leading- and trailing-edge circles of point sections (internal to the blade model; issue 8, item 2).
//
// Published profile tables often give an edge as three or four points on its circle, 10-16 mm apart;
// a spline through them sags inside the circle between the points (1.2 mm on a 12.8 mm LE radius). Here
// the run of consecutive given points lying on one circle around each edge is found (or the circle is
// taken from le_radius / le_centre hints), and the profile is rebuilt to follow that circle exactly
// between the outermost points of the run: a rational quadratic arc (The NURBS Book 7.5, A7.1; pieces of
// at most 90 deg), degree-elevated to cubic, joined tangent-continuously (G1) to cubic splines through
// the remaining points on either side (interpolation with the arc's end tangents, The NURBS Book 9.2.2).
// Between the last point on the circle and the next given point the true tangency is unknown; the arc
// is continued to where the tangent from that next point touches it (bounded, see profile_with_arcs).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "src/blade/leading_edge.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

/// Given points count as on a circle when within this distance of it (mm): tables in cm with four
/// decimals round by 5e-4 mm, in inches with four decimals by 1.3e-3 mm.
inline constexpr double kOnCircleTolerance = 0.005;
/// The profile follows a detected circle exactly (rational arc) when a spline through the run's points,
/// moved onto the circle, sags off it by more than this (mm) between them: the sag due to sparse
/// points, not to their scatter. Denser tables, whose spline already hugs the circle, are kept as they
/// are (so C3X stays exactly through its published points).
inline constexpr double kArcSagTolerance = 0.002;

struct EdgeCircleHint {
  double radius = 0;                       // mm, 0 = not given
  std::optional<Eigen::Vector2d> centre;   // mm, in the section's frame
  bool given() const { return radius > 0 || centre.has_value(); }
};

/// A run of consecutive points (indices first, first + 1, ..., first + count - 1, modulo the point
/// count) on one circle.
struct EdgeCircleRun {
  bool found = false;
  int first = 0, count = 0;
  EdgeCircle circle;
  double residual = 0;  // largest distance of a run point from the circle, mm
};

/// The longest run of consecutive points containing one within two points of `apex` and lying on one
/// circle within `tol` (grown greedily from every such 3-point seed):
/// without hints at least 4 points (any 3 points lie on a circle); with a radius hint at least 3 whose
/// circle has that radius (within tol); with a centre hint (and radius, or the apex's distance) at least
/// 2 points at that distance. A run leaves at least 4 points outside it.
/// Circles larger than max_radius (mm) are not edge circles (flat stretches of a side fit huge ones).
EdgeCircleRun find_edge_circle(const std::vector<Eigen::Vector2d>& points, int apex, const EdgeCircleHint& hint,
                               double max_radius, double tol = kOnCircleTolerance);

/// Largest distance of the curve from the circle between parameters a and b (a < b, the curve may be
/// periodic and b > its last parameter), sampled densely (64 samples per knot span).
double deviation_from_circle(const BSplineCurve<2>& curve, double a, double b, const EdgeCircle& circle);

/// The closed profile through `points` (in order, not repeated) in which each run is an exact circular
/// arc through the run's points, joined G1 to cubic splines through the other points. At each end the
/// arc continues past the run's outermost point towards the neighbouring given point, up to where the
/// tangent from that point touches the circle (where a side running on straight would leave it), but
/// by no more than the run's point spacing. Periodic, period 1, C0 knots (multiplicity 3) at the joins
/// and at the start (the first run's arc start). Runs must not overlap.
BSplineCurve<2> profile_with_arcs(const std::vector<Eigen::Vector2d>& points, const std::vector<EdgeCircleRun>& runs);

}  // namespace cg::blade::detail
