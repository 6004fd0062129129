#pragma once
// A light real blade for pipeline tests: the built-in example reduced to its mid-span section as a short
// straight blade, thickened so that a two-chamber core fits (and an insert in the LE chamber: the LE
// radius 2.6 mm exceeds wall + gap + sheet of the tests' inserts, 1.9 mm).
#include <nlohmann/json.hpp>

#include <string>

#include "src/config/builtin_example.hpp"

namespace cg::test {

/// The built-in example's document with `name`, a straight flow path `span` mm high and the mid-span
/// section alone (max_thickness 12 mm, le_radius 2.6 mm). Its cooling is the example's until replaced.
inline nlohmann::json short_example_blade(const std::string& name, double span) {
  nlohmann::json d = nlohmann::json::parse(config::builtin_example_json());
  d["name"] = name;
  d["flow_path"] = {{"type", "straight"}, {"span", span}};
  nlohmann::json mid = d["sections"][1];
  mid["span"] = 0.0;
  mid["parametric"]["max_thickness"] = 12.0;
  mid["parametric"]["le_radius"] = 2.6;
  d["sections"] = nlohmann::json::array({mid});
  return d;
}

/// cooling.core for that blade: two chambers split by one filleted rib, both fed from the hub.
inline nlohmann::json two_chamber_core() {
  return nlohmann::json::parse(R"({
    "wall_thickness": 1.0, "tip_cap": {"thickness": 1.0}, "hub_floor": {"thickness": 1.0},
    "ribs": [{"suction_chord": 0.3, "pressure_chord": -0.3, "thickness": 1.0, "fillet_radius": 0.3}],
    "inlets": [{"chamber": 1, "end": "hub", "diameter": 1.0}, {"chamber": 2, "end": "hub", "diameter": 1.2}]
  })");
}

}  // namespace cg::test
