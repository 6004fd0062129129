#pragma once
// Degree elevation of B-spline / NURBS curves and surfaces (The NURBS Book A5.9, on homogeneous poles).
// The result has degree p + t and every distinct knot's multiplicity raised by t, as OCCT's
// Geom_BSplineCurve::IncreaseDegree(p + t); the shape is unchanged. Periodic curves stay periodic
// (elevated on a clamped three-period extension, then one period is read back).
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// Degree p -> p + t. Throws InvalidGeometry when t < 1 or p + t exceeds kMaxDegree. A non-periodic curve
/// with unclamped end knots is clamped first (same shape, end multiplicity p + 1).
template <int Dim>
BSplineCurve<Dim> elevate_degree(const BSplineCurve<Dim>& curve, int t);

/// Surface degree elevation in u (v): A5.9 applied to every pole column (row) with shared coefficients.
template <int Dim>
BSplineSurface<Dim> elevate_degree_u(const BSplineSurface<Dim>& surface, int t);
template <int Dim>
BSplineSurface<Dim> elevate_degree_v(const BSplineSurface<Dim>& surface, int t);

#define CG_MODIFY_ELEVATION_EXTERN(D)                                          \
  extern template BSplineCurve<D> elevate_degree(const BSplineCurve<D>&, int);  \
  extern template BSplineSurface<D> elevate_degree_u(const BSplineSurface<D>&, int); \
  extern template BSplineSurface<D> elevate_degree_v(const BSplineSurface<D>&, int);
CG_MODIFY_ELEVATION_EXTERN(1)
CG_MODIFY_ELEVATION_EXTERN(2)
CG_MODIFY_ELEVATION_EXTERN(3)
#undef CG_MODIFY_ELEVATION_EXTERN

}  // namespace cg
