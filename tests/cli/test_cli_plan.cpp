// `coolinggen validate` plans the cooling features (features/plan/cooling_plan.hpp) and refuses what
// `coolinggen build` refuses in its first stage (the plan, before the solid: its progress on a terminal
// shows no other stage), naming the same field; run as processes on small variants of the examples whose
// refusal used to come only from the build, after its cooling stage or from the film stage's holes
// (their times are printed with --log_level=message):
//  - the C3X film vane with a film row written without "chamber" over the chamber that holds the insert,
//    the insert's gap narrowed to 0.3 mm: its holes' tools would reach past the gap, even ending along
//    the cavity wall (build refused it in its film stage);
//  - the built-in example with a turnaround gap of 80 mm, longer than the blade's span (~53 mm): the
//    build refused it when its rib tubes were built, after the inner wall and the core solid;
//  - the C3X film vane with a film row (no "chamber") whose holes enter the cavity within the ligament
//    of the rib (mid-surface +- thickness / 2 and the fillets' width): build refused it after its cooling
//    stage;
//  - a rotor variant whose turbulators find no room between the rib fillets (placed by the plan);
//  - the C3X vane with a 3.5 mm wall and its rib at 0.56 of the chord: the 3 mm inlet of the aft chamber
//    leaves the inner wall (build refused it after the core's cells, classifying the rim against them).
// The build refuses each with exit 2, one line starting with the same field, and writes nothing.
// And the built-in example with cutbacks longer than its TE region: 1 mm is planned on a wall thickened
// toward the TE (validate prints the change), 3 mm is refused by both (no such wall fits the sections).
#define BOOST_TEST_MODULE cli_plan
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "brep/temp_files.hpp"
#include "cli/run_cli.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;

namespace {

const fs::path kExamples = fs::path(COOLINGGEN_SOURCE_DIR) / "data" / "examples";

// An example config with its point files made absolute, no outputs but report.json, edited.
json variant(const fs::path& file, const std::function<void(json&)>& edit) {
  json d = json::parse(test::read_text(file));
  for (json& s : d["sections"])
    if (s.contains("points") && s["points"].contains("file")) {
      const fs::path p = s["points"]["file"].get<std::string>();
      if (p.is_relative()) s["points"]["file"] = (file.parent_path() / p).lexically_normal().string();
    }
  d["output"]["formats"] = json::array();
  edit(d);
  return d;
}

// validate, then build: both exit 2 with one line starting with `field`, nothing written.
void expect_planned_refusal(const json& doc, const std::string& field, const std::string& detail) {
  test::TempDir dir("cli_plan");
  const fs::path cfg = dir.path / "design.json";
  std::ofstream(cfg) << doc.dump(1);
  const test::Run v = test::run_cli("validate " + test::q(cfg), dir.path);
  BOOST_TEST_MESSAGE(field << ": validate " << v.seconds << " s: " << v.err);
  BOOST_TEST(v.exit_code == 2, field << ": " << v.out << v.err);
  BOOST_TEST(test::count_lines(v.err) == 1, v.err);
  BOOST_TEST(v.err.find("coolinggen: error: " + field + ": ") == 0u, v.err);
  BOOST_TEST(v.err.find(detail) != std::string::npos, v.err);
  // The build on a terminal shows its stages: refused in its first one (the plan), before the solid.
  const test::Run b = test::run_cli("build " + test::q(cfg) + " -o " + test::q(dir.path / "out"), dir.path, true);
  BOOST_TEST_MESSAGE(field << ": build " << b.seconds << " s: " << b.err);
  BOOST_TEST(b.exit_code == 2, field << ": " << b.err);
  BOOST_TEST(test::count_lines(b.err) == 1, b.err);
  BOOST_TEST(b.err.find("coolinggen: error: " + field + ": ") == 0u, b.err);
  BOOST_TEST(b.out.find("blade model") != std::string::npos, b.out);
  BOOST_TEST(b.out.find("solid (") == std::string::npos, "build got past its plan: " << b.out);
  BOOST_TEST(!fs::exists(dir.path / "out"));
}

}  // namespace

BOOST_AUTO_TEST_CASE(film_row_without_chamber_reaching_past_the_insert) {
  const json d = variant(kExamples / "c3x_film_vane.json", [](json& d) {
    json& c = d["cooling"];
    for (json& r : c["film_rows"]) {
      r["span_start"] = 0.5;
      r["span_end"] = 0.55;
      r.erase("chamber");
    }
    c["film_rows"][0]["chord"] = 0.2;  // over chamber_1 (the rib is at 0.3), which holds the insert
    c["showerhead"]["span_start"] = 0.5;
    c["showerhead"]["span_end"] = 0.55;
    c["inserts"][0]["gap"] = 0.3;               // the example's 1.5 mm gap lets the wall-following tools in
    c["core"]["ribs"][0]["fillet_radius"] = 0.2;  // (a gap narrower than the rib's fillets is refused)
  });
  // The insert's gap 0.3 mm leaves the tools 0.3 - 0.3 / 4 = 0.225 mm past the cavity wall. Ended by a
  // plane normal to the axis 0.15 mm past the last line's inlet they would reach 2.65 mm; ended along
  // the cavity wall (as the tools are where the normal end reaches too far) still 0.319 mm.
  expect_planned_refusal(d, "cooling.film_rows[0].chord", "an insert lies behind the gap");
}

