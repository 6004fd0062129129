#pragma once
// Moving the seam of a periodic curve (internal to the blade model): blade sections are stored with
// the seam at the leading edge so that u = 0 is the LE on every section and on the skinned surface.
#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

/// The same closed curve, periodic with period 1 and its seam at the point C(u): a knot is inserted at u
/// (The NURBS Book A5.1, unless u already is a knot), the unwrapped pole/knot window is shifted so that
/// the period starts at that knot, and the parameter is mapped affinely so that C(u) is at 0. The shape
/// and the smoothness (C^(p-1) across the old and the new seam for simple knots) are unchanged.
/// Throws InvalidGeometry for a non-periodic curve.
template <int Dim>
BSplineCurve<Dim> with_seam_at(const BSplineCurve<Dim>& curve, double u);

extern template BSplineCurve<2> with_seam_at(const BSplineCurve<2>&, double);
extern template BSplineCurve<3> with_seam_at(const BSplineCurve<3>&, double);

}  // namespace cg::blade::detail
