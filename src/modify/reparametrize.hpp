#pragma once
// Reparametrisation of B-spline / NURBS curves: reversal and affine maps of the parameter.
#include "src/core/bspline_curve.hpp"

namespace cg {

/// The reversed curve R(u) = C(first + last - u) on the same domain: knots reflected, poles (and weights)
/// in reverse order, as OCCT's Geom_BSplineCurve::Reverse. Periodic curves stay periodic (the seam knot
/// is again the first knot of the period).
template <int Dim>
BSplineCurve<Dim> reversed(const BSplineCurve<Dim>& curve);

/// The same curve on [a, b]: R(s) = C(first + (s - a) (last - first) / (b - a)); knots mapped affinely,
/// poles unchanged (the period of a periodic curve becomes b - a). Throws InvalidGeometry unless a < b.
template <int Dim>
BSplineCurve<Dim> reparametrized(const BSplineCurve<Dim>& curve, double a, double b);

#define CG_MODIFY_REPARAM_EXTERN(D)                                    \
  extern template BSplineCurve<D> reversed(const BSplineCurve<D>&);    \
  extern template BSplineCurve<D> reparametrized(const BSplineCurve<D>&, double, double);
CG_MODIFY_REPARAM_EXTERN(1)
CG_MODIFY_REPARAM_EXTERN(2)
CG_MODIFY_REPARAM_EXTERN(3)
#undef CG_MODIFY_REPARAM_EXTERN

}  // namespace cg
