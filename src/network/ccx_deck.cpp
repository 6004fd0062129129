#include "src/network/ccx_deck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <Eigen/Dense>

#include "src/core/constants.hpp"
#include "src/network/ccx_layout.hpp"

namespace cg::network {
namespace {

constexpr double kMPa = 1e-6;  // Pa -> MPa (N/mm^2)

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", x);
  std::string s = b;
  if (s.find_first_of(".eE") == std::string::npos) s += ".";
  return s;
}

// Darcy friction factor, Colebrook (fixed-point iteration); laminar 64 / Re below Re 2300.
double colebrook(double re, double relative_roughness) {
  if (re < 2300) return 64 / re;
  double lambda = 0.02;
  for (int i = 0; i < 50; ++i) lambda = std::pow(-2 * std::log10(relative_roughness / 3.7 + 2.51 / (re * std::sqrt(lambda))), -2);
  return lambda;
}

// The guess's model of an element: incompressible, m = C sign(dp) sqrt(|dp|) with C = A sqrt(2 rho / K).
double conductance(const Element& e, double rho) {
  double a = 0, k = 1;
  switch (e.kind) {
    case ElementKind::Segment:
      a = 0.5 * (e.area_in + e.area_out);
      k = 0.02 * e.length / e.hydraulic_diameter + 0.05;
      break;
    case ElementKind::Rotation:
      return 1e3;  // in series with a segment: the segment limits the flow
    case ElementKind::Bend:
      a = std::min(e.area_in, e.area_out);
      k = 1.5;
      break;
    case ElementKind::PinBank:
      a = e.area_in;
      k = e.pins->rows * e.pins->loss_per_row;
      break;
    default:
      a = e.opening->metering_area;
      k = 1 / (0.65 * 0.65);
  }
  return a * 1e-6 * std::sqrt(2 * rho / k);
}

struct Section {
  Section(std::string t, std::string d, std::string n = "") : type(std::move(t)), data(std::move(d)), note(std::move(n)) {}
  std::string type, data;
  std::string note;  // a comment line before it ("" none)
};

// The *FLUID SECTION type and data line of an element.
Section section(const Network& net, const Element& e, double flow, double rho, double t) {
  switch (e.kind) {
    case ElementKind::Segment: {
      // Fanno's equations are ill-conditioned near Mach 0 (ccx oscillated on the C3X vane's plenum-like
      // chambers, Mach ~1e-4): below Mach 0.01 the segment is the incompressible Darcy loss
      // lambda L / D_h (Colebrook at the guessed Reynolds number) as a loss coefficient.
      const double a = 0.5 * (e.area_in + e.area_out);
      const double gamma = net.gas.cp / (net.gas.cp - net.gas.gas_constant);
      const double mach = std::abs(flow) / (a * 1e-6) / (rho * std::sqrt(gamma * net.gas.gas_constant * t));
      if (mach < 0.01) {
        const double re = std::max(std::abs(flow) * e.hydraulic_diameter * 1e-3 / (a * 1e-6 * net.gas.viscosity), 100.0);
        return {"RESTRICTOR USER", num(a) + "," + num(a) + "," + num(e.hydraulic_diameter) + "," +
                                       num(colebrook(re, e.roughness / e.hydraulic_diameter) * std::max(e.length, 1e-3) / e.hydraulic_diameter)};
      }
      return {"GAS PIPE FANNO ADIABATIC", num(a) + "," + num(e.hydraulic_diameter) + "," + num(std::max(e.length, 1e-3)) + "," +
                                              num(e.roughness) + ",1."};
    }
    case ElementKind::Rotation:
      // Downstream radius, upstream radius, efficiency, core swirl ratio, omega (rad/s), no T change.
      return {"VORTEX FORCED", num(e.radius_out) + "," + num(e.radius_in) + ",1.,1.," + num(net.omega) + ",0."};
    case ElementKind::PinBank: {
      // Metzger's loss of all rows at the bank's Reynolds number, on the minimum gap's area.
      const PinBank& b = *e.pins;
      return {"RESTRICTOR USER", num(e.area_in) + "," + num(e.area_in) + "," + num(e.hydraulic_diameter) + "," + num(b.rows * b.loss_per_row),
              "** " + e.name + ": Metzger pin bank, " + std::to_string(b.rows) + " rows x K " + num(b.loss_per_row) + " at Re_D " +
                  num(b.re_d) + ", on the minimum gap's area"};
    }
    case ElementKind::Bend:
      return {"RESTRICTOR BEND IDEL CIRC", num(e.area_in) + "," + num(e.area_out) + "," + num(e.hydraulic_diameter) + "," +
                                               num(e.bend_radius) + "," + num(e.bend_angle_deg)};
    default: {
      // Holes, jets, inlets, slots: an orifice of the metering area (McGreehan & Schotsch Cd, L/d).
      const Opening& o = *e.opening;
      return {"ORIFICE MS_MS", num(o.metering_area) + "," + num(o.diameter) + "," + num(o.metering_length) + ",0.,0."};
    }
  }
}

}  // namespace

