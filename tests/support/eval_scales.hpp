#pragma once
// Scales for relative tolerances of evaluation tests: the size of a curve's k-th derivative and of a
// surface's control net.
#include <algorithm>
#include <cmath>
#include <vector>

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

/// Shortest non-empty knot span of a knot vector.
inline double shortest_span(const std::vector<double>& U) {
  double h = U.back() - U.front();
  for (std::size_t i = 0; i + 1 < U.size(); ++i)
    if (U[i + 1] > U[i]) h = std::min(h, U[i + 1] - U[i]);
  return h;
}

/// Scale of the mixed partial S^(k,l) of a surface, as deriv_scale for curves applied in each
/// direction: |P|max * (pu * wr / hu)^k * (pv * wr / hv)^l * wr (wr the weight ratio, hu, hv the
/// shortest spans). Each derivative along u multiplies the pole differences by pu / (span length),
/// and the quotient rule adds a weight ratio per order.
template <int Dim>
double deriv_scale(const BSplineSurface<Dim>& s, int k, int l) {
  double wmin = s.weight(0, 0), wmax = wmin, pmax = 0;
  for (int a = 0; a < s.num_poles_u(); ++a)
    for (int b = 0; b < s.num_poles_v(); ++b) {
      wmin = std::min(wmin, s.weight(a, b));
      wmax = std::max(wmax, s.weight(a, b));
      pmax = std::max(pmax, s.pole(a, b).norm());
    }
  const double wr = wmax / wmin;
  return pmax * std::pow(s.degree_u() * wr / shortest_span(s.knots_u()), k) *
         std::pow(s.degree_v() * wr / shortest_span(s.knots_v()), l) * wr;
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
