// Film holes that cannot be built get a clear error naming the config field below "cooling" and the
// limit: a hole larger than the wall allows, a row outside the span range or beyond the end walls,
// overlapping rows, a pitch below the diameter, a hole that reaches no chamber or the wrong one, a hole
// too close to a rib, a tool that would reach an insert. No solid is built (cheap): the checks run on the
// blade and its inner wall.
#define BOOST_TEST_MODULE film_inputs
#include <boost/test/unit_test.hpp>

#include <string>

#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>

#include "features/film/film_cavity.hpp"
#include "features/film/film_holes.hpp"
#include "features/film/film_rows.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "test_film_fixtures.hpp"

using namespace cg;
using namespace cg::features;

namespace {

test::FilmVane& vane() {
  static test::FilmVane v(false);
  return v;
}


// Runs placement and analysis; returns the error's field and message ("" when it built).
std::pair<std::string, std::string> attempt(const FilmCoolingDefinition& def, const HoleTarget& target) {
  try {
    make_film_hole_tools(target, place_film_holes(vane().model, def), def.limits);
  } catch (const FilmInputError& e) {
    return {e.field(), e.what()};
  }
  return {"", ""};
}

std::pair<std::string, std::string> attempt(const FilmCoolingDefinition& def) { return attempt(def, vane().target); }

FilmCoolingDefinition rows(std::initializer_list<FilmRowDefinition> r) {
  FilmCoolingDefinition d;
  d.rows = r;
  return d;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_CASE(a_valid_row_builds) {
  const auto [field, what] = attempt(rows({test::film_row(0.35)}));
  BOOST_TEST(field == "", what);
}

// A 7-7-7 hole of D = 0.5 mm needs 3.5 D = 1.75 mm of diffuser along its axis; through a 1 mm wall at
// 30 deg the hole is 2 mm long, and the metering part's back side reaches the cavity first.
BOOST_AUTO_TEST_CASE(hole_larger_than_the_wall) {
  FilmRowDefinition r = test::film_row(0.35, 0.5, 6);
  r.shape = preset_777(0.5);
  const auto [field, what] = attempt(rows({r}));
  BOOST_TEST(field == "film_rows[0].diameter");
  BOOST_TEST(has(what, "larger than the wall allows"), what);
  BOOST_TEST(has(what, "film_row_1_hole_001"), what);
  // A metering length that leaves no diffuser.
  FilmRowDefinition m = test::film_row(0.35, 0.3, 6);
  m.shape = preset_777(0.3);
  m.shape.fan.diffuser_length_d = 0;
  m.shape.fan.metering_length_d = 8;
  const auto [f2, w2] = attempt(rows({m}));
  BOOST_TEST(f2 == "film_rows[0].fan.metering_length_d", w2);
}

BOOST_AUTO_TEST_CASE(row_outside_the_span_range) {
  FilmRowDefinition r = test::film_row(0.35);
  r.span_end = 1.2;
  BOOST_TEST(attempt(rows({r})).first == "film_rows[0].span_end");
  r = test::film_row(0.35);
  r.span_start = -0.1;
  BOOST_TEST(attempt(rows({r})).first == "film_rows[0].span_start");
  // Beyond the tip cap (1 mm of a 12 mm span): inside the blade's span, outside the cavity's.
  r = test::film_row(0.35);
  r.span_end = 0.97;
  const auto [field, what] = attempt(rows({r}));
  BOOST_TEST(field == "film_rows[0].span_end", what);
  BOOST_TEST(has(what, "tip_cap"), what);
}

BOOST_AUTO_TEST_CASE(overlapping_rows) {
  const auto [field, what] = attempt(rows({test::film_row(0.35), test::film_row(0.365)}));
  BOOST_TEST(field == "film_rows[1].chord", what);
  BOOST_TEST(has(what, "overlapping rows film_row_1 and film_row_2"), what);
  BOOST_TEST(has(what, "min_ligament"), what);
}

BOOST_AUTO_TEST_CASE(pitch_below_the_diameter) {
  BOOST_TEST(attempt(rows({test::film_row(0.35, 0.4, 0.9)})).first == "film_rows[0].pitch_d");
  FilmRowDefinition c = test::film_row(0.35);
  c.pitch_d = 0;
  c.count = 40;  // 6 mm of row
  const auto [field, what] = attempt(rows({c}));
  BOOST_TEST(field == "film_rows[0].count", what);
  BOOST_TEST(has(what, "below the diameter"), what);
  // Above the diameter but below the ligament: 1.5 D leaves 0.2 mm < 0.3 mm.
  const auto [f2, w2] = attempt(rows({test::film_row(0.35, 0.4, 1.5)}));
  BOOST_TEST(f2 == "film_rows[0].pitch_d", w2);
  BOOST_TEST(has(w2, "pitch too small"), w2);
  // Neither count nor pitch.
  FilmRowDefinition n = test::film_row(0.35);
  n.pitch_d = 0;
  BOOST_TEST(attempt(rows({n})).first == "film_rows[0]");
}

// A thin symmetric blade (TE radius 0.5 mm) whose inner wall's crease lies well before the TE: a hole
// normal to the wall near the TE passes through the blade and leaves it again without meeting the cavity.
// And a row where the chamber's chordwise extent ends.
BOOST_AUTO_TEST_CASE(hole_that_reaches_no_chamber) {
  blade::BladeDefinition bd;
  bd.flow_path = blade::StraightFlowPath{12};
  blade::BladeSectionDefinition sec;
  sec.shape = blade::test::symmetric_section(40);
  bd.sections = {sec};
  const blade::BladeModel thin = blade::build_blade(bd);
  const FilmHollowBlade hollow = make_film_hollow_blade(thin, 1.0, 1.0, false);
  const HoleTarget t = film_hollow_target(thin, hollow);
  FilmCoolingDefinition d;
  FilmRowDefinition r = test::film_row(0.99, 0.2, 4);
  r.inclination_deg = 90;
  d.rows = {r};
  std::string field, what;
  try {
    make_film_hole_tools(t, place_film_holes(thin, d), d.limits);
  } catch (const FilmInputError& e) {
    field = e.field();
    what = e.what();
  }
  BOOST_TEST(hollow.inner.min_suction_chord < 0.98);
  BOOST_TEST(field == "film_rows[0].chord", what);
  BOOST_TEST(has(what, "reaches no chamber"), what);
  BOOST_TEST(has(what, "leaves the blade again"), what);
  HoleTarget front = vane().target;
  front.chambers[0].suction_to = 0.7;
  const auto [f1, w1] = attempt(rows({test::film_row(0.8)}), front);
  BOOST_TEST(f1 == "film_rows[0].chord", w1);
  BOOST_TEST(has(w1, "belongs to no chamber"), w1);
  // Two chambers with a gap between them (a rib's place): a row over the gap reaches neither.
  HoleTarget two = vane().target;
  two.chambers = {TargetChamber{1, "chamber_1", 0, 0.3, -0.3, 0}, TargetChamber{2, "chamber_2", 0.4, 1, -1, -0.4}};
  const auto [f2, w2] = attempt(rows({test::film_row(0.35)}), two);
  BOOST_TEST(f2 == "film_rows[0].chord", w2);
  BOOST_TEST(has(w2, "reaches no chamber"), w2);
  // A row configured for chamber 2 whose holes enter chamber 1.
  FilmRowDefinition in1 = test::film_row(0.2);
  in1.chamber = 2;
  const auto [f3, w3] = attempt(rows({in1}), two);
  BOOST_TEST(f3 == "film_rows[0].chamber", w3);
  BOOST_TEST(has(w3, "feeds from chamber_1"), w3);
}

// A rib (here a slab 1 mm thick across the core at chord 0.39) is an obstacle: a hole must keep the
// ligament from it where it enters the cavity. A hole leaning downstream enters the cavity upstream of
// its exit: the row at chord 0.42 enters at about 0.38.
BOOST_AUTO_TEST_CASE(hole_too_close_to_a_rib) {
  const blade::BladeCoordinates bc(vane().model);
  const Eigen::Vector3d a = bc.frame(0.5, 0.39).point, b = bc.frame(0.5, -0.39).point;
  const Eigen::Vector3d n = (a - b).cross(Eigen::Vector3d::UnitZ()).normalized();
  HoleTarget t = vane().target;
  t.obstacles.push_back({"rib_1", [a, n](const Eigen::Vector3d& p) { return std::abs((p - a).dot(n)) - 0.5; }, true, ""});
  const auto [field, what] = attempt(rows({test::film_row(0.42)}), t);
  BOOST_TEST(field == "film_rows[0].chord", what);
  BOOST_TEST(has(what, "rib_1"), what);
  // It enters the cavity inside the slab: an overlap, said as such, never a negative closeness.
  BOOST_TEST(has(what, "overlaps rib_1 by "), what);
  BOOST_TEST(!has(what, " -"), what);
  const auto [f2, w2] = attempt(rows({test::film_row(0.30)}), t);
  BOOST_TEST(f2 == "", w2);
}

// Turbulators, pin fins and slots of the passages are obstacles too (wall_feature_obstacles, exact
// distance to the tool solid near it), checked as the build does on the planned holes
// (check_film_holes_against): a 4 mm block on the suction wall under the row at chord 0.35 stops it
// naming the row's position field and the feature; the same block under the pressure side does not
// touch the row.
BOOST_AUTO_TEST_CASE(hole_onto_a_turbulator) {
  const blade::BladeCoordinates bc(vane().model);
  const auto with_block_at = [&](double chord) {
    const Eigen::Vector3d c = bc.frame(0.5, chord).point;
    WallFeatureBuild walls;
    FeatureTool block;
    block.feature = "turbulator_1_001";
    block.shape.shape = BRepPrimAPI_MakeBox(gp_Pnt(c.x() - 2, c.y() - 2, c.z() - 2), 4, 4, 4).Shape();
    walls.turbulators.tools.push_back(block);
    const FilmCoolingDefinition def = rows({test::film_row(0.35)});
    FilmHoleTools planned = analyse_film_holes(vane().target, place_film_holes(vane().model, def), def.limits);
    try {
      check_film_holes_against(planned, wall_feature_obstacles(walls), def.limits);
    } catch (const FilmInputError& e) {
      return std::pair<std::string, std::string>{e.field(), e.what()};
    }
    return std::pair<std::string, std::string>{"", ""};
  };
  const auto [field, what] = with_block_at(0.33);
  BOOST_TEST(field == "film_rows[0].chord", what);
  BOOST_TEST(has(what, "turbulator_1_001"), what);
  const auto [f2, w2] = with_block_at(-0.35);
  BOOST_TEST(f2 == "", w2);
}

// An insert behind the gap limits how far a tool may reach into the chamber.
BOOST_AUTO_TEST_CASE(tool_would_reach_an_insert) {
  HoleTarget t = vane().target;
  t.chambers[0].reach = 0.05;  // less than the tool's clearance past the wall
  const auto [field, what] = attempt(rows({test::film_row(0.35)}), t);
  BOOST_TEST(field == "film_rows[0].chord", what);
  BOOST_TEST(has(what, "insert"), what);
}

// A tool whose end normal to the axis would reach further than the chamber allows ends along the cavity
// wall instead (each line `clearance` past its own inlet), when that keeps it within the allowance.
BOOST_AUTO_TEST_CASE(tool_ends_along_the_wall_before_an_insert) {
  const FilmCoolingDefinition def = rows({test::film_row(0.35)});
  const std::vector<HoleSpec> holes = place_film_holes(vane().model, def);
  HoleTarget t = vane().target;
  const FilmHoleTools free = make_film_hole_tools(t, holes, def.limits);
  BOOST_TEST(free.geometry.front().extent.end_normal.norm() == 0.0);  // nothing behind: normal to the axis
  // Ended normal to the axis the tools reach 1.2-1.5 mm past the cavity wall (by bisection on the
  // allowance), ended along the wall 0.176 mm (0.16 mm is refused): 0.5 mm lies between.
  t.chambers[0].reach = 0.5;
  const FilmHoleTools limited = make_film_hole_tools(t, holes, def.limits);
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const HoleToolExtent& e = limited.geometry[k].extent;
    BOOST_TEST(std::abs(e.end_normal.norm() - 1.0) < 1e-12);
    BOOST_TEST(e.s_end < free.geometry[k].extent.s_end);
    BOOST_TEST(BRepCheck_Analyzer(limited.tools[k].shape.shape).IsValid());
  }
}

BOOST_AUTO_TEST_CASE(showerhead_inputs) {
  FilmCoolingDefinition d;
  ShowerheadDefinition sh;
  sh.diameter = 0.35;
  sh.rows = 3;
  sh.span_start = 0.4;
  sh.span_end = 0.75;
  sh.row_spacing_d = 0.8;
  d.showerhead = sh;
  BOOST_TEST(attempt(d).first == "showerhead.row_spacing_d");
  d.showerhead->row_spacing_d = 4;
  d.showerhead->pitch_d = 0.5;
  BOOST_TEST(attempt(d).first == "showerhead.pitch_d");
  d.showerhead->pitch_d = 7.5;
  BOOST_TEST(attempt(d).first == "");
  // A row position given as an arc length beyond the TE.
  FilmRowDefinition r = test::film_row(0);
  r.position = {RowPosition::Kind::ArcLength, 500};
  const auto [field, what] = attempt(rows({r}));
  BOOST_TEST(field == "film_rows[0].arc_length", what);
  BOOST_TEST(has(what, "beyond the TE"), what);
}
