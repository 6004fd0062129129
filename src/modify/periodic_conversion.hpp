#pragma once
// Exact conversion of periodic B-spline / NURBS curves and surfaces to clamped non-periodic ones.
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// The same curve on the base period [first, last] as a clamped non-periodic B-spline: the seam knot is
/// inserted to full multiplicity and the wrap-around poles are dropped (as OCCT's
/// Geom_BSplineCurve::SetNotPeriodic). A non-periodic curve is returned unchanged.
template <int Dim>
BSplineCurve<Dim> to_non_periodic(const BSplineCurve<Dim>& curve);

/// Both directions of a surface made non-periodic (as Geom_BSplineSurface::SetUNotPeriodic/SetVNotPeriodic).
template <int Dim>
BSplineSurface<Dim> to_non_periodic(const BSplineSurface<Dim>& surface);

#define CG_MODIFY_PERIODIC_EXTERN(D)                                          \
  extern template BSplineCurve<D> to_non_periodic(const BSplineCurve<D>&);    \
  extern template BSplineSurface<D> to_non_periodic(const BSplineSurface<D>&);
CG_MODIFY_PERIODIC_EXTERN(1)
CG_MODIFY_PERIODIC_EXTERN(2)
CG_MODIFY_PERIODIC_EXTERN(3)
#undef CG_MODIFY_PERIODIC_EXTERN

}  // namespace cg
