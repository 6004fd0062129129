// Hostile cooling input: every case is refused before anything is built, with one line naming the
// config field (the path below "cooling") — never a crash, a hang, an internal failure or a model.
//
// Cases (issue 21 item 3): numbers that are zero, negative, huge or of the wrong type in every kind of
// cooling field; NaN and infinity (JSON has no literal for them: the strict reader refuses the text
// with line and column); ragged and non-monotone tables; counts that would make millions of tools
// (refused by a limit, not attempted); references to chambers and ribs that do not exist; empty or
// wrongly typed objects and arrays; and the late refusals of the issue (a cutback longer than the
// trailing edge allows, a film row over another chamber than it names, a fillet radius no rib can
// take). The library part parses each case and runs pipeline::validate's cooling checks on the
// built-in example's blade model (built once); the CLI part runs `coolinggen build` on a selection
// into an existing output directory and checks exit 2, a single stderr line naming the field, and the
// directory as it was.
#define BOOST_TEST_MODULE hostile_cooling
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/cooling.hpp"

using namespace cg;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

struct Case {
  std::string field;                  // the path the error must start with
  std::function<void(json&)> edit;    // applied to the built-in example's "cooling" object
};

json& core(json& c) { return c["core"]; }

std::vector<Case> cases() {
  std::vector<Case> v;
  auto add = [&](std::string field, std::function<void(json&)> edit) { v.push_back({std::move(field), std::move(edit)}); };
  // Core walls.
  add("cooling.core.wall_thickness", [](json& c) { core(c)["wall_thickness"] = 0; });
  add("cooling.core.wall_thickness", [](json& c) { core(c)["wall_thickness"] = -1; });
  add("cooling.core.wall_thickness", [](json& c) { core(c)["wall_thickness"] = 1e300; });
  add("cooling.core.wall_thickness", [](json& c) { core(c)["wall_thickness"] = "1"; });
  add("cooling.core.wall_thickness", [](json& c) { core(c)["wall_thickness"] = 6; });  // no room for a chamber
  add("cooling.core.tip_cap.thickness", [](json& c) { core(c)["tip_cap"]["thickness"] = 0; });
  add("cooling.core.hub_floor.thickness", [](json& c) { core(c)["hub_floor"]["thickness"] = -2; });
  add("cooling.core.hub_floor.thickness", [](json& c) { core(c)["hub_floor"]["thickness"] = 60; });  // beyond the span
  add("cooling.core.tip_cap", [](json& c) { core(c)["tip_cap"] = json::array(); });
  // Wall thickness tables: ragged, non-monotone, empty.
  add("cooling.core.wall_thickness.values[1]", [](json& c) {
    core(c)["wall_thickness"] = {{"spans", {0, 1}}, {"chords", {-1, 0, 1}}, {"values", {{1, 1, 1}, {1, 1}}}};
  });
  add("cooling.core.wall_thickness.spans", [](json& c) {
    core(c)["wall_thickness"] = {{"spans", {0.5, 0.2}}, {"chords", {-1, 1}}, {"values", {{1, 1}, {1, 1}}}};
  });
  add("cooling.core.wall_thickness.chords", [](json& c) {
    core(c)["wall_thickness"] = {{"spans", {0, 1}}, {"chords", {1, -1}}, {"values", {{1, 1}, {1, 1}}}};
  });
  add("cooling.core.wall_thickness.values[0][1]", [](json& c) {
    core(c)["wall_thickness"] = {{"spans", {0, 1}}, {"chords", {-1, 1}}, {"values", {{1, 0}, {1, 1}}}};
  });
  add("cooling.core.wall_thickness.spans", [](json& c) {
    core(c)["wall_thickness"] = {{"spans", json::array()}, {"chords", {-1, 1}}, {"values", json::array()}};
  });
  // Ribs.
  add("cooling.core.ribs", [](json& c) { core(c)["ribs"] = json::object(); });
  add("cooling.core.ribs[0]", [](json& c) { core(c)["ribs"][0] = "rib"; });
  add("cooling.core.ribs[0]", [](json& c) { core(c)["ribs"][0] = json::object(); });
  add("cooling.core.ribs[0].colour", [](json& c) { core(c)["ribs"][0]["colour"] = 1; });
  add("cooling.core.ribs[0].thickness", [](json& c) { core(c)["ribs"][0]["thickness"] = 0; });
  add("cooling.core.ribs[0].thickness", [](json& c) { core(c)["ribs"][0]["thickness"] = 1e9; });
  add("cooling.core.ribs[0].suction_chord", [](json& c) { core(c)["ribs"][0]["suction_chord"] = 1.5; });
  add("cooling.core.ribs[0].suction_chord", [](json& c) { core(c)["ribs"][0]["suction_chord"] = -0.3; });
  add("cooling.core.ribs[0].pressure_chord", [](json& c) { core(c)["ribs"][0]["pressure_chord"] = 0.3; });
  add("cooling.core.ribs[1]", [](json& c) { core(c)["ribs"][1]["suction_chord"] = 0.1; });  // before rib 0
  add("cooling.core.ribs[0].fillet_radius", [](json& c) { core(c)["ribs"][0]["fillet_radius"] = -0.5; });
  add("cooling.core.ribs[0].fillet_radius", [](json& c) { core(c)["ribs"][0]["fillet_radius"] = 8; });
  add("cooling.core.ribs[1].turnaround.end", [](json& c) { core(c)["ribs"][1]["turnaround"]["end"] = "middle"; });
  add("cooling.core.ribs[1].turnaround.gap", [](json& c) { core(c)["ribs"][1]["turnaround"]["gap"] = 0; });
  add("cooling.core.ribs[1].turnaround.gap", [](json& c) { core(c)["ribs"][1]["turnaround"]["gap"] = 1000; });
  add("cooling.core.ribs[1].turnaround.tip_radius", [](json& c) { core(c)["ribs"][1]["turnaround"]["tip_radius"] = 5; });
  // Inlets.
  add("cooling.core.inlets", [](json& c) { core(c)["inlets"] = json::object(); });
  add("cooling.core.inlets[0].chamber", [](json& c) { core(c)["inlets"][0]["chamber"] = 9; });
  add("cooling.core.inlets[0].chamber", [](json& c) { core(c)["inlets"][0]["chamber"] = 0; });
  add("cooling.core.inlets[0].diameter", [](json& c) { core(c)["inlets"][0]["diameter"] = 0; });
  add("cooling.core.inlets[0].diameter", [](json& c) { core(c)["inlets"][0]["diameter"] = 50; });  // wider than its chamber
  add("cooling.core.inlets[0].end", [](json& c) { core(c)["inlets"][0]["end"] = "side"; });
  // Turbulators.
  add("cooling.core.turbulators[0].chamber", [](json& c) { core(c)["turbulators"][0]["chamber"] = 7; });
  add("cooling.core.turbulators[0].chamber", [](json& c) { core(c)["turbulators"][0]["chamber"] = 1; });
  add("cooling.core.turbulators[1].chamber", [](json& c) { core(c)["turbulators"][1]["chamber"] = 2; });  // twice
  add("cooling.core.turbulators[0].pitch", [](json& c) { core(c)["turbulators"][0]["pitch"] = 0; });
  add("cooling.core.turbulators[0].pitch", [](json& c) { core(c)["turbulators"][0]["pitch"] = 1e-3; });  // 50 000 ribs
  add("cooling.core.turbulators[0].height", [](json& c) { core(c)["turbulators"][0]["height"] = -0.4; });
  add("cooling.core.turbulators[0].width", [](json& c) { core(c)["turbulators"][0]["width"] = 0; });
  add("cooling.core.turbulators[0].angle_deg", [](json& c) { core(c)["turbulators"][0]["angle_deg"] = 200; });
  add("cooling.core.turbulators[0].walls", [](json& c) { core(c)["turbulators"][0]["walls"] = "top"; });
  // Trailing edge: slots and pins.
  add("cooling.core.trailing_edge.type", [](json& c) { core(c)["trailing_edge"]["type"] = "x"; });
  add("cooling.core.trailing_edge.pitch", [](json& c) { core(c)["trailing_edge"]["pitch"] = 0; });
  add("cooling.core.trailing_edge.pitch", [](json& c) { core(c)["trailing_edge"]["pitch"] = 1e-4; });  // millions of slots
  add("cooling.core.trailing_edge.slot_height", [](json& c) { core(c)["trailing_edge"]["slot_height"] = 0; });
  add("cooling.core.trailing_edge.cutback_length", [](json& c) { core(c)["trailing_edge"]["cutback_length"] = 100; });
  add("cooling.core.trailing_edge.pin_fins.rows", [](json& c) { core(c)["trailing_edge"]["pin_fins"]["rows"] = 1000; });
  add("cooling.core.trailing_edge.pin_fins.rows", [](json& c) { core(c)["trailing_edge"]["pin_fins"]["rows"] = -1; });
  add("cooling.core.trailing_edge.pin_fins.spanwise_pitch",
      [](json& c) { core(c)["trailing_edge"]["pin_fins"]["spanwise_pitch"] = 1e-3; });
  add("cooling.core.trailing_edge.pin_fins.diameter", [](json& c) { core(c)["trailing_edge"]["pin_fins"]["diameter"] = 0; });
  add("cooling.core.trailing_edge.pin_fins.streamwise_pitch",
      [](json& c) { core(c)["trailing_edge"]["pin_fins"]["streamwise_pitch"] = 0; });
  // Film rows.
  add("cooling.film_rows", [](json& c) { c["film_rows"] = json::object(); });
  add("cooling.film_rows[1]", [](json& c) { c["film_rows"][1] = json::array(); });
  add("cooling.film_rows[1].diameter", [](json& c) { c["film_rows"][1]["diameter"] = -0.4; });
  add("cooling.film_rows[1]", [](json& c) {  // 0.01 mm holes at 1.01 D: ~4 000 holes in one row
    c["film_rows"][1]["diameter"] = 0.01;
    c["film_rows"][1]["pitch_d"] = 1.01;
  });
  add("cooling.film_rows[1].chord", [](json& c) { c["film_rows"][1]["chord"] = 2; });
  add("cooling.film_rows[1].chamber", [](json& c) { c["film_rows"][1]["chamber"] = 9; });
  add("cooling.film_rows[1].chamber", [](json& c) { c["film_rows"][1]["chamber"] = 2; });  // sits over chamber 4
  add("cooling.film_rows[1].span_end", [](json& c) {
    c["film_rows"][1]["span_start"] = 0.9;
    c["film_rows"][1]["span_end"] = 0.1;
  });
  add("cooling.film_rows[1].span_end", [](json& c) { c["film_rows"][1]["span_end"] = 1.5; });
  add("cooling.film_rows[1].inclination_deg", [](json& c) { c["film_rows"][1]["inclination_deg"] = 0; });
  add("cooling.film_rows[1].inclination_deg", [](json& c) { c["film_rows"][1]["inclination_deg"] = 95; });
  add("cooling.film_rows[1].pitch_d", [](json& c) { c["film_rows"][1]["pitch_d"] = 0.5; });
  add("cooling.film_rows[1].pitch_d", [](json& c) { c["film_rows"][1]["pitch_d"] = 1e6; });
  add("cooling.film_rows[0].shape", [](json& c) { c["film_rows"][0]["shape"] = "round"; });
  // Showerhead.
  add("cooling.showerhead.rows", [](json& c) { c["showerhead"]["rows"] = 0; });
  add("cooling.showerhead.rows", [](json& c) { c["showerhead"]["rows"] = 1000000; });
  add("cooling.showerhead.diameter", [](json& c) { c["showerhead"]["diameter"] = 0; });
  add("cooling.showerhead.pitch_d", [](json& c) { c["showerhead"]["pitch_d"] = 0.9; });
  add("cooling.showerhead.chamber", [](json& c) { c["showerhead"]["chamber"] = 99; });
  add("cooling.showerhead.toward", [](json& c) { c["showerhead"]["toward"] = "up"; });
  add("cooling.showerhead.radial_angle_deg", [](json& c) { c["showerhead"]["radial_angle_deg"] = 100; });
  add("cooling.showerhead.span_start", [](json& c) { c["showerhead"]["span_start"] = -0.1; });
  // Whole objects, inserts, limits.
  add("cooling", [](json& c) { c = json::array(); });
  add("cooling", [](json& c) { c = json::object(); });
  add("cooling.core", [](json& c) { c["core"] = 5; });
  add("cooling.film_limits.min_ligament", [](json& c) { c["film_limits"] = {{"min_ligament", -1}}; });
  add("cooling.inserts[0].chamber", [](json& c) {
    c["inserts"] = json::parse(R"([{"chamber": 7, "gap": 1.0, "sheet_thickness": 0.5, "hub_end": "open", "tip_end": "closed",
                                   "jets": {"diameter": 0.5, "spacing_x_d": 10, "spacing_y_d": 10, "pattern": "staggered"}}])");
  });
  return v;
}

