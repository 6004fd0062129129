#include "src/blade/section_3d.hpp"


namespace cg::blade::detail {

BSplineCurve<3> section_in_plane(const BSplineCurve<2>& c, double z) {
  const auto& h = c.homogeneous_poles();
  BSplineCurve<3>::HPoles g(4, h.cols());
  g.row(0) = h.row(0);
  g.row(1) = h.row(1);
  g.row(2) = z * h.row(2);  // homogeneous: w z
  g.row(3) = h.row(2);
  return BSplineCurve<3>::from_homogeneous(c.degree(), c.knots(), std::move(g), c.is_periodic());
}

}  // namespace cg::blade::detail
