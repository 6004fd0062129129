#include "src/modify/bezier_decomposition.hpp"

#include "src/core/bezier_ops.hpp"
#include "src/core/error.hpp"

namespace cg {

// Each non-empty knot span of the domain is converted on its own by the shared span conversion
// (span_bezier_poles: the blossom of the span ends), so a periodic curve needs no clamping first.
template <int Dim>
BezierDecomposition<Dim> decompose_to_bezier(const BSplineCurve<Dim>& curve) {
  require(curve.num_poles() > 0, "Bezier decomposition of an empty curve");
  BezierDecomposition<Dim> d;
  const int p = curve.degree();
  const auto& U = curve.knots();
  const auto& H = curve.homogeneous_poles();
  for (int s = p; s < curve.num_poles(); ++s) {
    const double a = U[static_cast<std::size_t>(s)], b = U[static_cast<std::size_t>(s + 1)];
    if (!(b > a)) continue;
    typename BezierCurve<Dim>::HPoles q(Dim + 1, p + 1);
    span_bezier_poles(p, U.data(), s, H.col(s - p).data(), Dim + 1, q.data());
    if (d.breaks.empty()) d.breaks.push_back(a);
    d.breaks.push_back(b);
    d.segments.emplace_back(std::move(q));
  }
  return d;
}

template BezierDecomposition<1> decompose_to_bezier(const BSplineCurve<1>&);
template BezierDecomposition<2> decompose_to_bezier(const BSplineCurve<2>&);
template BezierDecomposition<3> decompose_to_bezier(const BSplineCurve<3>&);

}  // namespace cg
