#include "src/modify/knot_insertion.hpp"

#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
BSplineCurve<Dim> insert_knot(const BSplineCurve<Dim>& curve, double u, int times) {
  return bundle::to_curve<Dim>(bundle::insert_knot(bundle::from_curve(curve), u, times));
}

template <int Dim>
BSplineCurve<Dim> refine_knots(const BSplineCurve<Dim>& curve, const std::vector<double>& X) {
  return bundle::to_curve<Dim>(bundle::refine_knots(bundle::from_curve(curve), X));
}

template <int Dim>
BSplineSurface<Dim> insert_knot_u(const BSplineSurface<Dim>& s, double u, int times) {
  constexpr auto dir = SurfaceDirection::U;
  return bundle::to_surface(bundle::insert_knot(bundle::from_surface(s, dir), u, times), s, dir);
}

template <int Dim>
BSplineSurface<Dim> insert_knot_v(const BSplineSurface<Dim>& s, double v, int times) {
  constexpr auto dir = SurfaceDirection::V;
  return bundle::to_surface(bundle::insert_knot(bundle::from_surface(s, dir), v, times), s, dir);
}

template <int Dim>
BSplineSurface<Dim> refine_knots_u(const BSplineSurface<Dim>& s, const std::vector<double>& X) {
  constexpr auto dir = SurfaceDirection::U;
  return bundle::to_surface(bundle::refine_knots(bundle::from_surface(s, dir), X), s, dir);
}

template <int Dim>
BSplineSurface<Dim> refine_knots_v(const BSplineSurface<Dim>& s, const std::vector<double>& X) {
  constexpr auto dir = SurfaceDirection::V;
  return bundle::to_surface(bundle::refine_knots(bundle::from_surface(s, dir), X), s, dir);
}

#define CG_MODIFY_KNOT_INSERTION_INSTANTIATE(D)                                                     \
  template BSplineCurve<D> insert_knot(const BSplineCurve<D>&, double, int);                         \
  template BSplineCurve<D> refine_knots(const BSplineCurve<D>&, const std::vector<double>&);         \
  template BSplineSurface<D> insert_knot_u(const BSplineSurface<D>&, double, int);                   \
  template BSplineSurface<D> insert_knot_v(const BSplineSurface<D>&, double, int);                   \
  template BSplineSurface<D> refine_knots_u(const BSplineSurface<D>&, const std::vector<double>&);   \
  template BSplineSurface<D> refine_knots_v(const BSplineSurface<D>&, const std::vector<double>&);
CG_MODIFY_KNOT_INSERTION_INSTANTIATE(1)
CG_MODIFY_KNOT_INSERTION_INSTANTIATE(2)
CG_MODIFY_KNOT_INSERTION_INSTANTIATE(3)

}  // namespace cg
