#pragma once
// Scales for relative tolerances of evaluation tests: the size of a curve's k-th derivative and of a
// surface's control net.
#include <algorithm>
#include <cmath>

#include "support/random_geometry.hpp"

namespace cg::test {

/// Scale of the k-th derivative of a curve: |P|max * (p * weight ratio / shortest span)^k * weight ratio.
template <int Dim>
double deriv_scale(const BSplineCurve<Dim>& c, int k) {
  double h = c.last_param() - c.first_param();
  const auto& U = c.knots();
  for (std::size_t i = 0; i + 1 < U.size(); ++i)
    if (U[i + 1] > U[i]) h = std::min(h, U[i + 1] - U[i]);
  const auto w = c.weights();
  const double wr = *std::max_element(w.begin(), w.end()) / *std::min_element(w.begin(), w.end());
  return pole_scale(c) * std::pow(c.degree() * wr / h, k) * wr;
}

/// Size of a surface's control net: max |P|.
template <int Dim>
double pole_scale(const BSplineSurface<Dim>& s) {
  double scale = 0;
  for (int a = 0; a < s.num_poles_u(); ++a)
    for (int b = 0; b < s.num_poles_v(); ++b) scale = std::max(scale, s.pole(a, b).norm());
  return scale;
}

}  // namespace cg::test
