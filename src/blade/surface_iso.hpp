#pragma once
// Iso-parametric curves of a surface (internal to the blade model): the curve u -> S(u, v) at a fixed v,
// exact (The NURBS Book 5.4 / A3.5 applied to the pole columns: Q_i = sum_j N_j(v) Pw_ij in homogeneous
// form), with the surface's u degree, knots, weights and periodicity.
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::blade::detail {

/// v is checked against the surface's v domain (InvalidGeometry outside).
BSplineCurve<3> iso_curve_v(const BSplineSurface<3>& surface, double v);

}  // namespace cg::blade::detail