BOOST_AUTO_TEST_CASE(turnaround_gap_longer_than_the_span) {
  const json d = variant(kExamples / "hpt_rotor.json", [](json& d) { d["cooling"]["core"]["ribs"][1]["turnaround"]["gap"] = 80; });
  expect_planned_refusal(d, "cooling.core.ribs[1].turnaround", "the turnaround gap 80 mm leaves no rib");
}

BOOST_AUTO_TEST_CASE(film_row_entering_at_a_rib) {
  const json d = variant(kExamples / "c3x_film_vane.json", [](json& d) {
    json& c = d["cooling"];
    c.erase("inserts");
    c.erase("showerhead");
    c["film_rows"].erase(1);
    json& r = c["film_rows"][0];
    r["span_start"] = 0.5;
    r["span_end"] = 0.55;
    r.erase("chamber");
    r["chord"] = 0.35;  // its holes enter the cavity within the ligament of rib_1 (at 0.3, 3 mm thick, 1 mm fillets)
  });
  expect_planned_refusal(d, "cooling.film_rows[0].chord", "rib_1");
}

// A light rotor variant of bench/random_designs.py (seed 11, variant 32, data/repro/
// turbulator_between_fillets.json) with its turbulators' end_gap raised from 0.2 to 0.8 mm: its 45 deg
// turbulators find no room between the rib fillets at one span (at 0.2 mm they fit since the ends are
// measured against the rib's section rather than its acute-side reach on both sides, and it builds);
// build refused such a design only after the core's cells (0.5 of a median build), validate said valid.
BOOST_AUTO_TEST_CASE(turbulator_without_room_between_the_fillets) {
  const json d = variant(fs::path(COOLINGGEN_SOURCE_DIR) / "data" / "repro" / "turbulator_between_fillets.json",
                         [](json& d) { d["cooling"]["core"]["turbulators"][0]["end_gap"] = 0.8; });
  expect_planned_refusal(d, "cooling.core.turbulators[0].end_gap", "no room between the rib fillets");
}

// bench/random_designs.py (full variants, seed 11, variant 21) as the smallest edit of the C3X vane: the
// inlet is placed on the chamber's mid-line between its rib and the crease, where the 3.5 mm wall leaves
// less than 3 mm across; its rim leaves the inner wall, which the plan sees without the chamber solid.
BOOST_AUTO_TEST_CASE(inlet_rim_outside_the_inner_wall) {
  const json d = variant(kExamples / "c3x_film_vane.json", [](json& d) {
    json& c = d["cooling"];
    for (const char* k : {"film_rows", "showerhead", "inserts"}) c.erase(k);
    c["core"]["wall_thickness"] = 3.5;
    c["core"]["ribs"][0]["suction_chord"] = 0.56;
    c["core"]["ribs"][0]["pressure_chord"] = -0.56;
  });
  expect_planned_refusal(d, "cooling.core.inlets[1].diameter", "inlet_2 (diameter 3 mm) does not fit into chamber 2");
}

// The built-in example's 1 mm wall ends the chamber 0.91 mm from the TE at the hub: a 1 mm cutback gets a
// TE land (features/wall/cutback_wall.hpp), which validate reports; a 3 mm one is refused with the reason.
BOOST_AUTO_TEST_CASE(cutback_longer_than_the_te_region) {
  test::TempDir dir("cli_plan");
  const fs::path cfg = dir.path / "design.json";
  std::ofstream(cfg) << variant(kExamples / "hpt_rotor.json", [](json& d) {
    d["cooling"]["core"]["trailing_edge"]["cutback_length"] = 1.0;
  }).dump(1);
  const test::Run v = test::run_cli("validate " + test::q(cfg), dir.path);
  BOOST_TEST_MESSAGE("validate " << v.seconds << " s: " << v.out);
  BOOST_TEST(v.exit_code == 0, v.out << v.err);
  BOOST_TEST(v.out.find("\nplanned: cooling.core.wall_thickness: the cutback's lip (cutback_length 1 mm) would lie over the last "
                        "chamber of a 1 mm wall: the wall is thickened toward the trailing edge") != std::string::npos, v.out);
  const json refused = variant(kExamples / "hpt_rotor.json", [](json& d) { d["cooling"]["core"]["trailing_edge"]["cutback_length"] = 3.0; });
  expect_planned_refusal(refused, "cooling.core.trailing_edge.cutback_length", "; no wall thickened toward the TE");
}
