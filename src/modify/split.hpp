#pragma once
// Splitting a B-spline / NURBS curve and extracting a sub-curve; results are clamped, non-periodic.
#include <utility>

#include "src/core/bspline_curve.hpp"

namespace cg {

/// The pieces on [first, u] and [u, last]: u is raised to multiplicity p once (The NURBS Book A5.4), so
/// both pieces share the pole at C(u) exactly. A periodic curve is split on its base period (converted
/// to its clamped form first). Throws InvalidGeometry unless first < u < last.
template <int Dim>
std::pair<BSplineCurve<Dim>, BSplineCurve<Dim>> split(const BSplineCurve<Dim>& curve, double u);

/// The sub-curve on [a, b] with clamped ends, parametrised on [a, b] (as OCCT's Geom_BSplineCurve::Segment
/// with coincident knots matched exactly). Non-periodic: first <= a < b <= last (1e-12 of the domain
/// tolerated). Periodic: a anywhere, 0 < b - a <= period; the piece may cross the seam.
template <int Dim>
BSplineCurve<Dim> segment(const BSplineCurve<Dim>& curve, double a, double b);

#define CG_MODIFY_SPLIT_EXTERN(D)                                                                       \
  extern template std::pair<BSplineCurve<D>, BSplineCurve<D>> split(const BSplineCurve<D>&, double);   \
  extern template BSplineCurve<D> segment(const BSplineCurve<D>&, double, double);
CG_MODIFY_SPLIT_EXTERN(1)
CG_MODIFY_SPLIT_EXTERN(2)
CG_MODIFY_SPLIT_EXTERN(3)
#undef CG_MODIFY_SPLIT_EXTERN

}  // namespace cg
