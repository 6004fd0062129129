#pragma once
// Random periodic B-spline geometry (seeded) in both representations: OCCT's (one period of distinct
// knots with multiplicities, closing knot included, first multiplicity == last) and ours (unwrapped).
// Seam and interior multiplicities range over 1..degree; degrees 1..7 for curves.
#include <algorithm>
#include <cmath>
#include <vector>

#include "src/core/knots.hpp"
#include "support/random_geometry.hpp"

namespace cg::test {

/// One period of periodic knots in OCCT form: values[0] = a, values.back() = a + T, mults.front() ==
/// mults.back() (the seam multiplicity). The pole count (sum of all mults but the last) is >= p + 1.
struct PeriodicKnots {
  std::vector<double> values;
  std::vector<int> mults;
  int num_poles() const {
    int n = 0;
    for (std::size_t i = 0; i + 1 < mults.size(); ++i) n += mults[i];
    return n;
  }
  double period() const { return values.back() - values.front(); }
  /// Flat knots of one period (seam knot with its multiplicity, closing knot left out).
  std::vector<double> period_flat() const {
    return flat_knots(std::vector<double>(values.begin(), values.end() - 1),
                      std::vector<int>(mults.begin(), mults.end() - 1));
  }
};

/// seam_mult > 0 fixes the seam multiplicity (seam_mult = p: a C0 crease on the seam).
inline PeriodicKnots random_periodic_knots(Rng& r, int p, int extra_max = 8, int seam_mult = 0) {
  PeriodicKnots k;
  const double a = r.uniform(-3, 3), T = r.uniform(0.5, 10);
  const int seam = seam_mult > 0 ? seam_mult : (p >= 2 && r.coin(0.4)) ? r.integer(2, p) : 1;
  std::vector<double> inner;
  std::vector<int> inner_mults;
  int n = seam;
  const int target = p + 1 + r.integer(0, extra_max);
  while (n < target) {
    const int m = (p >= 2 && r.coin(0.25)) ? r.integer(2, p) : 1;
    inner.push_back(r.uniform(0.02, 0.98));
    inner_mults.push_back(m);
    n += m;
  }
  std::vector<std::size_t> order(inner.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return inner[x] < inner[y]; });
  k.values.push_back(a);
  k.mults.push_back(seam);
  for (std::size_t i : order) {
    const double v = a + T * inner[i];
    if (v == k.values.back()) continue;  // duplicate draw: astronomically rare, skip it
    k.values.push_back(v);
    k.mults.push_back(inner_mults[i]);
  }
  k.values.push_back(a + T);
  k.mults.push_back(seam);
  // A skipped duplicate may leave too few poles: top up the seam-adjacent span.
  while (k.num_poles() < p + 1) {
    k.values.insert(k.values.end() - 1, a + T * (0.99 + 0.001 * k.num_poles()));
    k.mults.insert(k.mults.end() - 1, 1);
  }
  return k;
}

template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> random_pole_vector(Rng& r, int n) {
  std::vector<typename BSplineCurve<Dim>::Point> P(static_cast<std::size_t>(n));
  for (auto& q : P)
    for (int d = 0; d < Dim; ++d) q[d] = r.uniform(-10, 10);
  return P;
}

inline std::vector<double> random_weight_vector(Rng& r, int n) {
  std::vector<double> w(static_cast<std::size_t>(n));
  for (auto& x : w) x = r.uniform(0.2, 5.0);
  return w;
}

/// Our periodic curve of random degree 1..7 built with BSplineCurve::periodic.
template <int Dim>
BSplineCurve<Dim> random_periodic_bspline(Rng& r, bool rational) {
  const int p = r.integer(1, 7);
  const PeriodicKnots k = random_periodic_knots(r, p);
  const int n = k.num_poles();
  return BSplineCurve<Dim>::periodic(p, k.period_flat(), k.period(), random_pole_vector<Dim>(r, n),
                                     rational ? random_weight_vector(r, n) : std::vector<double>{});
}

