#include "src/config/builtin_example.hpp"

namespace cg::config {

const char* builtin_example_json() {
  return R"json({
  "name": "hpt_rotor",
  "description": "Built-in example: high-pressure turbine rotor blade, three parametric sections on a conical hub and flared casing",
  "units": "mm",
  "flow_path": {
    "type": "meridional",
    "hub": [[-10.0, 250.0], [45.0, 252.0]],
    "casing": [[-10.0, 291.0], [17.5, 292.5], [45.0, 295.0]],
    "streamlines": [0.5],
    "leading_edge": [[5.0, 248.0], [6.0, 297.5]],
    "trailing_edge": [[31.0, 248.0], [29.5, 298.0]]
  },
  "sections": [
    {"span": 0.0, "parametric": {"chord": 30.0, "stagger_deg": -30.0, "inlet_metal_angle_deg": 40.0,
      "outlet_metal_angle_deg": -62.0, "max_thickness": 7.5, "max_thickness_position": 0.3,
      "le_radius": 1.6, "te_radius": 0.5}},
    {"span": 0.5, "parametric": {"chord": 30.0, "stagger_deg": -34.0, "inlet_metal_angle_deg": 30.0,
      "outlet_metal_angle_deg": -64.0, "max_thickness": 6.2, "max_thickness_position": 0.32,
      "le_radius": 1.4, "te_radius": 0.45}},
    {"span": 1.0, "parametric": {"chord": 30.0, "stagger_deg": -38.0, "inlet_metal_angle_deg": 20.0,
      "outlet_metal_angle_deg": -66.0, "max_thickness": 5.0, "max_thickness_position": 0.34,
      "le_radius": 1.2, "te_radius": 0.4}}
  ],
  "blade": {"overbuild": 0.05, "chordwise_samples": 97, "stacking": "centroid"},
  "output": {"step_schema": "AP214"}
}
)json";
}

Config builtin_example_config() { return parse_config_text(builtin_example_json(), ".", "hpt_rotor"); }

}  // namespace cg::config
