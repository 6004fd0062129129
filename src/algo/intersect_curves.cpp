#include "src/algo/intersect_curves.hpp"

#include <cmath>
#include <string>

#include "src/algo/intersect_engine.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

CurveCurveIntersections intersect_curves(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double tol) {
  require(a.num_poles() > 0 && b.num_poles() > 0, "intersect_curves needs two non-empty curves");
  require(std::isfinite(tol) && tol > 0.0, "intersection tolerance " + format_number(tol) + " must be > 0");
  detail::CurvePairIntersector engine(a, b, tol, false);
  const auto& pa = engine.pieces_a();
  const auto& pb = engine.pieces_b();
  std::vector<detail::Box2> boxes_b;
  boxes_b.reserve(pb.size());
  for (const auto& y : pb) boxes_b.push_back(detail::piece_box(y));
  for (const auto& x : pa) {
    const detail::Box2 bx = detail::piece_box(x);
    for (std::size_t j = 0; j < pb.size(); ++j)
      if (bx.overlaps(boxes_b[j], tol)) engine.intersect_pieces(x, pb[j]);
  }
  return engine.finish();
}

}  // namespace cg
