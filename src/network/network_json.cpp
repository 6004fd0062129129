#include "src/network/network_json.hpp"

#include <cmath>
#include <map>

namespace cg::network {
namespace {

using ojson = nlohmann::ordered_json;

ojson num(double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); }

ojson opening_json(const Opening& o) {
  ojson j;
  j["row"] = o.row;
  j["shape"] = o.shape;
  j["count"] = o.count;
  j["diameter_mm"] = num(o.diameter);
  j["metering_length_mm"] = num(o.metering_length);
  j["length_d"] = num(o.length_d);
  j["inclination_deg"] = num(o.inclination_deg);
  j["compound_deg"] = num(o.compound_deg);
  j["metering_area_mm2"] = num(o.metering_area);
  j["exit_area_mm2"] = num(o.exit_area);
  j["exit_area_ratio"] = num(o.area_ratio);
  if (!std::isnan(o.z_d)) {
    j["z_d"] = num(o.z_d);
    j["x_d"] = num(o.x_d);
    j["y_d"] = num(o.y_d);
  }
  if (!o.sink.empty()) j["sink"] = o.sink;
  return j;
}

}  // namespace

const char* name(NodeKind k) {
  switch (k) {
    case NodeKind::Supply: return "supply";
    case NodeKind::Junction: return "junction";
    case NodeKind::Sink: return "sink";
  }
  return "";
}

const char* name(ElementKind k) {
  switch (k) {
    case ElementKind::Inlet: return "inlet";
    case ElementKind::Segment: return "segment";
    case ElementKind::Bend: return "bend";
    case ElementKind::Rotation: return "rotation";
    case ElementKind::Jets: return "jets";
    case ElementKind::FilmHole: return "film_hole";
    case ElementKind::Slot: return "slot";
    case ElementKind::PinBank: return "pin_bank";
  }
  return "";
}

ojson network_json(const Network& net) {
  ojson j;
  j["units"] = {{"length", "mm"}, {"area", "mm^2"}, {"angle", "deg"}, {"pressure", "Pa"}, {"temperature", "K"}};
  j["gas"] = {{"gas_constant_j_kg_k", net.gas.gas_constant}, {"cp_j_kg_k", net.gas.cp}, {"viscosity_pa_s", net.gas.viscosity}};
  j["omega_rad_s"] = net.omega;
  ojson nodes = ojson::array();
  for (const Node& n : net.nodes) {
    ojson o{{"id", n.id}, {"name", n.name}, {"kind", name(n.kind)}};
    if (!n.chamber.empty()) o["chamber"] = n.chamber;
    if (!std::isnan(n.span)) o["span"] = n.span;
    if (!std::isnan(n.radius)) o["radius_mm"] = n.radius;
    if (!std::isnan(n.pressure)) o[n.kind == NodeKind::Supply ? "total_pressure_pa" : "static_pressure_pa"] = n.pressure;
    if (!std::isnan(n.temperature)) o["total_temperature_k"] = n.temperature;
    nodes.push_back(o);
  }
  j["nodes"] = nodes;
  ojson els = ojson::array();
  for (const Element& e : net.elements) {
    ojson o{{"id", e.id}, {"name", e.name}, {"kind", name(e.kind)}, {"upstream", net.node(e.upstream).name},
            {"downstream", net.node(e.downstream).name}, {"chamber", e.chamber}};
    if (!e.enters_from.empty()) o["enters_from"] = e.enters_from;
    o["length_mm"] = num(e.length);
    o["area_in_mm2"] = num(e.area_in);
    o["area_out_mm2"] = num(e.area_out);
    if (e.perimeter_in > 0) {
      o["wetted_perimeter_in_mm"] = num(e.perimeter_in);
      o["wetted_perimeter_out_mm"] = num(e.perimeter_out);
    }
    o["hydraulic_diameter_mm"] = num(e.hydraulic_diameter);
    if (!std::isnan(e.aspect_ratio)) o["aspect_ratio"] = e.aspect_ratio;
    o["roughness_mm"] = e.roughness;
    o["span_in"] = num(e.span_in);
    o["span_out"] = num(e.span_out);
    if (!std::isnan(e.radius_in)) {
      o["radius_in_mm"] = num(e.radius_in);
      o["radius_out_mm"] = num(e.radius_out);
    }
    if (!std::isnan(e.bend_angle_deg)) {
      o["bend_angle_deg"] = e.bend_angle_deg;
      o["bend_radius_mm"] = e.bend_radius;
      o["bend_radius_dh"] = e.bend_radius / e.hydraulic_diameter;
      if (!std::isnan(e.bend_gap)) {
        o["turnaround_gap_mm"] = e.bend_gap;
        o["turnaround_depth_mm"] = e.bend_depth;
      }
    }
    if (e.turbulators) {
      const Turbulation& t = *e.turbulators;
      o["turbulators"] = {{"e_dh", t.e_dh}, {"p_e", t.p_e}, {"angle_deg", t.angle_deg}, {"walls", t.walls},
                          {"count", t.count}, {"height_mm", t.height}, {"pitch_mm", t.pitch},
                          {"ribbed_wall_fanning_friction", t.friction_factor}, {"ribbed_perimeter_fraction", t.ribbed_fraction},
                          {"correlation", "Han rib roughness function, fully rough; as equivalent sand roughness"}};
    }
    if (e.pins) {
      const PinBank& p = *e.pins;
      o["pin_fins"] = {{"diameter_mm", p.diameter}, {"s_d", p.s_d}, {"x_d", p.x_d}, {"rows", p.rows}, {"pins", p.pins},
                       {"height_mm", p.height}, {"gap_area_mm2", p.gap_area}, {"re_d", p.re_d}, {"loss_per_row", p.loss_per_row},
                       {"correlation", "Metzger staggered short pins: K = 4 f per row at the minimum gap, f = 0.317 Re_D^-0.132 "
                                       "(Re_D 1e3-1e5) at re_d (the solved flow's); in network.inp as RESTRICTOR USER, rows x K (docs/network.md)"}};
    }
    if (e.opening) o["opening"] = opening_json(*e.opening);
    o["faces"] = e.faces;
    els.push_back(o);
  }
  j["elements"] = els;
  j["notes"] = net.notes;
  return j;
}

double isentropic_mach(double m, double a, double pt, double tt, const Gas& gas) {
  const double g = gas.cp / (gas.cp - gas.gas_constant);
  const double area = a * 1e-6;
  auto flow = [&](double mach) {
    return area * pt / std::sqrt(gas.gas_constant * tt) * std::sqrt(g) * mach *
           std::pow(1 + 0.5 * (g - 1) * mach * mach, -(g + 1) / (2 * (g - 1)));
  };
  if (!(m > 0)) return 0;
  if (m >= flow(1.0)) return 1.0;
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (flow(mid) < m ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace cg::network
