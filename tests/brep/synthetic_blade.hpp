#pragma once
// Synthetic blade for solid tests: an exact rational elliptic cross-section (periodic, degree 2,
// weights sqrt(2)/2 at the corners) swept along z, so volumes and areas have analytic or
// quadrature values independent of OCCT.
#include <cmath>
#include <functional>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/constants.hpp"
#include "src/core/knots.hpp"

namespace cg::test {

using cg::kPi;

struct EllipticBlade {
  double a = 20, b = 4;          // semi-axes along x (chord) and y (thickness), mm
  double z0 = 80, z1 = 130;      // span of the over-built surface, mm
  double lean_x = 0;             // x shift of the section per mm of z (leaned prism)
  int degree_v = 3;              // spanwise degree (the sweep stays linear in z)
};

/// u-periodic degree-2 rational ellipse (8 poles) swept linearly from z0 to z1, degree_v in v.
inline BSplineSurface<3> elliptic_blade_surface(const EllipticBlade& e) {
  const double s = std::sqrt(0.5);
  // Poles alternate corners (weight sqrt(2)/2) and quadrant ends (weight 1). With double knots at
  // 0, 1/4, 1/2, 3/4 the span [0, 1/4] of the unwrapped form uses poles 1..3, so the list starts at
  // the corner (a, -b) and each span is a quarter arc (tests check the kernel surface lies on it).
  const double px[8] = {1, 1, 1, 0, -1, -1, -1, 0}, py[8] = {-1, 0, 1, 1, 1, 0, -1, -1};
  const double w[8] = {s, 1, s, 1, s, 1, s, 1};
  const int pu = 2, pv = e.degree_v, nu = 8 + pu, nv = pv + 1;
  const std::vector<double> U = unwrap_periodic_knots(pu, {0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75}, 1.0);
  const std::vector<double> V = uniform_clamped_knots(pv, nv);
  BSplineSurface<3>::HPoles h(4, nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int k = i % 8;
      const double z = e.z0 + (e.z1 - e.z0) * j / pv;  // Bezier in v: equally spaced poles = linear in z
      h.col(i * nv + j) << w[k] * (e.a * px[k] + e.lean_x * z), w[k] * e.b * py[k], w[k] * z, w[k];
    }
  return BSplineSurface<3>::from_homogeneous(pu, pv, U, V, nu, nv, h, true, false);
}

/// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n, Numerical Recipes gauleg).
inline void gauss_legendre01(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(static_cast<std::size_t>(n), 0);
  w.assign(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = 0;
      for (int j = 0; j < n; ++j) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j + 1) * z * p1 - j * p2) / (j + 1);
      }
      dp = n * (z * p0 - p1) / (z * z - 1);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[static_cast<std::size_t>(i)] = 0.5 * (1 - z);
    w[static_cast<std::size_t>(i)] = 1.0 / ((1 - z * z) * dp * dp);
  }
}

/// Integral of height(x, y) over the ellipse x^2/a^2 + y^2/b^2 <= 1 in polar form
/// x = a s cos(phi), y = b s sin(phi), dA = a b s ds dphi: Gauss-Legendre (48 nodes) in s and the
/// trapezoid rule (256 nodes, exponentially convergent for periodic integrands) in phi. For smooth
/// heights this is accurate to ~1e-13 relative, far below the 1e-6 test tolerance.
inline double integrate_over_ellipse(double a, double b, const std::function<double(double, double)>& height) {
  std::vector<double> sx, sw;
  gauss_legendre01(48, sx, sw);
  const int m = 256;
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    const double phi = 2 * kPi * k / m;
    for (std::size_t i = 0; i < sx.size(); ++i)
      sum += sw[i] * sx[i] * height(a * sx[i] * std::cos(phi), b * sx[i] * std::sin(phi));
  }
  return sum * a * b * 2 * kPi / m;
}

/// Perimeter of the ellipse by the trapezoid rule on the periodic speed |C'(t)| (exponential convergence).
inline double ellipse_perimeter(double a, double b) {
  const int m = 512;
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    const double t = 2 * kPi * k / m;
    sum += std::hypot(a * std::sin(t), b * std::cos(t));
  }
  return sum * 2 * kPi / m;
}

}  // namespace cg::test
