#include "src/network/film_holes_csv.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "src/core/format.hpp"
#include "src/network/network_json.hpp"

namespace cg::network {
namespace {

using Vec3 = Eigen::Vector3d;

// One slot's row: the centre of its inlet face, of its opening (under the lip: cutback; the TE point:
// centreline, x_lip = te_x there), the axis between them and its hydraulic diameter.
std::string slot_row(const features::SlotInfo& s, const std::string& chamber) {
  const auto at = [&](double x, double y) -> Vec3 { return s.origin + x * s.x + y * s.y; };
  const Vec3 in = at(s.x_inlet, s.y_inlet + 0.5 * s.height), out = at(s.x_lip, s.floor_y + 0.5 * s.height);
  const Vec3 axis = (out - in).normalized();
  const double area = s.width * s.height, d = 2 * area / (s.width + s.height);
  std::string r = s.name + ",te_slots," + chamber + ",slot";
  for (const Vec3* p : {&out, &in, &axis})
    for (int k = 0; k < 3; ++k) r += "," + format_round_trip((*p)[k]);
  r += "," + format_round_trip(d) + "," + format_round_trip((out - in).norm()) + "," + format_round_trip((out - in).norm()) + ",1," +
       format_round_trip(area) + "," + format_round_trip(area) + ",,,";
  return r;
}

}  // namespace

std::string film_holes_csv(const features::FilmReport& film, const std::vector<features::SlotInfo>& slots, const Network* net,
                          const NetworkSolution* sol) {
  std::map<std::string, double> flow;
  if (net && sol && sol->status == SolveStatus::Converged)
    for (const Element& e : net->elements)
      if (e.kind == ElementKind::FilmHole || e.kind == ElementKind::Slot) flow[e.name] = sol->mass_flow[static_cast<std::size_t>(e.id - 1)];
  std::string s =
      "name,row,chamber,shape,exit_x_mm,exit_y_mm,exit_z_mm,inlet_x_mm,inlet_y_mm,inlet_z_mm,axis_x,axis_y,axis_z,"
      "diameter_mm,metering_length_mm,length_mm,exit_area_ratio,metering_area_mm2,exit_area_mm2,inclination_deg,"
      "compound_deg,mass_flow_kg_s\n";
  std::map<std::string, double> compound;
  if (net)
    for (const Element& e : net->elements)
      if (e.kind == ElementKind::FilmHole) compound[e.name] = e.opening->compound_deg;
  for (const features::HoleMeasure& h : film.holes) {
    // The report's axis points into the wall; the table gives the coolant's direction (inlet -> exit).
    const double in[3] = {h.exit[0] + h.length * h.axis[0], h.exit[1] + h.length * h.axis[1], h.exit[2] + h.length * h.axis[2]};
    s += h.name + "," + h.row + "," + h.chamber + "," + h.shape;
    for (double v : h.exit) s += "," + format_round_trip(v);
    for (double v : in) s += "," + format_round_trip(v);
    for (double v : h.axis) s += "," + format_round_trip(-v);
    s += "," + format_round_trip(h.diameter) + "," + format_round_trip(h.metering_length) + "," + format_round_trip(h.length) + "," + format_round_trip(h.area_ratio) + "," +
         format_round_trip(h.metering_area) + "," + format_round_trip(h.exit_area) + "," + format_round_trip(h.inclination_deg) + ",";
    const auto c = compound.find(h.name);
    if (c != compound.end() && std::isfinite(c->second)) s += format_round_trip(c->second);
    s += ",";
    const auto f = flow.find(h.name);
    if (f != flow.end()) s += format_round_trip(f->second);
    s += "\n";
  }
  std::map<std::string, std::string> chamber;  // the chamber each slot's element leaves from
  if (net)
    for (const Element& e : net->elements)
      if (e.kind == ElementKind::Slot) chamber[e.name] = e.chamber;
  for (const features::SlotInfo& slot : slots) {
    const auto c = chamber.find(slot.name);
    s += slot_row(slot, c != chamber.end() ? c->second : "");
    const auto f = flow.find(slot.name);
    if (f != flow.end()) s += format_round_trip(f->second);
    s += "\n";
  }
  return s;
}

}  // namespace cg::network
