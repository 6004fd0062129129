#pragma once
// NURBS approximation of the exact (untrimmed) offset of a planar curve within a tolerance.
//
// Method: the raw offset is cut at the breakpoints of offset_breakpoints (cusps and tangent corners;
// a corner contributes an exact circular arc). On each remaining stretch the offset O(u) is smooth
// except at the base knots, where it is C^(k-1) for a C^k base, so the fit keeps those knots as
// breakpoints with the matching multiplicity. The fit is a least-squares B-spline in the base
// parameter (fit_least_squares, The NURBS Book 9.4.1) of degree max(p, 3); it is then VERIFIED by a
// bound: on every knot span, |F(u) - O(u)| (which bounds the distance between the two curves) is at
// most its value at the ends of short intervals plus sqrt(2) h^2 / 8 times a bound of |F'' - O''|
// from the convex hulls of the Bézier forms of F and of the base on each interval (see
// offset_approximate.cpp, verified_span_error); intervals are bisected until the bound is <= tol, and
// a span whose sampled error exceeds tol / 2 is halved by a new knot and the fit repeated (Tiller &
// Hanson 1984 / Piegl & Tiller 1999 "Computing offsets of NURBS curves and surfaces").
#include <vector>

#include "src/algo/offset_exact.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg {

/// A fitted stretch of an offset: curve parametrised by the base parameter on [u0, u1].
struct OffsetFit {
  Curve2 curve;
  double error = 0;  ///< a proven upper bound of |F(u) - O(u)| over [u0, u1] (<= the tolerance)
};

/// Fits the exact offset on [u0, u1] (a stretch without cusp or corner inside) within tol.
/// The end points are the exact offset points (O(u1) taken as the left limit). Throws
/// InvalidGeometry unless u0 < u1 lie in the base domain and tol > 0; AlgorithmFailure when 40
/// refinement rounds do not reach tol (tol below the rounding level of the curve).
OffsetFit fit_offset_stretch(ExactOffset& offset, double u0, double u1, double tol);

/// One piece of the raw offset.
struct RawOffsetPiece {
  enum class Kind { offset, corner_arc };
  Kind kind = Kind::offset;
  /// offset: base interval of the stretch; corner_arc: u0 = u1 = the corner's base parameter.
  double u0 = 0, u1 = 0;
  /// corner_arc: polar angle of the arc start about the corner point and signed sweep (radians).
  double start_angle = 0, sweep = 0;
  /// offset: parametrised by the base parameter on [u0, u1]; corner_arc: exact arc on [0, 1].
  Curve2 curve;
  double error = 0;
};

/// The raw (untrimmed) offset: pieces in the order of the base curve; consecutive pieces join end
/// to start (and the last to the first when closed). It may contain cusps and loops.
struct RawOffset {
  double distance = 0;
  bool closed = false;
  std::vector<RawOffsetPiece> pieces;
  std::vector<double> cusps;  ///< base parameters of the cusps (joints between pieces)
  double max_error = 0;
};

/// Raw offset of `base` by the signed distance d (d > 0: to the left of the tangent, see
/// offset_exact.hpp) within tol. Throws InvalidGeometry for an empty or non-regular base,
/// d == 0 or tol <= 0.
RawOffset approximate_raw_offset(const Curve2& base, double distance, double tol);

}  // namespace cg
