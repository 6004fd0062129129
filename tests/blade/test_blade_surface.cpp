// Blade surface and blade-relative coordinates: the C3X vane (straight) and an HPT rotor on a curved
// meridional net.
#define BOOST_TEST_MODULE blade_surface
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "src/algo/project_point_curve.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::blade;

namespace {

const std::string kC3x = std::string(COOLINGGEN_SOURCE_DIR) + "/data/c3x/profile_table3_cm.csv";

BladeDefinition c3x_vane() {
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

ParametricSectionDefinition rotor_section(double tmax, double inlet, double outlet, double stagger) {
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

BladeDefinition hpt_rotor() {
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

}  // namespace

BOOST_AUTO_TEST_CASE(c3x_vane_surface) {
  const BladeDefinition def = c3x_vane();
  const BladeModel m = build_blade(def);
  const BSplineSurface<3>& S = m.surface;
  BOOST_TEST(S.is_periodic_u());
  BOOST_TEST(!S.is_periodic_v());
  BOOST_TEST(std::abs(S.first_v() + 0.05) < 1e-15);
  BOOST_TEST(std::abs(S.last_v() - 1.05) < 1e-15);
  BOOST_TEST(m.trim.straight);
  BOOST_TEST(m.trim.casing_z == 144.93);
  BOOST_TEST_REQUIRE(m.section_curves.size() == 2u);

  // Periodic in u: value and first two derivatives agree across the seam (C2 cubic).
  for (double v : {-0.05, 0.3, 1.05}) {
    Eigen::Vector3d a[9], b[9];
    S.derivatives(S.first_u(), v, 2, a);
    S.derivatives(S.last_u(), v, 2, b);
    for (int k : {0, 3, 6}) BOOST_TEST((a[k] - b[k]).norm() < 1e-9 * (1 + a[k].norm()));
  }
  // Prismatic: z = span fraction * span, and the same section everywhere.
  const auto pts = read_section_points(kC3x, LengthUnit::Centimetre);
  CurveProjector<3> proj(m.section_curves[0]);
  double worst = 0;
  for (const auto& p : pts) worst = std::max(worst, proj.project(Eigen::Vector3d(p.x(), p.y(), 0)).distance);
  // The 3D section is re-interpolated through 2 x 97 cosine-clustered samples of the 2D section (default
  // chordwise_samples): measured 8.0e-3 mm from the published points (5.5e-5 of chord; error ~ h^4, 161
  // samples give 2.0e-3 mm), so 1e-2 mm, and 2.5e-3 mm with 161 samples.
  BOOST_TEST_MESSAGE("C3X section vs published points: max distance " << worst << " mm");
  BOOST_TEST(worst < 1e-2);
  {
    BladeDefinition fine = def;
    fine.options.chordwise_samples = 161;
    const BladeModel mf = build_blade(fine);
    CurveProjector<3> pf(mf.section_curves[0]);
    double w = 0;
    for (const auto& p : pts) w = std::max(w, pf.project(Eigen::Vector3d(p.x(), p.y(), 0)).distance);
    BOOST_TEST(w < 2.5e-3);
  }
  for (int i = 0; i <= 50; ++i)
    for (double v : {-0.05, 0.0, 0.37, 1.0, 1.05}) {
      const double u = S.first_u() + (S.last_u() - S.first_u()) * i / 50.0;
      const Eigen::Vector3d p = S.point(u, v), q = m.section_curves[0].point(u);
      BOOST_TEST(std::abs(p.z() - v * 144.93) < 1e-9);
      BOOST_TEST((p.head<2>() - q.head<2>()).norm() < 1e-9);
    }
  // Section area at mid-span equals that of the profile (straight vane: the volume between two planes
  // is area * height).
  BOOST_TEST(std::abs(std::abs(section_properties(m.profiles[0].curve).area) - 2538.44) < 0.01);
}

BOOST_AUTO_TEST_CASE(c3x_blade_coordinates_round_trip) {
  const BladeModel m = build_blade(c3x_vane());
  BladeCoordinates bc(m);
  // LE faces the oncoming flow: the outward normal at c = 0 points up the chord line (towards -chord).
  const BladeFrame le = bc.frame(0.5, 0.0);
  BOOST_TEST(le.normal.head<2>().dot(m.profiles[0].chord_direction) < -0.9);
  BOOST_TEST(std::abs(le.normal.dot(le.span_tangent)) < 1e-12);
  BOOST_TEST(std::abs(le.normal.dot(le.chord_tangent)) < 1e-12);
  BOOST_TEST(le.span_tangent.z() > 0.999999);
  // Suction side lies on the convex side: its normal at mid-chord points away from the pressure side.
  const BladeFrame ss = bc.frame(0.5, 0.5), ps = bc.frame(0.5, -0.5);
  BOOST_TEST((ss.point - ps.point).dot(ss.normal) > 0);
  BOOST_TEST((ps.point - ss.point).dot(ps.normal) > 0);

  // Round trip: (span, chord, depth) -> point -> locate. Depth up to 0.8 mm (less than half the TE
  // thickness), chord away from the TE identification +-1. Parameters agree to 1e-9 (brief), depth to
  // 1e-9 mm.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> span(-0.04, 1.04), chord(-0.97, 0.97), depth(0.0, 0.8);
  double worst = 0;
  for (int k = 0; k < 300; ++k) {
    const BladeCoordinate c{span(rng), chord(rng), depth(rng)};
    const BladeLocateResult r = bc.locate(bc.point(c));
    BOOST_TEST_REQUIRE(r.found);
    worst = std::max({worst, std::abs(r.coordinate.span - c.span), std::abs(r.coordinate.chord - c.chord),
                      std::abs(r.coordinate.depth - c.depth)});
  }
  BOOST_TEST_MESSAGE("C3X round trip worst " << worst);
  BOOST_TEST(worst < 1e-9);
  // Beyond the over-build: not found.
  const BladeFrame top = bc.frame(1.05, 0.3);
  BOOST_TEST(!bc.locate(top.point + Eigen::Vector3d(0, 0, 5)).found);
}

BOOST_AUTO_TEST_CASE(hpt_rotor_on_meridional_net) {
  const BladeDefinition def = hpt_rotor();
  const BladeModel m = build_blade(def);
  BOOST_TEST_REQUIRE(m.net.has_value());
  BOOST_TEST(!m.trim.straight);
  BOOST_TEST(m.span_length > 50);
  BOOST_TEST(m.span_length < 60);
  const MeridionalNet& net = *m.net;
  for (std::size_t k = 0; k < m.section_spans.size(); ++k) {
    const double span = m.section_spans[k];
    const Streamline line = net.streamline_at(span);
    CurveProjector<2> on_line(line.curve());
    CurveProjector<2> on_le(net.leading_edge()->curve), on_te(net.trailing_edge()->curve);
    // Every sampled section point lies on its stream surface (the section curve interpolates them; between
    // samples the deviation is interpolation error, bounded here by 2 um).
    double worst_on = 0;
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector3d p = m.surface.point(i / 400.0, span);
      const Eigen::Vector2d xr(p.x(), std::hypot(p.y(), p.z()));
      worst_on = std::max(worst_on, on_line.project(xr).distance);
    }
    BOOST_TEST_MESSAGE("span " << span << ": max distance from the stream surface " << worst_on << " mm");
    BOOST_TEST(worst_on < 2e-3);
    // LE on the LE line and TE on the TE line (sample points: exact up to rounding).
    const Eigen::Vector3d le = m.surface.point(0.0, span), te = m.surface.point(m.u_te, span);
    BOOST_TEST(on_le.project(Eigen::Vector2d(le.x(), std::hypot(le.y(), le.z()))).distance < 1e-8);
    BOOST_TEST(on_te.project(Eigen::Vector2d(te.x(), std::hypot(te.y(), te.z()))).distance < 1e-8);
  }
  // Blade-relative coordinates round trip on the curved blade.
  BladeCoordinates bc(m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> span(0.0, 1.0), chord(-0.95, 0.95), depth(0.0, 0.25);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const BladeCoordinate c{span(rng), chord(rng), depth(rng)};
    const BladeLocateResult r = bc.locate(bc.point(c));
    BOOST_TEST_REQUIRE(r.found);
    worst = std::max({worst, std::abs(r.coordinate.span - c.span), std::abs(r.coordinate.chord - c.chord),
                      std::abs(r.coordinate.depth - c.depth)});
  }
  BOOST_TEST_MESSAGE("HPT round trip worst " << worst);
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_CASE(chordwise_mapping) {
  for (double ute : {0.3, 0.5, 0.61}) {
    BOOST_TEST(surface_u_at_chordwise(0, ute) == 0);
    BOOST_TEST(surface_u_at_chordwise(1, ute) == ute);
    BOOST_TEST(surface_u_at_chordwise(-1, ute) == ute);
    for (double c = -0.99; c < 1; c += 0.07)
      BOOST_TEST(std::abs(chordwise_at_surface_u(surface_u_at_chordwise(c, ute), ute) - c) < 1e-15);
  }
  BOOST_CHECK_THROW(surface_u_at_chordwise(1.2, 0.5), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(invalid_blades) {
  {
    BladeDefinition d = c3x_vane();
    d.flow_path = StraightFlowPath{-1};
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {
    BladeDefinition d = c3x_vane();
    d.options.overbuild = 0.7;
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {
    BladeDefinition d = c3x_vane();
    d.sections.clear();
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {  // spans not increasing
    BladeDefinition d = hpt_rotor();
    d.sections[1].placement.span = 1.0;
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {  // negative thickness in one section
    BladeDefinition d = hpt_rotor();
    std::get<ParametricSectionDefinition>(d.sections[1].shape).max_thickness = -1;
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {  // meridional without LE line
    BladeDefinition d = hpt_rotor();
    std::get<MeridionalFlowPath>(d.flow_path).net.leading_edge.clear();
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {  // TE line upstream of the LE line
    BladeDefinition d = hpt_rotor();
    auto& net = std::get<MeridionalFlowPath>(d.flow_path).net;
    std::swap(net.leading_edge, net.trailing_edge);
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  {  // section running past the end of the streamlines
    BladeDefinition d = hpt_rotor();
    auto& net = std::get<MeridionalFlowPath>(d.flow_path).net;
    // The LE line cuts the hub at x = 0.4 and the casing at x = 2.64; the LE circle reaches ~0.5 mm
    // further upstream than the LE point.
    net.hub = {{0.3, 275.05}, {20, 277.5}, {40, 279}, {70, 280}};
    net.casing = {{2.5, 331.1}, {20, 329.5}, {40, 329}, {70, 330}};
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
}
