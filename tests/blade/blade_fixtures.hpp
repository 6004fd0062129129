#pragma once
// Shared blade test fixtures: the C3X vane (straight, NASA CR-168015 Table III profile), the HPT rotor on
// a curved meridional net (three parametric sections) and the shoelace area of a closed polygon.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/blade/blade_surface.hpp"

namespace cg::blade::test {

inline const std::string kC3x = std::string(COOLINGGEN_SOURCE_DIR) + "/data/c3x/profile_table3_cm.csv";

inline BladeDefinition c3x_vane() {
  BladeDefinition d;
  d.flow_path = StraightFlowPath{144.93};
  PointSectionDefinition p;
  p.file = kC3x;
  p.unit = LengthUnit::Centimetre;
  BladeSectionDefinition s;
  s.shape = p;
  d.sections = {s};
  return d;
}

inline ParametricSectionDefinition rotor_section(double tmax, double inlet, double outlet, double stagger) {
  ParametricSectionDefinition p;
  p.chord = 38;
  p.stagger_deg = stagger;
  p.inlet_angle_deg = inlet;
  p.outlet_angle_deg = outlet;
  p.max_thickness = tmax;
  p.max_thickness_position = 0.3;
  p.le_radius = 0.22 * tmax;
  p.te_radius = 0.6;
  return p;
}

inline BladeDefinition hpt_rotor() {
  BladeDefinition d;
  MeridionalNetDefinition net;
  net.hub = {{-30, 272}, {0, 275}, {20, 277.5}, {40, 279}, {70, 280}};
  net.casing = {{-30, 334}, {0, 331}, {20, 329.5}, {40, 329}, {70, 330}};
  net.leading_edge = {{0, 265}, {3, 340}};
  net.trailing_edge = {{36, 265}, {38, 340}};
  d.flow_path = MeridionalFlowPath{net};
  const double spans[] = {0.0, 0.5, 1.0};
  const double tmax[] = {9, 7.5, 6}, inlet[] = {45, 38, 30}, outlet[] = {-66, -64, -62}, stagger[] = {-22, -26, -30};
  for (int k = 0; k < 3; ++k) {
    BladeSectionDefinition s;
    s.shape = rotor_section(tmax[k], inlet[k], outlet[k], stagger[k]);
    s.placement.span = spans[k];
    d.sections.push_back(s);
  }
  return d;
}


/// Symmetric profile on a straight camber: LE at the origin, TE at (50, 0), tip radii 2 and 0.5 mm.
inline ParametricSectionDefinition symmetric_section(int points_per_side) {
  ParametricSectionDefinition d;
  d.chord = 50;
  d.max_thickness = 8;
  d.max_thickness_position = 0.35;
  d.le_radius = 2;
  d.te_radius = 0.5;
  d.points_per_side = points_per_side;
  return d;
}

/// Signed area of the closed polygon (counter-clockwise positive).
inline double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& q = p[i];
    const Eigen::Vector2d& r = p[(i + 1) % p.size()];
    a += q.x() * r.y() - q.y() * r.x();
  }
  return 0.5 * a;
}

}  // namespace cg::blade::test
