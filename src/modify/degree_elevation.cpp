#include "src/modify/degree_elevation.hpp"

#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
BSplineCurve<Dim> elevate_degree(const BSplineCurve<Dim>& curve, int t) {
  return bundle::to_curve<Dim>(bundle::elevate_degree(bundle::from_curve(curve), t));
}

template <int Dim>
BSplineSurface<Dim> elevate_degree_u(const BSplineSurface<Dim>& s, int t) {
  constexpr auto dir = SurfaceDirection::U;
  return bundle::to_surface(bundle::elevate_degree(bundle::from_surface(s, dir), t), s, dir);
}

template <int Dim>
BSplineSurface<Dim> elevate_degree_v(const BSplineSurface<Dim>& s, int t) {
  constexpr auto dir = SurfaceDirection::V;
  return bundle::to_surface(bundle::elevate_degree(bundle::from_surface(s, dir), t), s, dir);
}

#define CG_MODIFY_ELEVATION_INSTANTIATE(D)                                   \
  template BSplineCurve<D> elevate_degree(const BSplineCurve<D>&, int);       \
  template BSplineSurface<D> elevate_degree_u(const BSplineSurface<D>&, int); \
  template BSplineSurface<D> elevate_degree_v(const BSplineSurface<D>&, int);
CG_MODIFY_ELEVATION_INSTANTIATE(1)
CG_MODIFY_ELEVATION_INSTANTIATE(2)
CG_MODIFY_ELEVATION_INSTANTIATE(3)

}  // namespace cg
