#include "src/network/film_holes_csv.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "src/core/format.hpp"
#include "src/network/network_json.hpp"

namespace cg::network {
std::string film_holes_csv(const features::FilmReport& film, const Network* net, const NetworkSolution* sol) {
  std::map<std::string, double> flow;
  if (net && sol && sol->status == SolveStatus::Converged)
    for (const Element& e : net->elements)
      if (e.kind == ElementKind::FilmHole) flow[e.name] = sol->mass_flow[static_cast<std::size_t>(e.id - 1)];
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
  return s;
}

}  // namespace cg::network
