#include "src/modify/split.hpp"

#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
std::pair<BSplineCurve<Dim>, BSplineCurve<Dim>> split(const BSplineCurve<Dim>& curve, double u) {
  auto halves = bundle::split(bundle::from_curve(curve), u);
  return {bundle::to_curve<Dim>(std::move(halves.first)), bundle::to_curve<Dim>(std::move(halves.second))};
}

template <int Dim>
BSplineCurve<Dim> segment(const BSplineCurve<Dim>& curve, double a, double b) {
  return bundle::to_curve<Dim>(bundle::segment(bundle::from_curve(curve), a, b));
}

#define CG_MODIFY_SPLIT_INSTANTIATE(D)                                                         \
  template std::pair<BSplineCurve<D>, BSplineCurve<D>> split(const BSplineCurve<D>&, double); \
  template BSplineCurve<D> segment(const BSplineCurve<D>&, double, double);
CG_MODIFY_SPLIT_INSTANTIATE(1)
CG_MODIFY_SPLIT_INSTANTIATE(2)
CG_MODIFY_SPLIT_INSTANTIATE(3)

}  // namespace cg
