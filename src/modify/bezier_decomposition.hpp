#pragma once
// Decomposition of a B-spline / NURBS curve into its rational Bézier segments (the result of The NURBS
// Book A5.6, computed span by span by the shared span conversion of src/core/bezier_ops.hpp).
#include <vector>

#include "src/core/bezier_curve.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg {

template <int Dim>
struct BezierDecomposition {
  /// One segment per non-empty knot span, each parametrised on [0, 1].
  std::vector<BezierCurve<Dim>> segments;
  /// segments.size() + 1 increasing parameters: segment i is the curve on [breaks[i], breaks[i+1]],
  /// i.e. C(u) = segments[i].point((u - breaks[i]) / (breaks[i+1] - breaks[i])).
  std::vector<double> breaks;
};

/// Bézier segments of the curve: one per non-empty knot span of [first, last] (a periodic curve's base
/// period: the seam is a break).
template <int Dim>
BezierDecomposition<Dim> decompose_to_bezier(const BSplineCurve<Dim>& curve);

extern template BezierDecomposition<1> decompose_to_bezier(const BSplineCurve<1>&);
extern template BezierDecomposition<2> decompose_to_bezier(const BSplineCurve<2>&);
extern template BezierDecomposition<3> decompose_to_bezier(const BSplineCurve<3>&);

}  // namespace cg
