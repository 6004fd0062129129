// Film holes on a hollow vane (inner wall = true offset, one chamber): rows placed in blade coordinates,
// cut through the verified boolean path and measured on the built solid: diameter, inclination and
// compound angle from the cylinder axis of each hole's faces, removed volume per hole against our own
// quadrature, the exit footprint against the area the blade wall lost, breakout width and coverage.
#define BOOST_TEST_MODULE film_holes
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>

#include "features/film/film_holes.hpp"
#include "features/film/film_rows.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/core/constants.hpp"
#include "test_film_fixtures.hpp"

using namespace cg;
using namespace cg::features;

namespace {

using cg::kPi;
constexpr double kDeg = 180 / kPi;

test::FilmVane& vane() {
  static test::FilmVane v(true);
  return v;
}


// Streamwise and spanwise unit directions in the surface at a hole (as defined in film_rows.hpp).
void surface_axes(const blade::BladeFrame& f, double chord, Eigen::Vector3d& stream, Eigen::Vector3d& span) {
  stream = chord >= 0 ? f.chord_tangent : Eigen::Vector3d(-f.chord_tangent);
  stream = (stream - stream.dot(f.normal) * f.normal).normalized();
  span = f.normal.cross(stream);
  if (span.dot(f.span_tangent) < 0) span = -span;
}

struct Built {
  FilmCoolingDefinition def;
  FilmHoleTools tools;
  FilmCutResult cut;
};

const Built& built() {
  static const Built b = [] {
    Built out;
    out.def.rows.push_back(test::film_row(0.35, 0.4, 4, 30, 0));     // suction side
    out.def.rows.push_back(test::film_row(-0.45, 0.4, 5, 35, 40));   // pressure side, compound angle
    FilmRowDefinition fan = test::film_row(-0.25, 0.3, 6, 30, 0);    // 7-7-7 (two holes: shaped holes cost the most)
    fan.shape = preset_777(0.3);
    fan.span_start = 0.4;
    fan.span_end = 0.6;
    out.def.rows.push_back(fan);
    ShowerheadDefinition sh;
    sh.rows = 3;
    sh.diameter = 0.35;
    sh.span_start = 0.4;
    sh.span_end = 0.75;
    sh.pitch_d = 7.5;
    out.def.showerhead = sh;
    const std::vector<HoleSpec> holes = place_film_holes(vane().model, out.def);
    out.tools = make_film_hole_tools(vane().target, holes, out.def.limits);
    out.cut = cut_film_holes(vane().hollow.part, vane().target, out.tools, film_boolean_options());
    return out;
  }();
  return b;
}

}  // namespace

// Every hole removed the volume of our quadrature (the step checks it; here the agreement is stated:
// 1e-5 relative, limited by OCCT's measurement of the cut pieces, while the quadrature itself is
// converged to 1e-8, see quadrature_converged), and its faces carry its name.
BOOST_AUTO_TEST_CASE(volumes_and_names) {
  const Built& b = built();
  const auto names = brep::count_face_names(b.cut.blade);
  BOOST_TEST(b.cut.report.holes.size() == b.tools.holes.size());
  BOOST_TEST(b.cut.report.holes.size() >= 15u);
  for (const HoleMeasure& m : b.cut.report.holes) {
    BOOST_TEST(m.volume_passed, m.name);
    BOOST_TEST(std::abs(m.measured_volume / m.expected_volume - 1) < 1e-5, m.name << " " << m.measured_volume << " vs " << m.expected_volume);
    BOOST_TEST(names.count(m.name) == 1u, m.name);
    BOOST_TEST(m.chamber == "chamber_1");
  }
  BOOST_TEST(names.at("blade_wall") >= 1);
  BOOST_TEST(names.at("chamber_1_wall") >= 1);
}

// Diameter, inclination and compound angle measured from the cylinder axis of each hole's faces on the
// cut blade (OCCT's gp_Cylinder), against the configured values and the surface normal at the exit.
BOOST_AUTO_TEST_CASE(angles_from_the_built_holes) {
  const Built& b = built();
  const blade::BladeCoordinates bc(vane().model);
  int measured = 0;
  for (std::size_t i = 0; i < b.tools.holes.size(); ++i) {
    const HoleSpec& h = b.tools.holes[i];
    const std::vector<gp_Cylinder> cyl = test::named_cylinders(b.cut.blade, h.name);
    BOOST_TEST_REQUIRE(!cyl.empty(), h.name);
    const blade::BladeFrame f = bc.frame(h.span, h.chord);
    Eigen::Vector3d stream, span;
    surface_axes(f, h.chord, stream, span);
    for (const gp_Cylinder& c : cyl) {
      BOOST_TEST(std::abs(2 * c.Radius() - h.shape.diameter) < 1e-9, h.name);
      const gp_Dir a = c.Axis().Direction();
      Eigen::Vector3d flow(a.X(), a.Y(), a.Z());
      if (flow.dot(f.normal) < 0) flow = -flow;  // the coolant leaves outwards
      const double inclination = std::asin(flow.dot(f.normal)) * kDeg;
      const Eigen::Vector3d p = flow - flow.dot(f.normal) * f.normal;
      const double compound = std::atan2(p.dot(span), p.dot(stream)) * kDeg;
      if (h.row.rfind("showerhead", 0) == 0) {
        // In the plane of the span direction and the normal, at the radial angle to the span direction.
        BOOST_TEST(std::abs(inclination - 30) < 1e-6, h.name << " radial angle " << inclination);
        BOOST_TEST(std::abs(std::abs(compound) - 90) < 1e-6, h.name << " " << compound);
      } else {
        const FilmRowDefinition& r = b.def.rows[std::stoi(h.row.substr(9)) - 1];
        BOOST_TEST(std::abs(inclination - r.inclination_deg) < 1e-6, h.name << " inclination " << inclination);
        BOOST_TEST(std::abs(compound - r.compound_deg) < 1e-6, h.name << " compound " << compound);
      }
      ++measured;
    }
  }
  BOOST_TEST(measured >= 15);
}