/// Our surface of degrees 1..5, periodic in the requested directions (unwrapped poles and knots).
/// seam_crease_u: the u seam gets multiplicity pu (a C0 crease along the seam).
inline BSplineSurface<3> random_periodic_surface(Rng& r, bool rational, bool periodic_u, bool periodic_v,
                                                 bool seam_crease_u = false) {
  const int pu = r.integer(1, 5), pv = r.integer(1, 5);
  auto direction = [&](bool periodic, int p, int& count, int& distinct, bool crease) {
    if (!periodic) {
      count = distinct = r.integer(p + 1, p + 6);
      return random_knots(r, p, count);
    }
    const PeriodicKnots k = random_periodic_knots(r, p, 4, crease ? p : 0);
    distinct = k.num_poles();
    count = distinct + p;
    return unwrap_periodic_knots(p, k.period_flat(), k.period());
  };
  int nu, nv, du, dv;
  std::vector<double> U = direction(periodic_u, pu, nu, du, seam_crease_u);
  std::vector<double> V = direction(periodic_v, pv, nv, dv, false);
  std::vector<std::vector<Eigen::Vector3d>> P(static_cast<std::size_t>(nu), std::vector<Eigen::Vector3d>(static_cast<std::size_t>(nv)));
  std::vector<std::vector<double>> W;
  if (rational) W.assign(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  // Draw the distinct du x dv poles; the unwrapped ones repeat them (index modulo the period).
  for (int i = 0; i < du; ++i)
    for (int j = 0; j < dv; ++j) {
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          Eigen::Vector3d(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10));
      if (rational) W[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = r.uniform(0.2, 5.0);
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const auto a = static_cast<std::size_t>(i % du), b = static_cast<std::size_t>(j % dv);
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = P[a][b];
      if (rational) W[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = W[a][b];
    }
  return BSplineSurface<3>::from_poles(pu, pv, std::move(U), std::move(V), P, W, periodic_u, periodic_v);
}


/// A blade-like surface: periodic in u (a thin cambered airfoil loop, chord 30..50 mm, thickness
/// 0.8..4 mm, so the leading and trailing edges curve with radii down to ~0.01 mm), clamped in v (4..7
/// sections over a 20..60 mm span with twist and lean); degree 2..5 in u, 1..3 in v, rational on request
/// (weights in [0.5, 2]).
inline BSplineSurface<3> random_blade_surface(Rng& r, bool rational) {
  const int pu = r.integer(2, 5), sections = r.integer(4, 7), pv = std::min(3, r.integer(1, sections - 1));
  const int du = r.integer(10, 24);  // distinct poles round the loop
  PeriodicKnots k;
  for (int i = 0; i <= du; ++i) {
    k.values.push_back(static_cast<double>(i));
    k.mults.push_back(1);
  }
  const int nu = du + pu;
  std::vector<double> U = unwrap_periodic_knots(pu, k.period_flat(), k.period());
  std::vector<double> V = random_knots(r, pv, sections);
  const double chord = r.uniform(30, 50), span = r.uniform(20, 60);
  std::vector<std::vector<Eigen::Vector3d>> P(static_cast<std::size_t>(nu), std::vector<Eigen::Vector3d>(static_cast<std::size_t>(sections)));
  std::vector<std::vector<double>> W;
  if (rational) W.assign(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(sections)));
  for (int j = 0; j < sections; ++j) {
    const double thick = r.uniform(0.8, 4.0), camber = r.uniform(0, 0.1) * chord;
    const double twist = r.uniform(-0.6, 0.6), lean = r.uniform(-3, 3);
    const double z = span * j / (sections - 1);
    for (int i = 0; i < du; ++i) {
      const double th = 2 * M_PI * i / du;
      const double x = 0.5 * chord * std::cos(th);
      const double y = 0.5 * thick * std::sin(th) * (1 + 0.4 * std::cos(th)) + camber * (1 - std::pow(2 * x / chord, 2));
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          Eigen::Vector3d(std::cos(twist) * x - std::sin(twist) * y + lean * j, std::sin(twist) * x + std::cos(twist) * y, z);
      if (rational) W[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = r.uniform(0.5, 2.0);
    }
  }
  for (int i = du; i < nu; ++i)
    for (int j = 0; j < sections; ++j) {
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = P[static_cast<std::size_t>(i - du)][static_cast<std::size_t>(j)];
      if (rational) W[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = W[static_cast<std::size_t>(i - du)][static_cast<std::size_t>(j)];
    }
  return BSplineSurface<3>::from_poles(pu, pv, std::move(U), std::move(V), P, W, true, false);
}

}  // namespace cg::test
