#pragma once
// Affine transformation of B-spline / NURBS curves and surfaces. B-splines are affinely invariant, so
// transforming the Cartesian poles (weights kept) transforms every point of the curve, as OCCT's
// Geom_Geometry::Transform.
#include <Eigen/Geometry>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

/// Poles P -> A P + t. Throws InvalidGeometry when A or t has a non-finite entry.
template <int Dim>
BSplineCurve<Dim> transformed(const BSplineCurve<Dim>& curve, const Eigen::Matrix<double, Dim, Dim>& A,
                              const Eigen::Matrix<double, Dim, 1>& t);
template <int Dim>
BSplineCurve<Dim> transformed(const BSplineCurve<Dim>& curve, const Eigen::Transform<double, Dim, Eigen::Affine>& T) {
  return transformed(curve, Eigen::Matrix<double, Dim, Dim>(T.linear()), Eigen::Matrix<double, Dim, 1>(T.translation()));
}

template <int Dim>
BSplineSurface<Dim> transformed(const BSplineSurface<Dim>& surface, const Eigen::Matrix<double, Dim, Dim>& A,
                                const Eigen::Matrix<double, Dim, 1>& t);
template <int Dim>
BSplineSurface<Dim> transformed(const BSplineSurface<Dim>& surface,
                                const Eigen::Transform<double, Dim, Eigen::Affine>& T) {
  return transformed(surface, Eigen::Matrix<double, Dim, Dim>(T.linear()),
                     Eigen::Matrix<double, Dim, 1>(T.translation()));
}

#define CG_MODIFY_TRANSFORM_EXTERN(D)                                                                      \
  extern template BSplineCurve<D> transformed(const BSplineCurve<D>&, const Eigen::Matrix<double, D, D>&,  \
                                              const Eigen::Matrix<double, D, 1>&);                         \
  extern template BSplineSurface<D> transformed(const BSplineSurface<D>&, const Eigen::Matrix<double, D, D>&, \
                                                const Eigen::Matrix<double, D, 1>&);
CG_MODIFY_TRANSFORM_EXTERN(1)
CG_MODIFY_TRANSFORM_EXTERN(2)
CG_MODIFY_TRANSFORM_EXTERN(3)
#undef CG_MODIFY_TRANSFORM_EXTERN

}  // namespace cg
