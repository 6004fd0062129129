#include "src/modify/periodic_conversion.hpp"

#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
BSplineCurve<Dim> to_non_periodic(const BSplineCurve<Dim>& curve) {
  if (!curve.is_periodic()) return curve;
  return bundle::to_curve<Dim>(bundle::clamped(bundle::from_curve(curve)));
}

template <int Dim>
BSplineSurface<Dim> to_non_periodic(const BSplineSurface<Dim>& s) {
  BSplineSurface<Dim> r = s;
  for (auto dir : {SurfaceDirection::U, SurfaceDirection::V}) {
    const PoleBundle b = bundle::from_surface(r, dir);
    if (b.periodic) r = bundle::to_surface(bundle::clamped(b), r, dir);
  }
  return r;
}

#define CG_MODIFY_PERIODIC_INSTANTIATE(D)                             \
  template BSplineCurve<D> to_non_periodic(const BSplineCurve<D>&);   \
  template BSplineSurface<D> to_non_periodic(const BSplineSurface<D>&);
CG_MODIFY_PERIODIC_INSTANTIATE(1)
CG_MODIFY_PERIODIC_INSTANTIATE(2)
CG_MODIFY_PERIODIC_INSTANTIATE(3)

}  // namespace cg
