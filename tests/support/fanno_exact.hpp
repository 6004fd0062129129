#pragma once
// Exact adiabatic Fanno flow with the Colebrook-White friction factor, written independently of the
// product (src/network) for tests of the CalculiX decks it writes: the mass flow through a straight pipe
// of constant area between an inlet total state and an outlet total pressure.
#include <cmath>
#include <functional>

namespace cg::test {

struct FannoGas {
  double gas_constant = 287.05;  ///< J/(kg K)
  double cp = 1005;              ///< J/(kg K)
  double viscosity = 1.8e-5;     ///< Pa s
};

struct FannoPipe {
  double area, dh, length, ks;  // mm^2, mm, mm, mm
};

// Darcy friction factor: Colebrook's implicit law, by fixed-point iteration to machine precision.
inline double colebrook_darcy(double re, double rel) {
  double lambda = 0.02;
  for (int i = 0; i < 200; ++i) lambda = std::pow(-2 * std::log10(rel / 3.7 + 2.51 / (re * std::sqrt(lambda))), -2);
  return lambda;
}

inline double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(lo) < 0) == (f(mid) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Exact adiabatic Fanno flow: for a mass flow m (kg/s) the inlet Mach number from the inlet totals, the
// outlet Mach number from lambda L / D = F(M1) - F(M2) (lambda from Colebrook at the pipe's Reynolds
// number, constant along an adiabatic pipe of constant viscosity), and the outlet total pressure.
// Returns the m whose outlet total pressure is `pt_out` (or the choking flow when the pipe chokes first).
inline double fanno_mass_flow(const FannoPipe& p, const FannoGas& gas, double pt_in, double tt, double pt_out) {
  const double g = gas.cp / (gas.cp - gas.gas_constant), a = p.area * 1e-6, d = p.dh * 1e-3;
  const auto flow = [&](double mach) {
    return a * pt_in / std::sqrt(gas.gas_constant * tt) * std::sqrt(g) * mach *
           std::pow(1 + 0.5 * (g - 1) * mach * mach, -(g + 1) / (2 * (g - 1)));
  };
  const auto fanno = [&](double mach) {
    const double m2 = mach * mach;
    return (1 - m2) / (g * m2) + (g + 1) / (2 * g) * std::log((g + 1) * m2 / (2 + (g - 1) * m2));
  };
  const auto outlet_pt = [&](double m) {
    const double m1 = bisect([&](double mach) { return flow(mach) - m; }, 1e-9, 1.0);
    const double re = m * d / (a * gas.viscosity);
    const double target = fanno(m1) - colebrook_darcy(re, p.ks / p.dh) * p.length / p.dh;
    if (target <= 0) return 0.0;  // the pipe chokes before its end: no such flow
    const double m2 = bisect([&](double mach) { return fanno(mach) - target; }, m1, 1.0);
    const double k = (g + 1) / (2 * (g - 1));
    return pt_in * (m1 / m2) * std::pow((2 + (g - 1) * m2 * m2) / (2 + (g - 1) * m1 * m1), k);
  };
  return bisect([&](double m) { return outlet_pt(m) - pt_out; }, 1e-9, 0.999 * flow(1.0));
}

}  // namespace cg::test