json example() { return json::parse(config::builtin_example_json()); }

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The field error of `doc` from parsing and the cooling checks of pipeline::validate on `model`
// (the built-in example's: the cases change only the cooling); "" when it is accepted.
std::string refusal(const json& doc, const blade::BladeModel& model) {
  try {
    const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "hostile");
    pipeline::plan_cooling(c.cooling, model);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

// The directory's files and their contents.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) s[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? test::read_text(e.path()) : "<dir>";
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_hostile_case_is_refused_before_a_build_naming_its_field) {
  const config::Config base = config::parse_config(example(), COOLINGGEN_SOURCE_DIR "/data/examples", "hostile");
  const blade::BladeModel model = config::build_model(base);
  BOOST_TEST_REQUIRE(refusal(example(), model).empty(), "the built-in example itself is refused");
  const std::vector<Case> all = cases();
  BOOST_TEST(all.size() >= 60u);
  int index = 0;
  for (const Case& k : all) {
    json doc = example();
    k.edit(doc["cooling"]);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string msg = refusal(doc, model);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    BOOST_TEST(starts_with(msg, k.field), "case " << index << ": expected a refusal naming " << k.field << ", got '" << msg << "'");
    BOOST_TEST(msg.find('\n') == std::string::npos, "case " << index << ": " << msg);
    // A limit, not an attempt: no case may spend long in the checks (the blade model is built already).
    BOOST_TEST(seconds < 5.0, "case " << index << " took " << seconds << " s in the checks: " << msg);
    ++index;
  }
}