namespace {

struct Guess {
  std::vector<double> pressure;  ///< Pa per node
  std::vector<double> flow;      ///< kg/s per element, incompressible
};

Guess guess(const Network& net) {
  const std::size_t n = net.nodes.size();
  double p_sup = 0, p_low = HUGE_VAL, t_sup = 300;
  std::vector<double> p(n, 0.0);
  for (const Node& nd : net.nodes) {
    if (nd.kind == NodeKind::Junction) continue;
    p[static_cast<std::size_t>(nd.id - 1)] = nd.pressure;
    p_low = std::min(p_low, nd.pressure);
    if (nd.kind == NodeKind::Supply) p_sup = std::max(p_sup, nd.pressure), t_sup = nd.temperature;
  }
  // An incompressible solution of the network (every junction's net flow zero), then a strict fall
  // along every element into a junction.
  const double rho = p_sup / (net.gas.gas_constant * t_sup);
  std::vector<double> c(net.elements.size());
  for (const Element& e : net.elements) {
    c[static_cast<std::size_t>(e.id - 1)] = conductance(e, rho);
  }
  // Newton on the junction pressures (flows regularised near dp = 0), damped to a fifth of the range.
  std::vector<int> unknown(n, -1);
  int nu = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (net.nodes[i].kind == NodeKind::Junction) {
      unknown[i] = nu++;
      p[i] = 0.5 * (p_sup + p_low);
    }
  const double eps = 1e-6 * p_sup;
  for (int it = 0; it < 200 && nu > 0; ++it) {
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(nu, nu);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(nu);
    for (const Element& e : net.elements) {
      const std::size_t u = static_cast<std::size_t>(e.upstream - 1), d = static_cast<std::size_t>(e.downstream - 1);
      const double dp = p[u] - p[d], ce = c[static_cast<std::size_t>(e.id - 1)];
      const double m = ce * dp / std::sqrt(std::abs(dp) + eps);
      const double g = ce * (0.5 * std::abs(dp) + eps) / std::pow(std::abs(dp) + eps, 1.5);
      const int iu = unknown[u], id = unknown[d];
      if (iu >= 0) f(iu) -= m, jac(iu, iu) -= g;
      if (id >= 0) f(id) += m, jac(id, id) -= g;
      if (iu >= 0 && id >= 0) jac(iu, id) += g, jac(id, iu) += g;
    }
    Eigen::VectorXd step = jac.fullPivLu().solve(-f);
    const double largest = step.cwiseAbs().maxCoeff(), limit = 0.2 * (p_sup - p_low);
    if (largest > limit) step *= limit / largest;
    for (std::size_t i = 0; i < n; ++i)
      if (unknown[i] >= 0) p[i] += step(unknown[i]);
    if (largest < 1e-9 * p_sup) break;
  }
  Guess out;
  for (const Element& e : net.elements) {
    const double dp = p[static_cast<std::size_t>(e.upstream - 1)] - p[static_cast<std::size_t>(e.downstream - 1)];
    out.flow.push_back(c[static_cast<std::size_t>(e.id - 1)] * dp / std::sqrt(std::abs(dp) + eps));
  }
  const double delta = 1e-6 * p_sup;
  for (std::size_t pass = 0; pass < n; ++pass) {
    bool changed = false;
    for (const Element& e : net.elements) {
      const std::size_t u = static_cast<std::size_t>(e.upstream - 1), d = static_cast<std::size_t>(e.downstream - 1);
      if (net.nodes[d].kind != NodeKind::Junction || p[d] <= p[u] - delta) continue;
      p[d] = p[u] - delta;
      changed = true;
    }
    if (!changed) break;
  }
  out.pressure = std::move(p);
  return out;
}

}  // namespace

std::vector<double> initial_pressures(const Network& net) { return guess(net).pressure; }

