#pragma once
// Random B-spline geometry for property and OCCT-comparison tests. Deterministic (seeded), covering
// degrees 1..7, repeated interior knots (up to the degree), non-unit parameter ranges, and
// polynomial and rational poles (weights in [0.2, 5]).
#include <algorithm>
#include <random>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::test {

struct Rng {
  std::mt19937_64 gen;
  explicit Rng(unsigned long seed) : gen(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(gen); }
  bool coin(double p = 0.5) { return uniform(0, 1) < p; }
};

/// Clamped knot vector for `num_poles` poles of degree p on a random domain, with random interior
/// knots, some of them repeated (multiplicity up to p).
inline std::vector<double> random_knots(Rng& r, int p, int num_poles) {
  const int interior = num_poles - p - 1;
  std::vector<double> inner;
  while (static_cast<int>(inner.size()) < interior) {
    const double k = r.uniform(0.02, 0.98);
    int mult = (p >= 2 && r.coin(0.25)) ? r.integer(2, p) : 1;
    mult = std::min(mult, interior - static_cast<int>(inner.size()));
    for (int m = 0; m < mult; ++m) inner.push_back(k);
  }
  std::sort(inner.begin(), inner.end());
  const double a = r.uniform(-3, 3), len = r.uniform(0.5, 10);
  std::vector<double> U;
  for (int i = 0; i <= p; ++i) U.push_back(a);
  for (double k : inner) U.push_back(a + len * k);
  for (int i = 0; i <= p; ++i) U.push_back(a + len);
  return U;
}

template <int Dim>
BSplineCurve<Dim> random_curve(Rng& r, int p, int num_poles, bool rational) {
  std::vector<typename BSplineCurve<Dim>::Point> P(static_cast<std::size_t>(num_poles));
  std::vector<double> w;
  for (auto& q : P)
    for (int d = 0; d < Dim; ++d) q[d] = r.uniform(-10, 10);
  if (rational)
    for (int i = 0; i < num_poles; ++i) w.push_back(r.uniform(0.2, 5.0));
  return BSplineCurve<Dim>(p, random_knots(r, p, num_poles), P, w);
}

/// Random curve of random degree 1..7 and pole count degree+1 .. degree+12.
template <int Dim>
BSplineCurve<Dim> random_curve(Rng& r, bool rational) {
  const int p = r.integer(1, 7);
  return random_curve<Dim>(r, p, r.integer(p + 1, p + 12), rational);
}

inline BSplineSurface<3> random_surface(Rng& r, bool rational) {
  const int pu = r.integer(1, 5), pv = r.integer(1, 5);
  const int nu = r.integer(pu + 1, pu + 6), nv = r.integer(pv + 1, pv + 6);
  std::vector<std::vector<Eigen::Vector3d>> P(static_cast<std::size_t>(nu), std::vector<Eigen::Vector3d>(static_cast<std::size_t>(nv)));
  std::vector<std::vector<double>> W;
  for (auto& row : P)
    for (auto& q : row) q = Eigen::Vector3d(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10));
  if (rational) {
    W.assign(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
    for (auto& row : W)
      for (auto& w : row) w = r.uniform(0.2, 5.0);
  }
  return BSplineSurface<3>(pu, pv, random_knots(r, pu, nu), random_knots(r, pv, nv), P, W);
}

/// Size of a curve's control polygon (scale for relative tolerances).
template <int Dim>
double pole_scale(const BSplineCurve<Dim>& c) {
  double s = 0;
  for (int i = 0; i < c.num_poles(); ++i) s = std::max(s, c.pole(i).norm());
  return s;
}

}  // namespace cg::test
