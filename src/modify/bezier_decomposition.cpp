#include "src/modify/bezier_decomposition.hpp"

#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
BezierDecomposition<Dim> decompose_to_bezier(const BSplineCurve<Dim>& curve) {
  BezierDecomposition<Dim> d;
  const auto segments = bundle::bezier_segments(bundle::clamped(bundle::from_curve(curve)), d.breaks);
  d.segments.reserve(segments.size());
  for (const auto& s : segments) d.segments.emplace_back(typename BezierCurve<Dim>::HPoles(s));
  return d;
}

template BezierDecomposition<1> decompose_to_bezier(const BSplineCurve<1>&);
template BezierDecomposition<2> decompose_to_bezier(const BSplineCurve<2>&);
template BezierDecomposition<3> decompose_to_bezier(const BSplineCurve<3>&);

}  // namespace cg
