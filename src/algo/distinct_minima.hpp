#pragma once
// Shared by the curve and surface projectors: several candidates may describe one minimum (found from
// neighbouring spans/patches), and a point may have several equal global minima (a circle's centre).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace cg::detail {

/// Sorts candidates (fields `dist`, `point`) by distance and moves to the front one representative per
/// minimum among those with dist <= limit: a candidate joins an already kept one when their points lie
/// within merge_tol. Returns the number kept (>= 1 when cands is non-empty and cands' best <= limit).
template <class Candidate>
std::size_t keep_distinct_minima(std::vector<Candidate>& cands, double limit, double merge_tol) {
  std::sort(cands.begin(), cands.end(), [](const Candidate& x, const Candidate& y) { return x.dist < y.dist; });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cands.size() && cands[i].dist <= limit; ++i) {
    bool dup = false;
    for (std::size_t j = 0; j < kept && !dup; ++j) dup = (cands[i].point - cands[j].point).norm() <= merge_tol;
    if (!dup) cands[kept++] = cands[i];
  }
  return kept;
}

}  // namespace cg::detail
