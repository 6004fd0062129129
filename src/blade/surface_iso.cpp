#include "src/blade/surface_iso.hpp"

#include "src/core/basis.hpp"
#include "src/core/error.hpp"

namespace cg::blade::detail {

BSplineCurve<3> iso_curve_v(const BSplineSurface<3>& s, double v) {
  double u = s.first_u();
  s.check_params(u, v);
  const int q = s.degree_v(), nv = s.num_poles_v(), nu = s.num_poles_u();
  const std::vector<double>& V = s.knots_v();
  const int span = find_span(V.data(), nv - 1, q, v);
  double N[kMaxDegree + 1];
  basis_funs(span, v, q, V.data(), N);
  BSplineCurve<3>::HPoles h = BSplineCurve<3>::HPoles::Zero(4, nu);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j <= q; ++j) h.col(i) += N[j] * s.homogeneous_pole(i, span - q + j);
  return BSplineCurve<3>::from_homogeneous(s.degree_u(), s.knots_u(), std::move(h), s.is_periodic_u());
}

}  // namespace cg::blade::detail
