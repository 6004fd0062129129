#pragma once
// 3D section curves of the blade (internal to the blade model): the 2D section curve placed in a plane,
// exactly. (Placements that are not affine, on stream surfaces, are fitted: wall_fit.hpp.)
#include <Eigen/Core>

#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

/// The 2D curve in the plane z = const: (a, b) -> (a, b, z). Exact (same knots and weights).
BSplineCurve<3> section_in_plane(const BSplineCurve<2>& curve, double z);

}  // namespace cg::blade::detail
