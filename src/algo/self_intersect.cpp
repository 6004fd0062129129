#include "src/algo/self_intersect.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/algo/intersect_engine.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

SelfIntersections self_intersections(const BSplineCurve<2>& curve, double tol) {
  require(curve.num_poles() > 0, "self_intersections needs a non-empty curve");
  require(std::isfinite(tol) && tol > 0.0, "intersection tolerance " + format_number(tol) + " must be > 0");
  detail::CurvePairIntersector engine(curve, curve, tol, true);
  const auto& pieces = engine.pieces_a();
  std::vector<detail::Box2> boxes;
  boxes.reserve(pieces.size());
  for (const auto& pc : pieces) boxes.push_back(detail::piece_box(pc));
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    engine.self_intersect_piece(pieces[i]);
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      if (boxes[i].overlaps(boxes[j], tol)) engine.intersect_pieces(pieces[i], pieces[j]);
  }
  const CurveCurveIntersections r = engine.finish();
  SelfIntersections out;
  for (const auto& p : r.points) {
    SelfIntersection q{std::min(p.s, p.t), std::max(p.s, p.t), p.point, p.kind};
    out.points.push_back(q);
  }
  std::sort(out.points.begin(), out.points.end(),
            [](const SelfIntersection& a, const SelfIntersection& b) { return a.s1 < b.s1; });
  out.overlaps = r.overlaps;
  return out;
}

}  // namespace cg
