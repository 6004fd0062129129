#pragma once
// Degree elevation of B-spline / NURBS curves and surfaces on the homogeneous poles. The result is that of
// The NURBS Book A5.9 and OCCT's Geom_BSplineCurve::IncreaseDegree(p + t): degree p + t, every distinct
// knot's multiplicity raised by t, shape unchanged. The poles are computed by blossoming (each new pole
// is the degree-(p+t) blossom at its knots, an average of de Boor evaluations) instead of A5.9's
// Bezier elevation + knot removal, whose extrapolating removal step lost up to 1e-5 of the pole scale on
// knot vectors with span ratios ~1e4 (measured); the blossom form stays within 1e-12 and is as fast as
// OCCT. Periodic curves stay periodic (elevated on a clamped three-period extension, then one period is
// read back; OCCT 7.6's periodic IncreaseDegree returns wrong curves for many inputs, measured).
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// Degree p -> p + t. Throws InvalidGeometry when t < 1 or p + t exceeds kMaxDegree. A non-periodic curve
/// with unclamped end knots is clamped first (same shape, end multiplicity p + 1).
template <int Dim>
BSplineCurve<Dim> elevate_degree(const BSplineCurve<Dim>& curve, int t);

/// Surface degree elevation in u (v): the curve elevation applied to every pole column (row) at once.
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
