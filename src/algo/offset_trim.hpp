#pragma once
// Offset curves with loop trimming: the part of the offset of a planar curve whose points are at
// distance |d| from the WHOLE base curve.
//
// Method (after Farouki & Neff 1990; Seong, Elber & Kim 2006 "Trimming local and global
// self-intersections in offset curves"): the raw offset (approximate_raw_offset: fitted stretches
// between cusps, exact arcs at corners) is joined into one C0 NURBS R. Its self-intersections
// (self_intersections) and, for an open base, its crossings with the circles of radius |d| about the
// base end points (where the distance to the base stops being attained inside it) cut R into
// sub-arcs. On each sub-arc the distance to the base is either |d| everywhere or below |d| inside,
// so the exact offset point at its middle decides: kept when its global distance to the base
// (CurveProjector) is >= |d| - tol. Kept sub-arcs are linked into chains: at a crossing the chain
// turns onto the other branch (the kept halves of two crossing branches are the outer ones), and a
// chain closes when it comes back to its first sub-arc.
#include <string>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

/// One connected component of a trimmed offset: NURBS pieces joined end to start (the last to
/// the first when closed). Pieces are segments of the fitted raw offset; a piece may hold a G1
/// corner arc (convex corner of a C0 base) inside.
struct OffsetChain {
  std::vector<Curve2> pieces;
  bool closed = false;
};

struct TrimmedOffset {
  double distance = 0;
  std::vector<OffsetChain> chains;  ///< empty when nothing of the offset survives
  double max_error = 0;             ///< verified max distance of the fitted pieces to the exact offset
  int loops_removed = 0;            ///< number of rejected sub-arcs (local and global loops)
  std::string reason;               ///< why the result is empty
  bool empty() const { return chains.empty(); }
};

/// Trimmed offset of `base` by the signed distance d (d > 0: left of the tangent, see
/// offset_exact.hpp) within tol (> 0, model units): every point of the result lies within tol of a
/// point at distance exactly |d| from the base curve, and no loop remains. Throws InvalidGeometry
/// for an empty or non-regular base, d == 0 or tol <= 0.
TrimmedOffset offset_curve(const Curve2& base, double distance, double tol);

}  // namespace cg
