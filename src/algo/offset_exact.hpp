#pragma once
// Exact pointwise offset of a planar curve and the parameters where it stops being a smooth
// image of the base curve (cusps and tangent corners).
//
// Sign convention: O(u) = C(u) + d N(u) with N the LEFT unit normal (the unit tangent turned by
// +90 deg). d > 0 offsets to the left of the direction of travel: inward for a counter-clockwise
// closed curve, outward for a clockwise one.
//
// With the signed curvature k = (C' x C'') / |C'|^3 (positive when turning left), N' = -k C', so
//   O'(u) = (1 - d k(u)) C'(u)
// (The NURBS Book 11.1 / Farouki & Neff 1990). g = 1 - d k is the speed ratio: the offset runs
// parallel to the base where g > 0, reversed where g < 0, and has a cusp where g = 0, i.e. where the
// radius of curvature equals |d| on the side of the offset.
#include <Eigen/Core>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/curve_evaluator.hpp"

namespace cg {

/// Evaluates O(u) = C(u) + d N(u) and O'(u) without heap allocation (span-cached base evaluator).
/// Throws InvalidGeometry where the base tangent vanishes (the normal is undefined there).
class ExactOffset {
 public:
  /// Keeps its own copy of `base` (through the evaluator); one ExactOffset per thread.
  ExactOffset(const Curve2& base, double distance);

  const Curve2& base() const { return ev_.curve(); }
  double distance() const { return d_; }

  /// Offset point. side = -1 takes the one-sided limit from the left (needed at a knot where the
  /// base tangent jumps; the evaluator otherwise uses the span to the right of a knot).
  Eigen::Vector2d point(double u, int side = +1);
  /// Offset point and first derivative O' = (1 - d k) C'.
  void d1(double u, Eigen::Vector2d& P, Eigen::Vector2d& D1, int side = +1);
  /// Speed ratio g(u) = 1 - d k(u) (see the header comment).
  double speed_ratio(double u, int side = +1);
  /// Left unit normal of the base curve.
  Eigen::Vector2d normal(double u, int side = +1);

 private:
  struct Local {
    Eigen::Vector2d C, C1, C2;
  };
  Local eval(double u, int side);
  double d_;
  CurveEvaluator<2> ev_;
};

/// Where the raw offset breaks: every distinct knot of the base, the cusps (g = 0) and, at knots
/// where the base tangent direction jumps (C0 corners, including the seam of a closed curve), a
/// circular arc of radius |d| about the corner that joins the two one-sided offsets (the locus of
/// points at distance |d| from a corner is that arc; on the concave side it forms a loop that loop
/// trimming removes, as BRepOffsetAPI_MakeOffset's arc join does).
struct OffsetBreakpoints {
  /// Sorted parameters from first to last (both included); pieces of the raw offset are the
  /// intervals between consecutive entries.
  std::vector<double> params;
  /// Indices into params of the cusps: g changes sign inside a span, or across a knot where the
  /// curvature of a C1 base jumps.
  std::vector<int> cusps;
  /// Corner arcs: index into params, and the turning angle (radians, signed, |angle| < pi) from
  /// the left-limit normal to the right-limit normal.
  struct Corner {
    int index;
    double angle;
  };
  std::vector<Corner> corners;
  /// True when the base is closed (periodic, or its ends coincide within 1e-9 of its size).
  bool closed = false;
};

/// Breakpoints of the offset of `base` by d. Cusps are located by sampling g on every knot span
/// (12 + 4 p samples) and bisecting its sign changes to machine precision; corners are knots whose
/// one-sided tangents differ by more than `corner_angle` radians.
OffsetBreakpoints offset_breakpoints(const Curve2& base, double distance, double corner_angle = 1e-9);

}  // namespace cg
