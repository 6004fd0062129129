#include <algorithm>
#include <cmath>
#include <map>

#include "src/network/network_json.hpp"

namespace cg::network {
namespace {

using ojson = nlohmann::ordered_json;

struct RowTotals {
  int holes = 0;
  double flow = 0, min_margin = HUGE_VAL, min_ratio = HUGE_VAL, max_ratio = 0, max_mach = 0;
  std::string chamber, sink;
};

// Per node: the largest relative mass imbalance at a junction (|in - out| / max(in, out)).
double worst_imbalance(const Network& net, const NetworkSolution& sol, std::string& where) {
  std::vector<double> in(net.nodes.size(), 0.0), out(net.nodes.size(), 0.0);
  for (const Element& e : net.elements) {
    const double m = sol.mass_flow[static_cast<std::size_t>(e.id - 1)];
    // A negative flow runs against the element's direction.
    (m >= 0 ? out : in)[static_cast<std::size_t>(e.upstream - 1)] += std::abs(m);
    (m >= 0 ? in : out)[static_cast<std::size_t>(e.downstream - 1)] += std::abs(m);
  }
  double worst = 0;
  for (const Node& n : net.nodes) {
    if (n.kind != NodeKind::Junction) continue;
    const std::size_t k = static_cast<std::size_t>(n.id - 1);
    const double scale = std::max(in[k], out[k]);
    const double r = scale > 0 ? std::abs(in[k] - out[k]) / scale : 0;
    if (r >= worst) {
      worst = r;
      where = n.name;
    }
  }
  return worst;
}

}  // namespace

ojson results_json(const Network& net, const NetworkSolution& sol) {
  ojson j;
  j["status"] = name(sol.status);
  j["message"] = sol.message;
  j["iterations"] = sol.iterations;
  j["solver_seconds"] = sol.seconds;
  j["units"] = {{"mass_flow", "kg/s"}, {"pressure", "Pa"}, {"temperature", "K"}};
  if (sol.status != SolveStatus::Converged) return j;
  auto pt = [&](int node) { return sol.pressure[static_cast<std::size_t>(node - 1)]; };
  auto tt = [&](int node) { return sol.temperature[static_cast<std::size_t>(node - 1)]; };
  auto mf = [&](const Element& e) { return sol.mass_flow[static_cast<std::size_t>(e.id - 1)]; };
  double supply = 0, exits = 0;
  for (const Element& e : net.elements) {
    if (net.node(e.upstream).kind == NodeKind::Supply) supply += mf(e);
    if (net.node(e.downstream).kind == NodeKind::Sink) exits += mf(e);
  }
  j["total_mass_flow_kg_s"] = supply;
  j["exit_mass_flow_kg_s"] = exits;
  std::string where;
  const double imbalance = worst_imbalance(net, sol, where);
  j["checks"] = {{"max_relative_node_imbalance", imbalance}, {"at_node", where},
                 {"supply_minus_exits_relative", supply > 0 ? (supply - exits) / supply : 0.0}};
  ojson nodes = ojson::array();
  for (const Node& n : net.nodes) nodes.push_back({{"name", n.name}, {"total_pressure_pa", pt(n.id)}, {"total_temperature_k", tt(n.id)}});
  j["nodes"] = nodes;
  // Chambers: the flow entering from outside the chamber (inlets, jets, bends, open ends).
  std::map<std::string, double> chamber_flow;
  std::vector<std::string> chamber_order;
  for (const Element& e : net.elements) {
    const std::string& to = net.node(e.downstream).chamber;
    if (to.empty() || net.node(e.upstream).chamber == to) continue;
    if (!chamber_flow.count(to)) chamber_order.push_back(to);
    chamber_flow[to] += mf(e);
  }
  // A passage from the supply straight to a sink (one segment, both ends open); a segment from the
  // supply into a station is counted above.
  for (const Element& e : net.elements)
    if (e.kind == ElementKind::Segment && net.node(e.upstream).kind == NodeKind::Supply && net.node(e.downstream).chamber.empty()) {
      if (!chamber_flow.count(e.chamber)) chamber_order.push_back(e.chamber);
      chamber_flow[e.chamber] += mf(e);
    }
  ojson chambers = ojson::array();
  for (const std::string& c : chamber_order)
    chambers.push_back({{"name", c}, {"mass_flow_kg_s", chamber_flow[c]}, {"fraction", supply > 0 ? chamber_flow[c] / supply : 0.0}});
  j["chambers"] = chambers;
  ojson els = ojson::array(), holes = ojson::array();
  std::map<std::string, RowTotals> rows;
  std::vector<std::string> row_order;
  for (const Element& e : net.elements) {
    els.push_back({{"name", e.name}, {"kind", name(e.kind)}, {"mass_flow_kg_s", mf(e)}});
    if (e.kind != ElementKind::FilmHole && e.kind != ElementKind::Slot) continue;
    const double p_up = pt(e.upstream), p_out = net.node(e.downstream).pressure;
    const double ratio = p_up / p_out, margin = (p_up - p_out) / p_out;
    const double mach = isentropic_mach(std::abs(mf(e)), e.opening->metering_area * e.opening->count, p_up, tt(e.upstream), net.gas);
    holes.push_back({{"name", e.name}, {"row", e.opening->row}, {"chamber", e.chamber}, {"mass_flow_kg_s", mf(e)},
                     {"pressure_ratio", ratio}, {"backflow_margin", margin}, {"mach", mach}});
    if (!rows.count(e.opening->row)) row_order.push_back(e.opening->row);
    RowTotals& r = rows[e.opening->row];
    ++r.holes;
    r.flow += mf(e);
    r.min_margin = std::min(r.min_margin, margin);
    r.min_ratio = std::min(r.min_ratio, ratio);
    r.max_ratio = std::max(r.max_ratio, ratio);
    r.max_mach = std::max(r.max_mach, mach);
    r.chamber = e.chamber;
    r.sink = e.opening->sink;
  }
  j["elements"] = els;
  ojson row_list = ojson::array();
  for (const std::string& n : row_order) {
    const RowTotals& r = rows[n];
    row_list.push_back({{"name", n}, {"chamber", r.chamber}, {"sink", r.sink}, {"holes", r.holes}, {"mass_flow_kg_s", r.flow},
                        {"min_pressure_ratio", r.min_ratio}, {"max_pressure_ratio", r.max_ratio},
                        {"min_backflow_margin", r.min_margin}, {"max_mach", r.max_mach}});
  }
  j["rows"] = row_list;
  j["holes"] = holes;
  return j;
}

ojson results_summary(const ojson& results) {
  ojson s;
  s["status"] = results.at("status");
  s["message"] = results.at("message");
  if (results.at("status") != "converged") return s;
  s["total_mass_flow_kg_s"] = results.at("total_mass_flow_kg_s");
  ojson chambers = ojson::object();
  for (const auto& c : results.at("chambers")) chambers[c.at("name").get<std::string>()] = c.at("mass_flow_kg_s");
  s["chamber_mass_flow_kg_s"] = chambers;
  double worst = HUGE_VAL;
  std::string row;
  for (const auto& r : results.at("rows"))
    if (r.at("min_backflow_margin").get<double>() < worst) {
      worst = r.at("min_backflow_margin").get<double>();
      row = r.at("name").get<std::string>();
    }
  if (!row.empty()) {
    s["worst_backflow_margin"] = worst;
    s["worst_backflow_row"] = row;
  }
  return s;
}

}  // namespace cg::network
