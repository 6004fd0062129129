#include "src/algo/self_intersect_loops.hpp"

#include <algorithm>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

std::vector<ParamInterval> loop_intervals(const std::vector<SelfIntersection>& points) {
  std::vector<ParamInterval> loops;
  loops.reserve(points.size());
  for (const auto& p : points) loops.push_back({std::min(p.s1, p.s2), std::max(p.s1, p.s2)});
  // By start, and for equal starts the outermost loop first.
  std::sort(loops.begin(), loops.end(), [](const ParamInterval& a, const ParamInterval& b) {
    return a.lo < b.lo || (a.lo == b.lo && a.hi > b.hi);
  });
  std::vector<ParamInterval> cut;
  for (const auto& l : loops) {
    if (!cut.empty() && l.lo < cut.back().hi) continue;  // starts inside a loop already cut
    cut.push_back(l);
  }
  return cut;
}

std::vector<ParamInterval> kept_intervals(double first, double last, const std::vector<SelfIntersection>& points) {
  require(first < last, "kept_intervals: first parameter " + format_number(first) + " must be below last " +
                            format_number(last));
  std::vector<ParamInterval> kept;
  double start = first;
  for (const auto& l : loop_intervals(points)) {
    const double lo = std::max(l.lo, first), hi = std::min(l.hi, last);
    if (hi <= lo) continue;
    if (lo > start) kept.push_back({start, lo});
    start = std::max(start, hi);
  }
  if (last > start) kept.push_back({start, last});
  return kept;
}

}  // namespace cg
