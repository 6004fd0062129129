// The CalculiX deck writer (src/network/ccx_deck.hpp) and solver run on networks of straight pipes,
// against an exact adiabatic Fanno-flow integration with the Colebrook friction factor written here,
// independently of the product: a single pipe, and a split between two pipes of different length.
#define BOOST_TEST_MODULE network_deck
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>

#include "brep/temp_files.hpp"
#include "src/network/ccx_deck.hpp"
#include "src/network/ccx_solve.hpp"

using namespace cg;
using namespace cg::network;

namespace {

constexpr double kPt = 2.0e6, kTt = 800, kSink = 1.9e6;  // Pa, K, Pa: subsonic pipes
const Gas kAir{287.05, 1100, 3.6e-5};

struct Pipe {
  double area, dh, length, ks;  // mm^2, mm, mm, mm
};

// Darcy friction factor: Colebrook's implicit law, by fixed-point iteration to machine precision.
double colebrook(double re, double rel) {
  double lambda = 0.02;
  for (int i = 0; i < 200; ++i) lambda = std::pow(-2 * std::log10(rel / 3.7 + 2.51 / (re * std::sqrt(lambda))), -2);
  return lambda;
}

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(lo) < 0) == (f(mid) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Exact adiabatic Fanno flow: for a mass flow m (kg/s) the inlet Mach number from the inlet totals, the
// outlet Mach number from lambda L / D = F(M1) - F(M2), and the outlet total pressure. Returns the m
// whose outlet total pressure is `pt_out` (or the choking flow when the pipe chokes first).
double fanno_mass_flow(const Pipe& p, double pt_in, double pt_out) {
  const double g = kAir.cp / (kAir.cp - kAir.gas_constant), a = p.area * 1e-6, d = p.dh * 1e-3;
  const auto flow = [&](double mach) {
    return a * pt_in / std::sqrt(kAir.gas_constant * kTt) * std::sqrt(g) * mach *
           std::pow(1 + 0.5 * (g - 1) * mach * mach, -(g + 1) / (2 * (g - 1)));
  };
  const auto fanno = [&](double mach) {
    const double m2 = mach * mach;
    return (1 - m2) / (g * m2) + (g + 1) / (2 * g) * std::log((g + 1) * m2 / (2 + (g - 1) * m2));
  };
  const auto outlet_pt = [&](double m) {
    const double m1 = bisect([&](double mach) { return flow(mach) - m; }, 1e-9, 1.0);
    const double re = m * d / (a * kAir.viscosity);
    const double target = fanno(m1) - colebrook(re, p.ks / p.dh) * p.length / p.dh;
    if (target <= 0) return 0.0;  // the pipe chokes before its end: no such flow
    const double m2 = bisect([&](double mach) { return fanno(mach) - target; }, m1, 1.0);
    const double k = (g + 1) / (2 * (g - 1));
    return pt_in * (m1 / m2) * std::pow((2 + (g - 1) * m2 * m2) / (2 + (g - 1) * m1 * m1), k);
  };
  return bisect([&](double m) { return outlet_pt(m) - pt_out; }, 1e-9, 0.999 * flow(1.0));
}

Network pipes_network(const std::vector<Pipe>& pipes) {
  Network net;
  net.gas = kAir;
  net.nodes.push_back({1, "supply", NodeKind::Supply, "", kUnset, kUnset, kPt, kTt});
  net.nodes.push_back({2, "sink", NodeKind::Sink, "", kUnset, kUnset, kSink, kTt});
  for (const Pipe& p : pipes) {
    Element e;
    e.id = static_cast<int>(net.elements.size()) + 1;
    e.name = "pipe_" + std::to_string(e.id);
    e.upstream = 1;
    e.downstream = 2;
    e.area_in = e.area_out = p.area;
    e.hydraulic_diameter = p.dh;
    e.length = p.length;
    e.roughness = p.ks;
    net.elements.push_back(e);
  }
  return net;
}

NetworkSolution solve(const Network& net) {
  test::TempDir dir("network_deck");
  SolveOptions o;
  o.time_limit_s = 30;
  o.work_dir = dir.path / "ccx";
  NetworkSolution s = solve_network(net, ccx_deck(net), o);
  BOOST_TEST_REQUIRE(std::string(name(s.status)) == "converged", s.message);
  return s;
}

}  // namespace

// ccx's Fanno pipe against the exact integration: a smooth pipe agrees to 1e-5 (the .dat's 7 digits), a
// rough one (k_s / D 0.004) to 1.2e-4 measured (ccx's Colebrook evaluation differs in the 4th digit of
// the friction factor): tolerance 2e-4 relative.
BOOST_AUTO_TEST_CASE(straight_pipe_matches_exact_fanno_colebrook) {
  for (const Pipe& p : {Pipe{12.57, 4.0, 60.0, 0.0}, Pipe{30.0, 5.0, 120.0, 0.02}}) {
    const NetworkSolution s = solve(pipes_network({p}));
    const double exact = fanno_mass_flow(p, kPt, kSink);
    BOOST_TEST(std::abs(s.mass_flow[0] - exact) / exact < (p.ks > 0 ? 2e-4 : 1e-5), "ccx " << s.mass_flow[0] << " kg/s, exact " << exact);
  }
}

// Two pipes from one supply to one sink: each carries the flow of its own resistance (the exact
// integration of each alone), so their ratio is the resistance ratio's.
BOOST_AUTO_TEST_CASE(two_branch_split_follows_the_resistances) {
  const Pipe a{12.57, 4.0, 40.0, 0.0}, b{12.57, 4.0, 160.0, 0.0};
  const NetworkSolution s = solve(pipes_network({a, b}));
  const double ea = fanno_mass_flow(a, kPt, kSink), eb = fanno_mass_flow(b, kPt, kSink);
  BOOST_TEST(std::abs(s.mass_flow[0] / s.mass_flow[1] - ea / eb) / (ea / eb) < 1e-5,
             "ccx split " << s.mass_flow[0] / s.mass_flow[1] << ", exact " << ea / eb);
  BOOST_TEST(s.mass_flow[0] / s.mass_flow[1] > 1.5);  // the short pipe takes clearly more
}
