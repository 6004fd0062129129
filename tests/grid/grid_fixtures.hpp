#pragma once
// Sections for the grid tests: the C3X vane profile (NASA CR-168015 Table III, as data/examples/c3x_vane.json)
// and the mid section of the built-in HPT rotor example (data/examples/hpt_rotor.json, span 0.5).
#include <string>

#include "src/blade/section.hpp"

namespace cg::grid::test {

inline const blade::SectionProfile& c3x_section() {
  static const blade::SectionProfile s = [] {
    blade::PointSectionDefinition p;
    p.file = std::string(COOLINGGEN_SOURCE_DIR) + "/data/c3x/profile_table3_cm.csv";
    p.unit = blade::LengthUnit::Centimetre;
    return blade::section_from_points(p);
  }();
  return s;
}

inline const blade::SectionProfile& rotor_section() {
  static const blade::SectionProfile s = [] {
    blade::ParametricSectionDefinition p;
    p.chord = 38;
    p.stagger_deg = -26;
    p.inlet_angle_deg = 38;
    p.outlet_angle_deg = -64;
    p.max_thickness = 7.5;
    p.max_thickness_position = 0.3;
    p.le_radius = 1.65;
    p.te_radius = 0.6;
    return blade::section_from_parameters(p);
  }();
  return s;
}

constexpr double kC3xPitch = 117.73;  // mm, NASA CR-168015
constexpr double kRotorPitch = 31.4;  // mm: 60 blades at r = 300 mm

}  // namespace cg::grid::test