// The exit footprints add up to the area the outer wall lost (measured on the faces named blade_wall),
// and the 7-7-7 holes report the published area ratio 2.5 (within 2 %) at their 30 deg.
BOOST_AUTO_TEST_CASE(footprints_and_area_ratio) {
  const Built& b = built();
  const double lost = test::named_area(vane().hollow.part, "blade_wall") - test::named_area(b.cut.blade, "blade_wall");
  double footprints = 0;
  for (const HoleMeasure& m : b.cut.report.holes) {
    footprints += m.footprint_area;
    if (m.shape == "fan_shaped") {
      BOOST_TEST(std::abs(m.area_ratio - 2.5) < 0.02 * 2.5, m.name << " " << m.area_ratio);
      BOOST_TEST(std::abs(m.metering_length + m.diffuser_length - m.length) < 1e-9);
      BOOST_TEST(std::abs(m.diffuser_length - 3.5 * 0.3) < 1e-12);
    } else {
      BOOST_TEST(m.area_ratio == 1.0);
    }
    BOOST_TEST(std::abs(m.length_d * m.diameter - m.length) < 1e-12);
  }
  BOOST_TEST(std::abs(lost - footprints) < 1e-5 * footprints, "lost " << lost << " footprints " << footprints);
}

// Breakout width along the row: a cylinder with no compound angle on a straight vane (surface lines
// parallel to the span) breaks out exactly D wide along the span, so its row coverage is D / P.
BOOST_AUTO_TEST_CASE(breakout_width_and_coverage) {
  const Built& b = built();
  for (const HoleMeasure& m : b.cut.report.holes)
    if (m.row == "film_row_1") BOOST_TEST(std::abs(m.breakout_width - 0.4) < 1e-6, m.name << " " << m.breakout_width);
  bool seen = false;
  for (const RowMeasure& r : b.cut.report.rows) {
    if (r.name == "film_row_1") {
      seen = true;
      BOOST_TEST(std::abs(r.pitch - 1.6) < 1e-12);
      BOOST_TEST(std::abs(r.coverage - 0.25) < 1e-6);
    }
    if (r.name == "film_row_3") BOOST_TEST(r.coverage > 2 * (0.15 + 1.05 * std::tan(7 / kDeg)) / 1.8);  // wider than at the axis
  }
  BOOST_TEST(seen);
  // Per chamber: the metering area of every hole it feeds.
  BOOST_REQUIRE(b.cut.report.chambers.size() == 1u);
  double area = 0;
  for (const HoleMeasure& m : b.cut.report.holes) area += kPi * m.diameter * m.diameter / 4;
  BOOST_TEST(std::abs(b.cut.report.chambers[0].metering_area - area) < 1e-12 * area);
}

// The quadrature is converged: doubling every rule changes no expected volume by more than 1e-7 (1e-8
// away from the leading edge's curvature).
BOOST_AUTO_TEST_CASE(quadrature_converged) {
  const Built& b = built();
  HoleQuadrature fine;
  fine.radial = 12;
  fine.angular = 32;
  fine.piece = 10;
  const FilmHoleTools f = make_film_hole_tools(vane().target, b.tools.holes, b.def.limits, fine);
  for (std::size_t i = 0; i < f.geometry.size(); ++i) {
    BOOST_TEST(std::abs(f.geometry[i].expected_volume / b.tools.geometry[i].expected_volume - 1) < 1e-7,
               b.tools.holes[i].name << " " << f.geometry[i].expected_volume / b.tools.geometry[i].expected_volume - 1);
    BOOST_TEST(std::abs(f.geometry[i].footprint_area / b.tools.geometry[i].footprint_area - 1) < 1e-6,
               b.tools.holes[i].name << " " << f.geometry[i].footprint_area / b.tools.geometry[i].footprint_area - 1);
  }
}
