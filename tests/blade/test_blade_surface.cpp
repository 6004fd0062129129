// Blade surface and blade-relative coordinates: the C3X vane (straight) and an HPT rotor on a curved
// meridional net.
#define BOOST_TEST_MODULE blade_surface
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "blade/blade_fixtures.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/blade/section_3d.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::blade;

using namespace cg::blade::test;

namespace {

// Largest coordinate error of point() -> locate() over n random (span, chord, depth) samples.
double worst_round_trip(const BladeCoordinates& bc, unsigned seed, int n, std::pair<double, double> spans,
                        double max_chord, double max_depth) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> span(spans.first, spans.second), chord(-max_chord, max_chord),
      depth(0.0, max_depth);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const BladeCoordinate c{span(rng), chord(rng), depth(rng)};
    const BladeLocateResult r = bc.locate(bc.point(c));
    BOOST_TEST_REQUIRE(r.found);
    worst = std::max({worst, std::abs(r.coordinate.span - c.span), std::abs(r.coordinate.chord - c.chord),
                      std::abs(r.coordinate.depth - c.depth)});
  }
  return worst;
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
  // Geometrically exact: one section on a straight vane is skinned as it is (its seam moved to the TE,
  // exactly: knot insertion), so every iso-curve is the 2D section curve lifted to z = v * span (1e-9 mm:
  // the skinning solve is exact up to rounding, measured ~1e-13 mm), and the published points lie on it.
  const SectionProfile& prof = m.profiles[0];
  BOOST_TEST(m.surface_deviation < 1e-9);
  CurveProjector<2> on_profile(prof.curve);
  double worst_iso = 0;
  for (int i = 0; i <= 1000; ++i)
    for (double v : {-0.05, 0.0, 0.37, 1.0, 1.05}) {
      const double u = i / 1000.0;
      const Eigen::Vector3d p = S.point(u, v);
      worst_iso = std::max({worst_iso, std::abs(p.z() - v * 144.93), on_profile.project(p.head<2>()).distance,
                            (m.section_curves[0].point(u).head<2>() - p.head<2>()).norm()});
    }
  BOOST_TEST_MESSAGE("C3X surface vs section curve: max deviation " << worst_iso << " mm");
  BOOST_TEST(worst_iso < 1e-9);
  const auto pts = read_section_points(kC3x, LengthUnit::Centimetre);
  CurveProjector<3> proj(m.section_curves[0]);
  double worst = 0;
  for (const auto& p : pts) worst = std::max(worst, proj.project(Eigen::Vector3d(p.x(), p.y(), 0)).distance);
  BOOST_TEST_MESSAGE("C3X section vs published points: max distance " << worst << " mm");
  BOOST_TEST(worst < 1e-9);
  // The seam (u = 0) is the TE (default seam +1), the LE at u_le, on every span.
  BOOST_TEST(m.u_te == 0.0);
  for (double v : {0.0, 0.5, 1.0}) {
    BOOST_TEST((S.point(m.u_le, v).head<2>() - prof.le).norm() < 1e-9);
    BOOST_TEST((S.point(m.u_te, v).head<2>() - prof.te).norm() < 1e-9);
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
  const double worst = worst_round_trip(bc, 7, 300, {-0.04, 1.04}, 0.97, 0.8);
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
  BOOST_TEST(m.u_te == 0.0);  // the seam at the TE
  BOOST_TEST(m.u_le == 0.5);  // parametric sections: LE at phi = 0, TE at phi = pi
  BOOST_TEST(m.surface_deviation <= m.surface_tolerance);
  const MeridionalNet& net = *m.net;
  for (std::size_t k = 0; k < m.section_spans.size(); ++k) {
    const double span = m.section_spans[k];
    const Streamline line = net.streamline_at(span);
    CurveProjector<2> on_line(line.curve());
    CurveProjector<2> on_le(net.leading_edge()->curve), on_te(net.trailing_edge()->curve);
    // The section is an iso-curve of the surface (1e-10 mm: exact extraction) and lies on its stream
    // surface within the surface tolerance (1e-3 mm by default).
    double worst_iso = 0;
    for (int i = 0; i <= 400; ++i)
      worst_iso = std::max(worst_iso, (m.surface.point(i / 400.0, span) - m.section_curves[k].point(i / 400.0)).norm());
    BOOST_TEST(worst_iso < 1e-10);
    double worst_on = 0;
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector3d p = m.surface.point(i / 400.0, span);
      const Eigen::Vector2d xr(p.x(), std::hypot(p.y(), p.z()));
      worst_on = std::max(worst_on, on_line.project(xr).distance);
    }
    BOOST_TEST_MESSAGE("span " << span << ": max distance from the stream surface " << worst_on << " mm");
    BOOST_TEST(worst_on < m.surface_tolerance);
    // LE on the LE line and TE on the TE line, within the surface tolerance.
    const Eigen::Vector3d le = m.surface.point(m.u_le, span), te = m.surface.point(m.u_te, span);
    BOOST_TEST(on_le.project(Eigen::Vector2d(le.x(), std::hypot(le.y(), le.z()))).distance < m.surface_tolerance);
    BOOST_TEST(on_te.project(Eigen::Vector2d(te.x(), std::hypot(te.y(), te.z()))).distance < m.surface_tolerance);
  }
  // Blade-relative coordinates round trip on the curved blade.
  BladeCoordinates bc(m);
  const double worst = worst_round_trip(bc, 11, 200, {0.0, 1.0}, 0.95, 0.25);
  // Global projection then Newton polish: the coordinates come back to rounding (measured ~1e-12).
  BOOST_TEST_MESSAGE("HPT round trip worst " << worst);
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_CASE(placed_section_curves) {
  PointSectionDefinition def;
  def.file = kC3x;
  def.unit = LengthUnit::Centimetre;
  const SectionProfile s = section_from_points(def);
  // In a plane: exact (same knots and weights), checked against the 2D curve to rounding.
  const BSplineCurve<3> flat = detail::section_in_plane(s.curve, 12.5);
  for (int i = 0; i <= 500; ++i) {
    const double u = i / 500.0;
    BOOST_TEST((flat.point(u) - Eigen::Vector3d(s.curve.point(u).x(), s.curve.point(u).y(), 12.5)).norm() < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(invalid_blades) {
  {
    BladeDefinition d = c3x_vane();
    d.flow_path = StraightFlowPath{-1};
    BOOST_CHECK_THROW(build_blade(d), InvalidGeometry);
  }
  for (double ob : {0.7, 0.0, -0.1}) {  // overbuild in (0, 0.5], as the schema
    BladeDefinition d = c3x_vane();
    d.options.overbuild = ob;
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
