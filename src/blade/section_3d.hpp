#pragma once
// 3D section curves of the blade (internal to the blade model): the 2D section curve placed in space,
// exactly where the placement is affine and by interpolation to a stated tolerance where it is not.
#include <Eigen/Core>
#include <functional>

#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

/// The 2D curve in the plane z = const: (a, b) -> (a, b, z). Exact (same knots and weights).
BSplineCurve<3> section_in_plane(const BSplineCurve<2>& curve, double z);

struct MappedSection {
  BSplineCurve<3> curve;
  double max_error = 0;  // largest |curve(u) - F(C(u))| at the check parameters, mm
  int subdivisions = 0;  // intervals per knot span of the 2D curve
};

/// A closed 2D curve C mapped by a smooth non-linear F (a, b) -> R^3 (a stream-surface placement):
/// F o C is not a NURBS, so it is interpolated by a periodic cubic through F(C(t)) at the knots of C,
/// each knot span cut into m equal intervals (the interpolant has the same parameter as C, so C's LE at
/// u = 0 and every knot of C stay where they are). The error is checked against F o C at 1/4, 1/2 and
/// 3/4 of every interval; m doubles (starting with at least min_points points per period) until it is
/// <= tol (F o C is smooth inside a span of C: cubic interpolation error ~ h^4, so this converges).
/// Throws AlgorithmFailure if 4096 intervals per span do not reach tol.
MappedSection map_closed_section(const BSplineCurve<2>& curve,
                                 const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& F, double tol,
                                 int min_points);

}  // namespace cg::blade::detail
