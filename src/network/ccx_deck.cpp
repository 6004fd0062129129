#include "src/network/ccx_deck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/core/constants.hpp"

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

// Share of the supply-to-sink drop an element kind takes in the initial guess.
double guess_share(ElementKind k) {
  switch (k) {
    case ElementKind::Inlet:
    case ElementKind::Jets:
      return 0.1;
    case ElementKind::Bend:
      return 0.02;
    case ElementKind::Rotation:
      return 0.002;
    default:
      return 0.005;
  }
}

// The *FLUID SECTION type and data line of an element.
std::pair<std::string, std::string> section(const Network& net, const Element& e) {
  switch (e.kind) {
    case ElementKind::Segment:
      return {"GAS PIPE FANNO ADIABATIC", num(0.5 * (e.area_in + e.area_out)) + "," + num(e.hydraulic_diameter) + "," +
                                              num(std::max(e.length, 1e-3)) + "," + num(e.roughness) + ",1."};
    case ElementKind::Rotation:
      // Downstream radius, upstream radius, efficiency, core swirl ratio, omega (rad/s), no T change.
      return {"VORTEX FORCED", num(e.radius_out) + "," + num(e.radius_in) + ",1.,1.," + num(net.omega) + ",0."};
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

std::vector<double> initial_pressures(const Network& net) {
  const std::size_t n = net.nodes.size();
  std::vector<double> t(n, 0.0);
  // Longest share-weighted path from the supply (the network is acyclic; relaxation in <= n passes).
  for (std::size_t pass = 0; pass < n; ++pass) {
    bool changed = false;
    for (const Element& e : net.elements) {
      const std::size_t u = static_cast<std::size_t>(e.upstream - 1), d = static_cast<std::size_t>(e.downstream - 1);
      if (net.nodes[d].kind != NodeKind::Junction) continue;
      const double v = t[u] + guess_share(e.kind);
      if (v > t[d] + 1e-12) {
        t[d] = v;
        changed = true;
      }
    }
    if (!changed) break;
  }
  double p_sup = 0, p_sink = 0;
  for (const Node& nd : net.nodes) {
    if (nd.kind == NodeKind::Supply) p_sup = std::max(p_sup, nd.pressure);
    if (nd.kind == NodeKind::Sink) p_sink = std::max(p_sink, nd.pressure);
  }
  const double t_max = std::max(1e-9, *std::max_element(t.begin(), t.end()));
  std::vector<double> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Node& nd = net.nodes[i];
    p[i] = nd.kind == NodeKind::Junction ? p_sup - (p_sup - p_sink) * 0.6 * t[i] / t_max : nd.pressure;
  }
  return p;
}

std::string ccx_deck(const Network& net) {
  const int nn = static_cast<int>(net.nodes.size()), ne = static_cast<int>(net.elements.size());
  // Every exit gets its own copy of its sink (CalculiX's connectivity check walks the network from the
  // input/output elements and loses a node reached twice in one sweep: shared sink nodes made it report
  // connected elements as unconnected). Inputs: one INOUT element per supply node.
  std::vector<int> supplies, exits;  // node ids; element ids
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) supplies.push_back(n.id);
  for (const Element& e : net.elements)
    if (net.node(e.downstream).kind == NodeKind::Sink) exits.push_back(e.id);
  const int n_io = static_cast<int>(supplies.size() + exits.size());
  const int copy_base = nn + ne + n_io;  // exit k's sink node: copy_base + k + 1
  std::vector<int> downstream(static_cast<std::size_t>(ne) + 1);
  for (const Element& e : net.elements) downstream[static_cast<std::size_t>(e.id)] = e.downstream;
  for (std::size_t k = 0; k < exits.size(); ++k) downstream[static_cast<std::size_t>(exits[k])] = copy_base + static_cast<int>(k) + 1;

  std::string s = "** CoolingGen coolant flow network (docs/network.md); units N, mm, s, tonne, K\n";
  for (const Element& e : net.elements) s += "** element " + std::to_string(e.id) + " " + e.name + "\n";
  for (const Node& n : net.nodes) s += "** node " + std::to_string(n.id) + " " + n.name + "\n";
  s += "** nodes " + std::to_string(copy_base + 1) + "-" + std::to_string(copy_base + static_cast<int>(exits.size())) +
       ": each exit's copy of its sink\n";
  s += "*NODE,NSET=NCORNER\n";
  for (int id = 1; id <= nn; ++id) s += std::to_string(id) + "," + std::to_string(id) + ".,0.,0.\n";
  for (std::size_t k = 0; k < exits.size(); ++k) {
    const int id = copy_base + static_cast<int>(k) + 1;
    s += std::to_string(id) + "," + std::to_string(id) + ".,0.,0.\n";
  }
  s += "*NODE,NSET=NMID\n";
  for (int k = 1; k <= ne + n_io; ++k) s += std::to_string(nn + k) + "," + std::to_string(nn + k) + ".,1.,0.\n";
  for (const Element& e : net.elements) {
    s += "*ELEMENT,TYPE=D,ELSET=E" + std::to_string(e.id) + "\n";
    s += std::to_string(e.id) + "," + std::to_string(e.upstream) + "," + std::to_string(mid_node(net, e.id)) + "," +
         std::to_string(downstream[static_cast<std::size_t>(e.id)]) + "\n";
  }
  s += "*ELEMENT,TYPE=D,ELSET=EINOUT\n";
  int io = ne;
  for (int node : supplies) {
    ++io;
    s += std::to_string(io) + ",0," + std::to_string(nn + io) + "," + std::to_string(node) + "\n";
  }
  for (int e : exits) {
    ++io;
    s += std::to_string(io) + "," + std::to_string(downstream[static_cast<std::size_t>(e)]) + "," + std::to_string(nn + io) + ",0\n";
  }
  s += "*MATERIAL,NAME=GAS\n*CONDUCTIVITY\n1.\n*FLUID CONSTANTS\n" + num(net.gas.cp * 1e6) + "," +
       num(net.gas.viscosity * 1e-6) + "\n*SPECIFIC GAS CONSTANT\n" + num(net.gas.gas_constant * 1e6) + "\n";
  for (const Element& e : net.elements) {
    const auto [type, data] = section(net, e);
    s += "*FLUID SECTION,ELSET=E" + std::to_string(e.id) + ",TYPE=" + type + ",MATERIAL=GAS\n" + data + "\n";
  }
  s += "*FLUID SECTION,ELSET=EINOUT,TYPE=INOUT,MATERIAL=GAS\n";
  s += "*PHYSICAL CONSTANTS,ABSOLUTE ZERO=0.\n";
  const std::vector<double> p = initial_pressures(net);
  double t_supply = 0;
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Supply) t_supply = n.temperature;
  // Fixed pressure and temperature: supplies (total) and the exits' sink copies (static).
  std::vector<std::pair<int, const Node*>> fixed;
  for (int node : supplies) fixed.emplace_back(node, &net.node(node));
  for (int e : exits) fixed.emplace_back(downstream[static_cast<std::size_t>(e)], &net.node(net.elements[static_cast<std::size_t>(e - 1)].downstream));
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