std::string ccx_deck(const Network& net) {
  const int nn = static_cast<int>(net.nodes.size()), ne = static_cast<int>(net.elements.size());
  // Every exit gets its own copy of its sink (CalculiX's connectivity check walks the network from the
  // input/output elements and loses a node reached twice in one sweep: shared sink nodes made it report
  // connected elements as unconnected). Inputs: one INOUT element per supply node.
  const DeckLayout layout = deck_layout(net);
  const std::vector<int>& supplies = layout.supplies;
  const std::vector<int>& exits = layout.exits;

  std::string s = "** CoolingGen coolant flow network (docs/network.md); units N, mm, s, tonne, K\n";
  for (const Element& e : net.elements) s += "** element " + std::to_string(e.id) + " " + e.name + "\n";
  for (const Node& n : net.nodes) s += "** node " + std::to_string(n.id) + " " + n.name + "\n";
  if (!exits.empty())
    s += "** nodes " + std::to_string(layout.exit_nodes.front()) + "-" + std::to_string(layout.exit_nodes.back()) +
         ": each exit's copy of its sink\n";
  s += "*NODE,NSET=NCORNER\n";
  for (int id = 1; id <= nn; ++id) s += std::to_string(id) + "," + std::to_string(id) + ".,0.,0.\n";
  for (int id : layout.exit_nodes) s += std::to_string(id) + "," + std::to_string(id) + ".,0.,0.\n";
  s += "*NODE,NSET=NMID\n";
  for (const DeckElement& d : layout.elements) s += std::to_string(d.mid) + "," + std::to_string(d.mid) + ".,1.,0.\n";
  auto line = [](const DeckElement& d) {
    return std::to_string(d.id) + "," + std::to_string(d.first) + "," + std::to_string(d.mid) + "," + std::to_string(d.last) + "\n";
  };
  for (int k = 0; k < ne; ++k) s += "*ELEMENT,TYPE=D,ELSET=E" + std::to_string(k + 1) + "\n" + line(layout.elements[static_cast<std::size_t>(k)]);
  s += "*ELEMENT,TYPE=D,ELSET=EINOUT\n";
  for (std::size_t k = static_cast<std::size_t>(ne); k < layout.elements.size(); ++k) s += line(layout.elements[k]);
  s += "*MATERIAL,NAME=GAS\n*CONDUCTIVITY\n1.\n*FLUID CONSTANTS\n" + num(net.gas.cp * 1e6) + "," +
       num(net.gas.viscosity * 1e-6) + "\n*SPECIFIC GAS CONSTANT\n" + num(net.gas.gas_constant * 1e6) + "\n";
  const Guess g = guess(net);
  double t_gas = 300;
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) t_gas = n.temperature;
  for (const Element& e : net.elements) {
    const double rho = g.pressure[static_cast<std::size_t>(e.upstream - 1)] / (net.gas.gas_constant * t_gas);
    const Section sec = section(net, e, g.flow[static_cast<std::size_t>(e.id - 1)], rho, t_gas);
    if (!sec.note.empty()) s += sec.note + "\n";
    s += "*FLUID SECTION,ELSET=E" + std::to_string(e.id) + ",TYPE=" + sec.type + ",MATERIAL=GAS\n" + sec.data + "\n";
  }
  s += "*FLUID SECTION,ELSET=EINOUT,TYPE=INOUT,MATERIAL=GAS\n";
  s += "*PHYSICAL CONSTANTS,ABSOLUTE ZERO=0.\n";
  const std::vector<double>& p = g.pressure;
  double t_supply = 0;
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) t_supply = n.temperature;
  // Fixed pressure and temperature: supplies (total) and the exits' sink copies (static).
  std::vector<std::pair<int, const Node*>> fixed;
  for (int node : supplies) fixed.emplace_back(node, &net.node(node));
  for (std::size_t k = 0; k < exits.size(); ++k)
    fixed.emplace_back(layout.exit_nodes[k], &net.node(net.elements[static_cast<std::size_t>(exits[k] - 1)].downstream));
  s += "*INITIAL CONDITIONS,TYPE=TOTAL PRESSURE\n";
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Junction) s += std::to_string(n.id) + "," + num(p[static_cast<std::size_t>(n.id - 1)] * kMPa) + "\n";
  for (const auto& [id, n] : fixed) s += std::to_string(id) + "," + num(n->pressure * kMPa) + "\n";
  s += "*INITIAL CONDITIONS,TYPE=TEMPERATURE\n";
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Junction) s += std::to_string(n.id) + "," + num(t_supply) + "\n";
  for (const auto& f : fixed) s += std::to_string(f.first) + "," + num(t_supply) + "\n";
  s += "*STEP\n*HEAT TRANSFER,STEADY STATE\n1.,1.\n*BOUNDARY\n";
  for (const auto& [id, n] : fixed) {
    s += std::to_string(id) + ",2,2," + num(n->pressure * kMPa) + "\n";
    s += std::to_string(id) + ",11,11," + num(n->kind == NodeKind::Supply ? n->temperature : t_supply) + "\n";
  }
  s += "*NODE PRINT,NSET=NCORNER\nPN,NT\n*NODE PRINT,NSET=NMID\nMF\n*END STEP\n";
  return s;
}

}  // namespace cg::network