// NaN and infinity have no JSON literal: the text is refused with its line and column; a number beyond
// a double's range likewise.
BOOST_AUTO_TEST_CASE(nan_and_infinity_are_refused_as_text) {
  for (const char* bad : {"NaN", "Infinity", "-Infinity", "1e999"}) {
    std::string text = config::builtin_example_json();
    const std::string key = "\"wall_thickness\": 1.0";
    const auto at = text.find(key);
    BOOST_TEST_REQUIRE(at != std::string::npos);
    text.replace(at, key.size(), std::string("\"wall_thickness\": ") + bad);
    try {
      config::parse_config_text(text, ".", "hostile", "rotor.json");
      BOOST_FAIL(std::string(bad) + " accepted");
    } catch (const config::ConfigError& e) {
      BOOST_TEST(starts_with(e.what(), "rotor.json line "), e.what());
    }
  }
}

// Through the CLI: exit 2, one line naming the field, the output directory as it was.
BOOST_AUTO_TEST_CASE(cli_refuses_and_leaves_the_output_directory_alone) {
  test::TempDir dir("hostile_cli");
  const fs::path out = dir.path / "out";
  fs::create_directories(out / "old");
  std::ofstream(out / "blade.step") << "an earlier run's file\n";
  std::ofstream(out / "old" / "notes.txt") << "keep me\n";
  const auto before = snapshot(out);
  const std::vector<Case> all = cases();
  // The late refusals of the issue and a few of each kind.
  for (std::size_t i : {9u, 25u, 31u, 34u, 40u, 49u, 58u, 61u, 77u, 78u}) {
    BOOST_TEST_REQUIRE(i < all.size());
    json doc = example();
    all[i].edit(doc["cooling"]);
    const fs::path cfg = dir.path / ("case_" + std::to_string(i) + ".json");
    std::ofstream(cfg) << doc.dump(1);
    const test::Run r = test::run_cli("build " + test::q(cfg) + " -q -o " + test::q(out), dir.path);
    BOOST_TEST(r.exit_code == 2, "case " << i << ": exit " << r.exit_code << ": " << r.err);
    BOOST_TEST(test::count_lines(r.err) == 1, "case " << i << ": " << r.err);
    BOOST_TEST(starts_with(r.err, "coolinggen: error: " + all[i].field), "case " << i << ": " << r.err);
    BOOST_TEST(r.seconds < 30.0, "case " << i << " took " << r.seconds << " s to be refused");
    BOOST_TEST((snapshot(out) == before), "case " << i << " changed the output directory");
  }
}
