// Bad "cooling" input: every case gets a ConfigError that names its field (and, where the blade decides,
// the span / chord where it fails); nothing is built half-way.
#define BOOST_TEST_MODULE passages_config
#include <boost/test/unit_test.hpp>

#include <functional>
#include <nlohmann/json.hpp>

#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/cooling.hpp"
#include "src/config/cooling_config.hpp"

using namespace cg;
using nlohmann::json;

namespace {

// The built-in example without its coolant section (whose per-row sinks name film rows these tests remove).
json example() {
  json d = json::parse(config::builtin_example_json());
  d.erase("coolant");
  return d;
}
json c3x() {
  std::ifstream in(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json");
  return json::parse(in);
}

// The uncooled blades, built once (the cooling input does not change them).
struct Built {
  blade::BladeModel model;
  brep::NamedShape blade;
};
const Built& built(const json& doc) {
  static std::map<std::string, std::unique_ptr<Built>> cache;
  json plain = doc;
  plain.erase("cooling");
  auto& slot = cache[plain.dump()];
  if (!slot) {
    slot = std::make_unique<Built>();
    slot->model = config::build_model(config::parse_config(plain, COOLINGGEN_SOURCE_DIR "/data/examples", "t"));
    const brep::BladeSolid s = brep::build_blade_solid(slot->model);
    slot->blade = {s.solid, s.faces};
  }
  return *slot;
}

// Parses the edited document and builds its cooling; requires a ConfigError whose message starts with
// `path` and contains every detail.
void expect_error(json doc, const std::function<void(json&)>& edit, const std::string& path,
                  const std::vector<std::string>& details) {
  edit(doc);
  try {
    const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
    pipeline::apply_cooling(built(doc).model, pipeline::plan_cooling(c.cooling, built(doc).model), built(doc).blade);
    BOOST_ERROR("no error for " << path);
  } catch (const config::ConfigError& e) {
    const std::string m = e.what();
    BOOST_TEST_MESSAGE(m);
    BOOST_TEST(m.rfind(path, 0) == 0u, "message does not start with " << path << ": " << m);
    for (const auto& d : details) BOOST_TEST(m.find(d) != std::string::npos, "message lacks \"" << d << "\": " << m);
  }
}

json& core(json& d) { return d["cooling"]["core"]; }

}  // namespace

BOOST_AUTO_TEST_CASE(field_ranges_and_types) {
  expect_error(example(), [](json& d) { core(d)["ribs"][0]["fillet_radius"] = -0.5; },
               "cooling.core.ribs[0].fillet_radius", {"[0, 10]", "-0.5"});
  expect_error(example(), [](json& d) { core(d)["ribs"][1]["turnaround"]["tip_radius"] = 0.8; },
               "cooling.core.ribs[1].turnaround.tip_radius", {"thickness / 2"});
  expect_error(example(), [](json& d) { core(d)["ribs"][1]["turnaround"]["gap"] = -1; },
               "cooling.core.ribs[1].turnaround.gap", {"(0, 200]"});
  expect_error(example(), [](json& d) { core(d)["ribs"][0]["thickness"] = 0; }, "cooling.core.ribs[0].thickness", {});
  expect_error(example(), [](json& d) { core(d)["ribs"][0]["suction_chord"] = 1.2; },
               "cooling.core.ribs[0].suction_chord", {"(0, 1)"});
  expect_error(example(), [](json& d) { core(d)["wall_thickness"] = -1; }, "cooling.core.wall_thickness", {});
  expect_error(example(), [](json& d) { core(d)["tip_cap"] = {{"thickness", 1.0}, {"open", true}}; },
               "cooling.core.tip_cap.thickness", {"open"});
  expect_error(example(), [](json& d) { core(d)["inlets"][0]["diameter"] = -2; }, "cooling.core.inlets[0].diameter", {});
  expect_error(example(), [](json& d) { core(d)["chambers"] = 3; }, "cooling.core.chambers", {"unknown key"});
  expect_error(example(), [](json& d) { d["cooling"]["pin_finz"] = 1; }, "cooling.pin_finz", {"unknown key"});
  expect_error(example(),
               [](json& d) {
                 core(d)["wall_thickness"] = {{"spans", {0.0, 0.5, 0.4}}, {"chords", {-1, 1}}, {"values", {{1, 1}, {1, 1}, {1, 1}}}};
               },
               "cooling.core.wall_thickness.spans[2]", {"increasing"});
  expect_error(c3x(), [](json& d) { d["cooling"]["radial_passages"]["file"] = "../c3x/missing.csv"; },
               "cooling.radial_passages.file", {"cannot read"});
}

BOOST_AUTO_TEST_CASE(ribs_outside_overlapping_or_out_of_order) {
  // A rib whose thickness and fillets reach past the inner wall's trailing-edge crease (at suction chord
  // 0.983 on the hub section: chord is the arc-length fraction of the side).
  expect_error(example(), [](json& d) { core(d)["ribs"][2]["suction_chord"] = 0.97; },
               "cooling.core.ribs[2].suction_chord", {"outside the core", "span", "inner wall ends at suction chord"});
  // Two ribs closer than their thickness.
  expect_error(example(), [](json& d) { core(d)["ribs"][1]["suction_chord"] = 0.26; },
               "cooling.core.ribs[1].suction_chord", {"closer than their thickness", "span", "clear width"});
  expect_error(example(), [](json& d) { core(d)["ribs"][1]["pressure_chord"] = -0.1; },
               "cooling.core.ribs[1].pressure_chord", {"from the LE to the TE"});
}

// A rib inside the core but where it is too thin for the rib and its fillets (suction chord 0.94, next
// to the trailing-edge crease): OCCT's core split warns, and the failure names the ribs to move.
BOOST_AUTO_TEST_CASE(rib_meeting_a_wall_at_a_shallow_angle) {
  // Rib 3 moved to suction chord 0.94 meets the pressure-side wall at 4-5 deg (near the TE's crease): a
  // fillet there runs ~11 radii along the rib (r cot(a / 2)), more than the rib's length. The plan refuses
  // it, naming the radius that fits (OCCT's split or fillet of the core failed on it before).
  json doc = example();
  doc["cooling"].erase("film_rows");
  doc["cooling"].erase("showerhead");
  core(doc).erase("turbulators");
  core(doc).erase("trailing_edge");
  core(doc)["ribs"][2]["suction_chord"] = 0.94;
  const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
  try {
    pipeline::plan_cooling(c.cooling, built(doc).model);
    BOOST_ERROR("the plan did not refuse a rib meeting a wall at 4-5 deg");
  } catch (const config::ConfigError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.rfind("cooling.core.ribs[2].fillet_radius: rib 3 meets the walls at", 0) == 0u, m);
    for (const char* d : {" deg at span ", "fillets of radius 0.5 mm at both ends would run", "must be < "})
      BOOST_TEST(m.find(d) != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_CASE(wall_too_thick_for_the_blade) {
  // The tip LE radius is 1.3 mm: the blade right behind its leading edge is thinner than two 1.6 mm walls
  // (the planning stage meets this before the fold of the offset at the LE's radius of curvature).
  expect_error(example(), [](json& d) { core(d)["wall_thickness"] = 1.6; },
               "cooling.core.wall_thickness", {"1.6 mm", "leaves no core", "span"});
}

BOOST_AUTO_TEST_CASE(coolant_supply) {
  expect_error(example(), [](json& d) { core(d).erase("inlets"); }, "cooling.core.inlets", {"receive no coolant", "1, 2, 3, 4"});
  expect_error(example(), [](json& d) { core(d)["inlets"][1]["chamber"] = 9; }, "cooling.core.inlets[1].chamber",
               {"[1, 4]"});
  expect_error(example(), [](json& d) { core(d)["tip_cap"] = {{"open", true}}; }, "cooling.core.ribs[1].turnaround.end",
               {"open"});
  // One chamber (no ribs, so no turbulators between ribs and no film rows into chamber 4 either): an
  // inlet wider than the chamber at the hub floor.
  expect_error(example(),
               [](json& d) {
                 core(d).erase("ribs");
                 core(d).erase("turbulators");
                 d["cooling"].erase("film_rows");
                 d["cooling"].erase("showerhead");
                 core(d)["inlets"] = {{{"chamber", 1}, {"diameter", 9.0}}};
               },
               "cooling.core.inlets[0].diameter", {"does not fit"});
}

BOOST_AUTO_TEST_CASE(turnaround_gap_leaves_no_rib) {
  expect_error(example(), [](json& d) { core(d)["ribs"][1]["turnaround"]["gap"] = 80; },
               "cooling.core.ribs[1].turnaround", {"leaves no rib"});
}

BOOST_AUTO_TEST_CASE(radial_passages) {
  // Passage 10's axis lies 2.63 mm inside the wall: a 6 mm passage there breaks through.
  expect_error(c3x(), [](json& d) { d["cooling"]["radial_passages"] = {{{"position", {72.087, 13.079}}, {"diameter", 6.0}}}; },
               "cooling.radial_passages[0].position", {"breaks through the wall"});
  expect_error(c3x(),
               [](json& d) {
                 d["cooling"]["radial_passages"] = {{{"position", {40.0, 80.0}}, {"diameter", 4.0}},
                                                    {{"position", {41.0, 80.0}}, {"diameter", 4.0}}};
               },
               "cooling.radial_passages[1].position", {"overlap"});
  expect_error(example(),
               [](json& d) {
                 d["cooling"].erase("core");
                 for (const char* k : {"showerhead", "film_rows"}) d["cooling"].erase(k);  // film holes need the core
                 d["cooling"]["radial_passages"] = {{{"position", {10.0, 0.0}}, {"diameter", 2.0}}};
               },
               "cooling.radial_passages", {"straight vanes only"});
}
