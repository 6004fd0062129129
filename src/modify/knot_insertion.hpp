#pragma once
// Knot insertion and knot refinement of B-spline / NURBS curves and surfaces. The shape is unchanged;
// only the representation gains knots and poles.
//
// Periodic curves and surfaces stay periodic, as with OCCT's Geom_BSplineCurve::InsertKnot: the knot is
// inserted in the unwrapped form together with its copies one period away, so the wrap poles stay
// consistent. Knots are matched exactly (OCCT's default parametric tolerance 0).
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// Inserts u `times` times (The NURBS Book A5.1 on the homogeneous poles).
/// Throws InvalidGeometry when times < 1, u lies outside [first, last] (non-periodic; periodic curves
/// wrap u into the base period) or the multiplicity of u would exceed the degree (this includes the
/// clamped end knots, which already have multiplicity degree + 1).
template <int Dim>
BSplineCurve<Dim> insert_knot(const BSplineCurve<Dim>& curve, double u, int times = 1);

/// Inserts all knots of the non-decreasing list X at once (knot refinement, The NURBS Book A5.4),
/// with the checks of insert_knot. An empty list returns the curve unchanged.
template <int Dim>
BSplineCurve<Dim> refine_knots(const BSplineCurve<Dim>& curve, const std::vector<double>& X);

/// Surface knot insertion in u (v): A5.1 applied to every pole column (row) of the homogeneous grid with
/// shared alphas (The NURBS Book A5.3). Same checks as for curves.
template <int Dim>
BSplineSurface<Dim> insert_knot_u(const BSplineSurface<Dim>& surface, double u, int times = 1);
template <int Dim>
BSplineSurface<Dim> insert_knot_v(const BSplineSurface<Dim>& surface, double v, int times = 1);

/// Surface knot refinement in u (v) with the non-decreasing list X (A5.4 row-wise).
template <int Dim>
BSplineSurface<Dim> refine_knots_u(const BSplineSurface<Dim>& surface, const std::vector<double>& X);
template <int Dim>
BSplineSurface<Dim> refine_knots_v(const BSplineSurface<Dim>& surface, const std::vector<double>& X);

#define CG_MODIFY_KNOT_INSERTION_EXTERN(D)                                                                 \
  extern template BSplineCurve<D> insert_knot(const BSplineCurve<D>&, double, int);                         \
  extern template BSplineCurve<D> refine_knots(const BSplineCurve<D>&, const std::vector<double>&);         \
  extern template BSplineSurface<D> insert_knot_u(const BSplineSurface<D>&, double, int);                   \
  extern template BSplineSurface<D> insert_knot_v(const BSplineSurface<D>&, double, int);                   \
  extern template BSplineSurface<D> refine_knots_u(const BSplineSurface<D>&, const std::vector<double>&);   \
  extern template BSplineSurface<D> refine_knots_v(const BSplineSurface<D>&, const std::vector<double>&);
CG_MODIFY_KNOT_INSERTION_EXTERN(1)
CG_MODIFY_KNOT_INSERTION_EXTERN(2)
CG_MODIFY_KNOT_INSERTION_EXTERN(3)
#undef CG_MODIFY_KNOT_INSERTION_EXTERN

}  // namespace cg
