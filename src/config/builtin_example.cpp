#include "src/config/builtin_example.hpp"

namespace cg::config {

const char* builtin_example_json() {
  return R"json({
  "$schema": "../schema/coolinggen.schema.json",
  "name": "hpt_rotor",
  "description": "High-pressure turbine rotor blade at engine scale: hub radius ~275 mm, span ~55 mm, axial chord ~36 mm; curved hub and casing contours, three parametric sections with twist and thickness taper, fitted between the LE and TE lines. Cooled: 1 mm wall, a radial LE chamber and a 3-pass serpentine (ribs 2 and 3 turn at the tip and the hub), filleted ribs, two hub inlets. Coolant: 2.5 MPa / 850 K supply at 13000 rpm (blade speed ~375-450 m/s), hot-gas static pressures per kind of exit.",
  "units": "mm",
  "flow_path": {
    "type": "meridional",
    "hub": [[-30.0, 272.0], [0.0, 275.0], [20.0, 277.5], [40.0, 279.0], [70.0, 280.0]],
    "casing": [[-30.0, 334.0], [0.0, 331.0], [20.0, 329.5], [40.0, 329.0], [70.0, 330.0]],
    "streamlines": [0.25, 0.5, 0.75],
    "leading_edge": [[0.0, 265.0], [3.0, 340.0]],
    "trailing_edge": [[36.0, 265.0], [38.0, 340.0]]
  },
  "sections": [
    {"span": 0.0, "parametric": {"chord": 38.0, "stagger_deg": -22.0, "inlet_metal_angle_deg": 45.0,
      "outlet_metal_angle_deg": -66.0, "max_thickness": 9.0, "max_thickness_position": 0.3,
      "le_radius": 2.0, "te_radius": 0.6}},
    {"span": 0.5, "parametric": {"chord": 38.0, "stagger_deg": -26.0, "inlet_metal_angle_deg": 38.0,
      "outlet_metal_angle_deg": -64.0, "max_thickness": 7.5, "max_thickness_position": 0.3,
      "le_radius": 1.65, "te_radius": 0.6}},
    {"span": 1.0, "parametric": {"chord": 38.0, "stagger_deg": -30.0, "inlet_metal_angle_deg": 30.0,
      "outlet_metal_angle_deg": -62.0, "max_thickness": 6.0, "max_thickness_position": 0.32,
      "le_radius": 1.3, "te_radius": 0.5}}
  ],
  "blade": {"overbuild": 0.05, "chordwise_samples": 97, "stacking": "centroid"},
  "cooling": {
    "core": {
      "wall_thickness": 1.0,
      "tip_cap": {"thickness": 1.2},
      "hub_floor": {"thickness": 2.0},
      "ribs": [
        {"suction_chord": 0.24, "pressure_chord": -0.2, "thickness": 1.0, "fillet_radius": 0.5},
        {"suction_chord": 0.46, "pressure_chord": -0.44, "thickness": 1.0, "fillet_radius": 0.5,
          "turnaround": {"end": "tip", "gap": 2.5, "tip_radius": 0.5}},
        {"suction_chord": 0.68, "pressure_chord": -0.66, "thickness": 1.0, "fillet_radius": 0.5,
          "turnaround": {"end": "hub", "gap": 2.5, "tip_radius": 0.5}}
      ],
      "inlets": [{"chamber": 1, "end": "hub", "diameter": 2.0}, {"chamber": 2, "end": "hub", "diameter": 2.5}],
      "turbulators": [
        {"chamber": 2, "walls": "pressure", "height": 0.4, "width": 0.5, "pitch": 5.0, "angle_deg": 90},
        {"chamber": 3, "walls": "pressure", "height": 0.4, "width": 0.5, "pitch": 5.0, "angle_deg": 60}
      ],
      "trailing_edge": {"type": "pressure_side_cutback", "slot_height": 0.4, "slot_width": 1.2, "pitch": 2.5,
        "lip_thickness": 0.3, "cutback_length": 0.6, "land_taper_deg": 3.0,
        "pin_fins": {"diameter": 0.8, "spanwise_pitch": 2.5, "streamwise_pitch": 1.6, "rows": 2}}
    },
    "showerhead": {"rows": 3, "diameter": 0.5, "row_spacing_d": 4, "pitch_d": 6, "radial_angle_deg": 30, "toward": "tip",
                   "span_start": 0.1, "span_end": 0.9, "chamber": 1},
    "film_rows": [
      {"shape": "7-7-7", "diameter": 0.33, "chord": -0.16, "span_start": 0.1, "span_end": 0.9, "chamber": 1},
      {"diameter": 0.4, "chord": -0.8, "pitch_d": 5, "inclination_deg": 35, "span_start": 0.1, "span_end": 0.9, "chamber": 4},
      {"diameter": 0.4, "chord": 0.17, "pitch_d": 5, "inclination_deg": 35, "span_start": 0.1, "span_end": 0.9, "chamber": 1},
      {"diameter": 0.4, "chord": 0.35, "pitch_d": 5, "inclination_deg": 30, "compound_deg": 15, "span_start": 0.1, "span_end": 0.9, "chamber": 2},
      {"diameter": 0.4, "chord": 0.57, "pitch_d": 5, "inclination_deg": 30, "span_start": 0.1, "span_end": 0.9, "chamber": 3}
    ]
  },
  "coolant": {
    "supply": {"total_pressure_pa": 2.5e6, "total_temperature_k": 850},
    "sinks": {"static_pressure_pa": 1.3e6, "suction_side_pa": 1.1e6, "pressure_side_pa": 1.4e6, "showerhead_pa": 1.47e6,
              "trailing_edge_pa": 1.15e6, "rows": {"film_row_2": 1.15e6}},
    "rotational_speed_rpm": 13000
  },
  "output": {"step_schema": "AP214"}
}
)json";
}

Config builtin_example_config() { return parse_config_text(builtin_example_json(), ".", "hpt_rotor"); }

}  // namespace cg::config
