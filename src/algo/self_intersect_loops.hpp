#pragma once
// Untangling of nested self-intersection loops (used by offset-loop trimming): every self-intersection
// C(s1) = C(s2), s1 < s2, closes the loop C([s1, s2]). Cutting a loop removes every loop that starts
// inside it (nested loops, and loops interleaved with it, whose start point is gone), so the loops to
// cut are found greedily by increasing s1, each taken with its largest s2 (the outermost loop).
#include <vector>

#include "src/algo/self_intersect.hpp"

namespace cg {

struct ParamInterval {
  double lo = 0.0;
  double hi = 0.0;
};

/// Maximal loop intervals [s1, s2] to cut, sorted and disjoint (touching allowed).
std::vector<ParamInterval> loop_intervals(const std::vector<SelfIntersection>& points);

/// The parameter intervals of [first, last] that remain after cutting the maximal loops; consecutive
/// kept intervals join at the self-intersection points (C(lo of the next) = C(hi of the previous)).
/// Throws InvalidGeometry when first >= last.
std::vector<ParamInterval> kept_intervals(double first, double last, const std::vector<SelfIntersection>& points);

}  // namespace cg
