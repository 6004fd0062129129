// Impingement inserts (features/film/insert.hpp) in the core of a hollow vane (thick section, 1 mm wall), measured on the built solids:
// the gap to the chamber wall and the sheet thickness (along the wall normal through the built faces,
// and the least distance between the bodies), the jet holes' removed volume against our quadrature, the
// insert as its own valid body with named faces; inputs that do not fit.
#define BOOST_TEST_MODULE insert
#include <boost/test/unit_test.hpp>

#include <BRepCheck_Analyzer.hxx>

#include <chrono>
#include <cmath>

#include "features/film/insert.hpp"
#include "test_film_fixtures.hpp"

using namespace cg;
using namespace cg::features;

namespace {

test::FilmVane& vane() {
  static test::FilmVane v(true, 12, 12);  // a thick vane: LE radius 2.6 mm
  return v;
}

InsertDefinition insert_def() {
  InsertDefinition d;
  d.gap = 0.6;
  d.sheet_thickness = 0.3;
  d.jet_diameter = 0.4;
  d.jet_spacing_x_d = 16;
  d.jet_spacing_y_d = 10;
  d.staggered = true;
  d.hub_open = false;
  d.tip_open = false;
  return d;
}

}  // namespace

BOOST_AUTO_TEST_CASE(closed_insert_gap_sheet_and_jets) {
  const InsertChamber chamber = film_hollow_insert_chamber(vane().model, vane().hollow);
  const InsertDefinition def = insert_def();
  InsertBuild ins = build_insert(vane().model, chamber, def, 1, "inserts[0]");
  const auto t0 = std::chrono::steady_clock::now();
  measure_insert(vane().model, vane().hollow.part, ins, chamber, def);
  for (const auto& [stage, sec] : ins.seconds) BOOST_TEST_MESSAGE(stage << " " << sec << " s");
  BOOST_TEST_MESSAGE("measure " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s");
  const InsertMeasure& m = ins.measure;
  BOOST_TEST_MESSAGE("gap " << m.measured_gap << " sheet " << m.measured_sheet_min << ".." << m.measured_sheet_max << " jets "
                            << m.jet_holes << " volume " << m.volume << " expected " << m.expected_volume);
  BOOST_TEST(ins.body.name == "insert_1");
  BOOST_TEST(BRepCheck_Analyzer(ins.body.geometry.shape).IsValid());
  // The offsets are fitted within 1e-3 mm (inner_wall.hpp): gap and sheet within 2e-3 mm.
  BOOST_TEST(std::abs(m.measured_gap - def.gap) < 2e-3, "gap " << m.measured_gap);
  BOOST_TEST(std::abs(m.measured_sheet_min - def.sheet_thickness) < 2e-3, "sheet " << m.measured_sheet_min);
  BOOST_TEST(std::abs(m.measured_sheet_max - def.sheet_thickness) < 2e-3, "sheet " << m.measured_sheet_max);
  BOOST_TEST(m.jet_holes >= 6, m.jet_holes);
  BOOST_TEST(std::abs(m.volume - m.expected_volume) < 1e-5 * m.expected_volume, m.volume << " vs " << m.expected_volume);
  const auto names = brep::count_face_names(ins.body.geometry);
  BOOST_TEST(names.at("insert_1") >= 3);  // outer sheet, inner sheet, end caps
  BOOST_TEST(names.count("insert_1_jet_001") == 1u);
  char last[32];
  std::snprintf(last, sizeof last, "insert_1_jet_%03d", m.jet_holes);
  BOOST_TEST(names.count(last) == 1u);
  for (const auto& [name, n] : names) BOOST_TEST(brep::feature_kind(name) == "insert", name);
}

// An open-ended insert: a tube through the chamber (the inner solid runs out of both ends).
BOOST_AUTO_TEST_CASE(open_insert) {
  const InsertChamber chamber = film_hollow_insert_chamber(vane().model, vane().hollow);
  InsertDefinition def = insert_def();
  def.hub_open = def.tip_open = true;
  def.jet_spacing_x_d = 30;
  def.jet_spacing_y_d = 20;
  InsertBuild ins = build_insert(vane().model, chamber, def, 2, "inserts[1]");
  BOOST_TEST(BRepCheck_Analyzer(ins.body.geometry.shape).IsValid());
  // Shell volume: between the two offsets over the insert's length, less the jets: smaller than the
  // closed insert's by the two caps.
  BOOST_TEST(ins.measure.volume > 0);
  BOOST_TEST(brep::count_face_names(ins.body.geometry).count("insert_2") == 1u);
}

BOOST_AUTO_TEST_CASE(insert_that_does_not_fit) {
  const InsertChamber chamber = film_hollow_insert_chamber(vane().model, vane().hollow);
  InsertDefinition def = insert_def();
  def.gap = 1.5;  // 1 + 1.5 + 0.3 mm inside a 2.64 mm LE radius
  try {
    build_insert(vane().model, chamber, def, 1, "inserts[0]");
    BOOST_FAIL("an insert larger than its chamber was built");
  } catch (const FilmInputError& e) {
    BOOST_TEST(e.field() == "inserts[0].gap");
    BOOST_TEST(std::string(e.what()).find("does not fit in chamber_1") != std::string::npos, e.what());
  }
  def = insert_def();
  def.jet_spacing_x_d = 1.5;
  try {
    build_insert(vane().model, chamber, def, 1, "inserts[0]");
    BOOST_FAIL("jets closer than 2 D were accepted");
  } catch (const FilmInputError& e) {
    BOOST_TEST(e.field() == "inserts[0].jets.spacing_x_d");
  }
}
