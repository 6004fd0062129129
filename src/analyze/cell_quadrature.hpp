#pragma once
// The 8-point Gauss-Legendre rule over equal cells of an interval, and over a disc, for the volume
// quadratures of the cooling features' tools (ruled blocks, slots, pins, inlets).
#include "src/analyze/gauss_legendre.hpp"
#include "src/core/constants.hpp"

namespace cg {

/// 8-point Gauss-Legendre rule mapped onto [a, b] in n equal cells: calls f(x, weight).
template <class F>
void gauss_legendre(double a, double b, int cells, F f);

/// Integral of f(rho, phi) over the disc of radius r: Gauss-Legendre (8 points) in rho, `angles` equal
/// steps in phi (the trapezoidal rule, spectrally accurate for the smooth periodic integrand).
template <class F>
double disc_integral(double r, F f, int angles = 32);

// ---------------------------------------------------------------------------------------------------

namespace detail {
struct Gauss8 {
  double x[8], w[8];
  Gauss8() { gauss_legendre(8, x, w); }
};
inline const Gauss8& gauss8() {
  static const Gauss8 rule;
  return rule;
}
}  // namespace detail

template <class F>
void gauss_legendre(double a, double b, int cells, F f) {
  const detail::Gauss8& g = detail::gauss8();
  const double h = (b - a) / cells;
  for (int c = 0; c < cells; ++c)
    for (int i = 0; i < 8; ++i) f(a + h * (c + 0.5 * (g.x[i] + 1)), 0.5 * h * g.w[i]);
}

template <class F>
double disc_integral(double r, F f, int angles) {
  constexpr double kTwoPi = 2 * kPi;
  double sum = 0;
  gauss_legendre(0.0, r, 1, [&](double rho, double w) {
    for (int k = 0; k < angles; ++k) sum += w * rho * (kTwoPi / angles) * f(rho, kTwoPi * k / angles);
  });
  return sum;
}

}  // namespace cg
