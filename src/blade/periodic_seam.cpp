#include "src/blade/periodic_seam.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"
#include "src/modify/knot_insertion.hpp"
#include "src/modify/reparametrize.hpp"

namespace cg::blade::detail {

template <int Dim>
BSplineCurve<Dim> with_seam_at(const BSplineCurve<Dim>& curve, double u) {
  require(curve.is_periodic(), "with_seam_at: the curve must be periodic");
  u = curve.check_param(u);
  const double T = curve.period();
  const int p = curve.degree();
  // A parameter within rounding of an existing knot is that knot (inserting it would raise the
  // multiplicity and cost continuity).
  const double snap = 1e-13 * T;
  BSplineCurve<Dim> c = curve;
  auto knot_index = [&](const BSplineCurve<Dim>& k) {
    const auto& U = k.knots();
    for (int i = p; i <= k.num_poles(); ++i)
      if (std::abs(U[static_cast<std::size_t>(i)] - u) <= snap) return i;
    return -1;
  };
  int s = knot_index(c);
  if (s < 0) {
    c = insert_knot(c, u);
    s = knot_index(c);
    require(s >= 0, "with_seam_at: the inserted knot was not found");  // cannot happen: A5.1 adds u
  }
  if (s == c.num_poles()) s = p;  // the end of the domain is its start
  // Unwrapped data: n distinct poles, knots U[0 .. n + 2p]. Shifting the window by j = s - p keeps the
  // same infinite periodic sequence of knots and poles, so the curve is unchanged.
  const int n = c.num_period_poles(), j = s - p;
  const auto& U = c.knots();
  const auto& H = c.homogeneous_poles();
  std::vector<double> V(U.size());
  for (std::size_t k = 0; k < V.size(); ++k) {
    const std::size_t src = k + static_cast<std::size_t>(j);
    V[k] = src < U.size() ? U[src] : U[src - static_cast<std::size_t>(n)] + T;
  }
  typename BSplineCurve<Dim>::HPoles G(H.rows(), H.cols());
  for (int i = 0; i < H.cols(); ++i) G.col(i) = H.col((i + j) % n);
  const BSplineCurve<Dim> rotated = BSplineCurve<Dim>::from_homogeneous(p, std::move(V), std::move(G), true);
  return reparametrized(rotated, 0.0, 1.0);
}

template BSplineCurve<2> with_seam_at(const BSplineCurve<2>&, double);
template BSplineCurve<3> with_seam_at(const BSplineCurve<3>&, double);

}  // namespace cg::blade::detail
