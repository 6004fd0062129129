#include "src/modify/reparametrize.hpp"

#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/modify/pole_bundle.hpp"

namespace cg {

template <int Dim>
BSplineCurve<Dim> reversed(const BSplineCurve<Dim>& curve) {
  return bundle::to_curve<Dim>(bundle::reversed(bundle::from_curve(curve)));
}

template <int Dim>
BSplineCurve<Dim> reparametrized(const BSplineCurve<Dim>& curve, double a, double b) {
  require(std::isfinite(a) && std::isfinite(b) && a < b,
          "reparametrisation interval [" + format_number(a) + ", " + format_number(b) + "] must satisfy a < b");
  const double f = curve.first_param(), l = curve.last_param();
  const double scale = (b - a) / (l - f);
  // Domain ends map exactly onto a and b; other knots keep their order because the map is monotone.
  auto map = [&](double u) { return u == f ? a : u == l ? b : a + (u - f) * scale; };
  const int p = curve.degree();
  if (curve.is_periodic()) {
    const int n = curve.num_period_poles();
    std::vector<double> t(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) t[static_cast<std::size_t>(i)] = map(curve.knots()[static_cast<std::size_t>(p + i)]);
    return BSplineCurve<Dim>::from_homogeneous(p, unwrap_periodic_knots(p, t, b - a), curve.homogeneous_poles(), true);
  }
  std::vector<double> U = curve.knots();
  for (double& u : U) u = map(u);
  return BSplineCurve<Dim>::from_homogeneous(p, std::move(U), curve.homogeneous_poles());
}

#define CG_MODIFY_REPARAM_INSTANTIATE(D)                       \
  template BSplineCurve<D> reversed(const BSplineCurve<D>&);   \
  template BSplineCurve<D> reparametrized(const BSplineCurve<D>&, double, double);
CG_MODIFY_REPARAM_INSTANTIATE(1)
CG_MODIFY_REPARAM_INSTANTIATE(2)
CG_MODIFY_REPARAM_INSTANTIATE(3)

}  // namespace cg
