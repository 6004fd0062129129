// The film and insert keys of "cooling" (src/config/cooling_film_config.hpp): values, defaults, presets
// and field-path errors with the allowed range; every key the parser reads is documented in the schema.
#define BOOST_TEST_MODULE film_config
#include <boost/test/unit_test.hpp>

#include <fstream>
#include <set>
#include <sstream>

#include "src/config/cooling_film_config.hpp"

using namespace cg;
using namespace cg::config;
using json = nlohmann::json;

namespace {

features::FilmCoolingDefinition parse(const json& cooling) { return parse_film_cooling(Field(cooling, "cooling")); }

// The ConfigError message of parsing `cooling` ("" when it parses).
std::string error_of(const json& cooling) {
  try {
    parse(cooling);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

json valid() {
  return json::parse(R"({
    "film_rows": [
      {"diameter": 0.4, "chord": 0.35, "pitch_d": 4, "span_start": 0.2, "span_end": 0.8},
      {"shape": "7-7-7", "diameter": 0.3, "arc_length": -12.5, "count": 12, "compound_deg": 15, "chamber": 2},
      {"shape": "fan_shaped", "diameter": 0.3, "chord": -0.5, "pitch_d": 5, "inclination_deg": 35,
       "fan": {"lateral_angle_deg": 10, "forward_angle_deg": 5, "metering_length_d": 2, "edge_radius_d": 0.3}}
    ],
    "showerhead": {"rows": 5, "diameter": 0.99, "row_spacing_d": 4, "pitch_d": 7.5, "radial_angle_deg": 25, "toward": "hub"},
    "inserts": [{"chamber": 1, "gap": 0.8, "sheet_thickness": 0.4, "hub_end": "closed",
                 "jets": {"diameter": 0.5, "spacing_x_d": 6, "spacing_y_d": 7, "pattern": "inline"}}],
    "film_limits": {"min_ligament": 0.25, "clearance": 0.1}
  })");
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_CASE(values_defaults_and_presets) {
  const features::FilmCoolingDefinition d = parse(valid());
  BOOST_REQUIRE(d.rows.size() == 3u);
  BOOST_TEST((d.rows[0].shape.kind == features::HoleKind::Cylindrical));
  BOOST_TEST(d.rows[0].pitch_d == 4);
  BOOST_TEST(d.rows[0].inclination_deg == 30);
  // 7-7-7: the preset's diffuser and inclination.
  BOOST_TEST((d.rows[1].shape.kind == features::HoleKind::FanShaped));
  BOOST_TEST(d.rows[1].shape.fan.lateral_angle_deg == 7);
  BOOST_TEST(d.rows[1].shape.fan.diffuser_length_d == 3.5);
  BOOST_TEST(d.rows[1].shape.fan.edge_radius_d == 0.5);
  BOOST_TEST(d.rows[1].count == 12);
  BOOST_TEST((d.rows[1].position.kind == features::RowPosition::Kind::ArcLength));
  BOOST_TEST(d.rows[1].position.value == -12.5);
  BOOST_TEST(d.rows[1].chamber == 2);
  // fan_shaped with a metering length: the diffuser length follows from the wall.
  BOOST_TEST(d.rows[2].shape.fan.metering_length_d == 2);
  BOOST_TEST(d.rows[2].shape.fan.diffuser_length_d == 0);
  BOOST_TEST(d.rows[2].shape.fan.lateral_angle_deg == 10);
  BOOST_REQUIRE(d.showerhead.has_value());
  BOOST_TEST(d.showerhead->diameter == 0.99);
  BOOST_TEST(!d.showerhead->toward_tip);
  BOOST_REQUIRE(d.inserts.size() == 1u);
  BOOST_TEST(!d.inserts[0].hub_open);
  BOOST_TEST(d.inserts[0].tip_open);
  BOOST_TEST(!d.inserts[0].staggered);
  BOOST_TEST(d.inserts[0].jet_spacing_y_d == 7);
  BOOST_TEST(d.limits.min_ligament == 0.25);
  // A 7-7-7 row without count or pitch takes the preset's P/D 6.
  json j = valid();
  j["film_rows"][1].erase("count");
  BOOST_TEST(parse(j).rows[1].pitch_d == 6);
}

BOOST_AUTO_TEST_CASE(field_path_errors) {
  struct Case {
    std::string what;
    std::function<void(json&)> edit;
    std::string path, text;
  };
  const std::vector<Case> cases = {
      {"pitch below the diameter", [](json& j) { j["film_rows"][0]["pitch_d"] = 0.8; }, "cooling.film_rows[0].pitch_d", "below the diameter"},
      {"no position", [](json& j) { j["film_rows"][0].erase("chord"); }, "cooling.film_rows[0]", "chord and arc_length"},
      {"two positions", [](json& j) { j["film_rows"][0]["arc_length"] = 3; }, "cooling.film_rows[0]", "exactly one"},
      {"count and pitch", [](json& j) { j["film_rows"][0]["count"] = 3; }, "cooling.film_rows[0]", "count and pitch_d"},
      {"span outside", [](json& j) { j["film_rows"][0]["span_end"] = 1.2; }, "cooling.film_rows[0].span_end", "[0, 1]"},
      {"span reversed", [](json& j) { j["film_rows"][0]["span_end"] = 0.1; }, "cooling.film_rows[0].span_end", "span_start"},
      {"chord at the TE", [](json& j) { j["film_rows"][0]["chord"] = 1.0; }, "cooling.film_rows[0].chord", "(-1, 1)"},
      {"inclination", [](json& j) { j["film_rows"][0]["inclination_deg"] = 0; }, "cooling.film_rows[0].inclination_deg", "(0, 90]"},
      {"unknown shape", [](json& j) { j["film_rows"][0]["shape"] = "conical"; }, "cooling.film_rows[0].shape", "7-7-7"},
      {"fan on a cylinder", [](json& j) { j["film_rows"][0]["fan"] = json::object(); }, "cooling.film_rows[0].fan", "fan_shaped"},
      {"both lengths", [](json& j) { j["film_rows"][2]["fan"]["diffuser_length_d"] = 3; }, "cooling.film_rows[2].fan", "not both"},
      {"unknown key", [](json& j) { j["film_rows"][0]["angle"] = 3; }, "cooling.film_rows[0].angle", "unknown key"},
      {"showerhead rows overlap", [](json& j) { j["showerhead"]["row_spacing_d"] = 0.5; }, "cooling.showerhead.row_spacing_d", "overlap"},
      {"showerhead toward", [](json& j) { j["showerhead"]["toward"] = "up"; }, "cooling.showerhead.toward", "\"tip\""},
      {"insert gap", [](json& j) { j["inserts"][0]["gap"] = 0; }, "cooling.inserts[0].gap", "(0, 10]"},
      {"insert jets", [](json& j) { j["inserts"][0]["jets"]["spacing_x_d"] = 1; }, "cooling.inserts[0].jets.spacing_x_d", "[2, 100]"},
      {"insert without jets", [](json& j) { j["inserts"][0].erase("jets"); }, "cooling.inserts[0].jets", "missing"},
      {"ligament", [](json& j) { j["film_limits"]["min_ligament"] = -1; }, "cooling.film_limits.min_ligament", "[0, 10]"},
  };
  for (const Case& c : cases) {
    json j = valid();
    c.edit(j);
    const std::string e = error_of(j);
    BOOST_TEST(e.rfind(c.path + ":", 0) == 0u, c.what << ": " << e);
    BOOST_TEST(has(e, c.text), c.what << ": " << e);
  }
  BOOST_TEST(error_of(valid()) == "");
}

// Errors found while building carry the same paths.
BOOST_AUTO_TEST_CASE(build_errors_name_the_field) {
  const ConfigError e = film_error(features::FilmInputError("film_rows[1].diameter", "film_row_2_hole_003: larger than the wall allows"));
  BOOST_TEST(std::string(e.what()) == "cooling.film_rows[1].diameter: film_row_2_hole_003: larger than the wall allows");
}

namespace {
void collect(const json& s, std::set<std::string>& names) {
  if (s.is_object()) {
    if (s.contains("properties"))
      for (const auto& [k, v] : s.at("properties").items()) names.insert(k);
    for (const auto& [k, v] : s.items()) collect(v, names);
  } else if (s.is_array()) {
    for (const auto& v : s) collect(v, names);
  }
}
void keys_of(const json& j, std::set<std::string>& keys) {
  if (j.is_object())
    for (const auto& [k, v] : j.items()) {
      keys.insert(k);
      keys_of(v, keys);
    }
  else if (j.is_array())
    for (const auto& v : j) keys_of(v, keys);
}
}  // namespace

// Every key of the valid document (all the parser reads, plus the alternatives) is in the schema.
BOOST_AUTO_TEST_CASE(schema_documents_the_keys) {
  std::ifstream in(COOLINGGEN_SOURCE_DIR "/data/schema/coolinggen.schema.json");
  std::stringstream ss;
  ss << in.rdbuf();
  const json schema = json::parse(ss.str());
  for (const char* d : {"film_row", "fan_diffuser", "showerhead", "insert", "film_limits"})
    BOOST_TEST(schema.at("definitions").contains(d), d);
  std::set<std::string> names, keys;
  collect(schema, names);
  keys_of(valid(), keys);
  for (const char* k : kFilmCoolingKeys) keys.erase(k);  // properties of "cooling" (checked with the cooling section)
  for (const char* k : {"diffuser_length_d", "tip_gap", "hub_gap", "margin", "stagger", "stagnation_arc_length", "span_start"})
    keys.insert(k);
  for (const std::string& k : keys) BOOST_TEST(names.count(k) == 1u, "schema lacks " << k);
}
