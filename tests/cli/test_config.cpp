// Config parsing: every invalid field gives a ConfigError whose message starts with the field's
// path; valid documents map onto the blade model's definition structs (units converted to mm).
#define BOOST_TEST_MODULE config
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "brep/temp_files.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;

namespace {

json example() { return json::parse(config::builtin_example_json()); }

// The error message of parsing (and, with model = true, building the model of) `doc`; "" if none.
std::string error_of(const json& doc, bool model = false, const fs::path& base = ".") {
  try {
    const config::Config c = config::parse_config(doc, base, "test");
    if (model) config::build_model(c);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// Applies `edit` to the example and requires a ConfigError starting with `path` and containing `detail`.
void expect_error(const std::function<void(json&)>& edit, const std::string& path, const std::string& detail,
                  bool model = false) {
  json doc = example();
  edit(doc);
  const std::string msg = error_of(doc, model);
  BOOST_TEST(starts_with(msg, path + ":"), "expected error at " << path << ", got: '" << msg << "'");
  BOOST_TEST(msg.find(detail) != std::string::npos, "expected '" << detail << "' in: '" << msg << "'");
}

}  // namespace

BOOST_AUTO_TEST_CASE(builtin_example_parses_into_structs) {
  const config::Config c = config::builtin_example_config();
  BOOST_TEST(c.name == "hpt_rotor");
  const auto* m = std::get_if<blade::MeridionalFlowPath>(&c.blade.flow_path);
  BOOST_TEST_REQUIRE(m != nullptr);
  BOOST_TEST(m->net.hub.size() == 5u);
  BOOST_TEST(m->net.casing.size() == 5u);
  BOOST_TEST(m->net.interpolated_spans == (std::vector<double>{0.25, 0.5, 0.75}));
  BOOST_TEST(m->net.leading_edge.size() == 2u);
  BOOST_TEST(c.blade.sections.size() == 3u);
  const auto& p = std::get<blade::ParametricSectionDefinition>(c.blade.sections[2].shape);
  BOOST_TEST(p.inlet_angle_deg == 30.0);
  BOOST_TEST(p.outlet_angle_deg == -62.0);
  BOOST_TEST(p.max_thickness == 6.0);
  BOOST_TEST(c.blade.sections[2].placement.span == 1.0);
  BOOST_TEST(c.blade.options.overbuild == 0.05);
  BOOST_TEST(c.output.product_name == "hpt_rotor");
}

// The embedded example is data/examples/hpt_rotor.json.
BOOST_AUTO_TEST_CASE(builtin_example_is_the_data_example) {
  BOOST_TEST(example() == json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/examples/hpt_rotor.json")));
}

BOOST_AUTO_TEST_CASE(missing_fields) {
  expect_error([](json& d) { d.erase("units"); }, "units", "missing");
  expect_error([](json& d) { d.erase("sections"); }, "sections", "missing");
  expect_error([](json& d) { d["sections"][1]["parametric"].erase("chord"); }, "sections[1].parametric.chord", "missing");
  expect_error([](json& d) { d["flow_path"].erase("casing"); }, "flow_path.casing", "missing");
  expect_error([](json& d) { d["sections"][0].erase("span"); }, "sections[0].span", "missing");
  expect_error([](json& d) { d["sections"] = json::array(); }, "sections", "at least 1");
  expect_error([](json& d) { d["sections"][0].erase("parametric"); }, "sections[0]", "exactly one of");
}

BOOST_AUTO_TEST_CASE(out_of_range_values) {
  expect_error([](json& d) { d["sections"][2]["parametric"]["max_thickness"] = -1.0; },
               "sections[2].parametric.max_thickness", "must be (0, 38)");
  expect_error([](json& d) { d["sections"][0]["parametric"]["max_thickness"] = 39.0; },
               "sections[0].parametric.max_thickness", "< chord");
  expect_error([](json& d) { d["sections"][0]["parametric"]["chord"] = 0.0; }, "sections[0].parametric.chord", "(0, 100000] mm");
  expect_error([](json& d) { d["sections"][1]["parametric"]["stagger_deg"] = 95.0; },
               "sections[1].parametric.stagger_deg", "(-90, 90) deg");
  expect_error([](json& d) { d["sections"][0]["parametric"]["le_radius"] = 5.0; },
               "sections[0].parametric.le_radius", "max_thickness / 2");
  expect_error([](json& d) { d["sections"][0]["parametric"]["points_per_side"] = 3; },
               "sections[0].parametric.points_per_side", "[8, 2000]");
  expect_error([](json& d) { d["sections"][1]["span"] = 1.5; }, "sections[1].span", "[0, 1]");
  expect_error([](json& d) { d["sections"][1]["span"] = 0.0; }, "sections[1].span", "strictly increasing");
  expect_error([](json& d) { d["flow_path"]["hub"][1][1] = -5.0; }, "flow_path.hub[1][1]", "> 0 mm");
  expect_error([](json& d) { d["flow_path"]["streamlines"] = {1.2}; }, "flow_path.streamlines[0]", "(0, 1)");
  // Unsorted input: span fractions out of order, contour points out of order or repeated.
  expect_error([](json& d) { d["flow_path"]["streamlines"] = {0.5, 0.25}; }, "flow_path.streamlines[1]",
               "strictly increasing");
  expect_error([](json& d) { std::swap(d["flow_path"]["hub"][1], d["flow_path"]["hub"][2]); }, "flow_path.hub[2]",
               "turns back");
  expect_error([](json& d) { d["flow_path"]["casing"][2] = d["flow_path"]["casing"][1]; }, "flow_path.casing[2]",
               "coincides");
  expect_error([](json& d) { d["blade"]["overbuild"] = 0.0; }, "blade.overbuild", "(0, 0.5]");
  expect_error([](json& d) { d["units"] = "cm"; }, "units", "\"mm\"");
  expect_error([](json& d) { d["output"]["step_schema"] = "AP203"; }, "output.step_schema", "\"AP242\"");
  expect_error([](json& d) { d["flow_path"] = {{"type", "straight"}, {"span", -3}}; }, "flow_path.span", "(0, 100000] mm");
}

BOOST_AUTO_TEST_CASE(unknown_keys) {
  expect_error([](json& d) { d["colour"] = "red"; }, "colour", "unknown key");
  expect_error([](json& d) { d["sections"][0]["parametric"]["camber"] = 1; }, "sections[0].parametric.camber",
               "unknown key");
  expect_error([](json& d) { d["flow_path"]["tip"] = json::array(); }, "flow_path.tip", "unknown key");
  expect_error([](json& d) { d["blade"]["degree"] = 3; }, "blade.degree", "allowed here: overbuild");
  // A straight flow path has no hub contour.
  expect_error([](json& d) { d["flow_path"] = {{"type", "straight"}, {"span", 50}, {"hub", json::array()}}; },
               "flow_path.hub", "unknown key");
}

BOOST_AUTO_TEST_CASE(wrong_types) {
  expect_error([](json& d) { d["flow_path"]["hub"] = "abc"; }, "flow_path.hub", "must be an array, got string");
  expect_error([](json& d) { d["sections"][0]["parametric"]["chord"] = "30"; }, "sections[0].parametric.chord",
               "must be a number, got string");
  expect_error([](json& d) { d["sections"][0]["parametric"]["points_per_side"] = 12.5; },
               "sections[0].parametric.points_per_side", "must be an integer");
  expect_error([](json& d) { d["sections"] = json::object(); }, "sections", "must be an array, got object");
  expect_error([](json& d) { d["flow_path"]["type"] = 3; }, "flow_path.type", "\"meridional\"");
  expect_error([](json& d) { d["flow_path"]["hub"][0] = {1, 2, 3}; }, "flow_path.hub[0]", "exactly 2");
  expect_error([](json& d) { d["sections"][0]["offset"] = {1, true}; }, "sections[0].offset[1]", "must be a number");
  BOOST_CHECK_THROW(config::parse_config(json::array(), ".", "x"), config::ConfigError);
  try {
    config::parse_config_text("{\"units\": \"mm\",\n \"flow_path\": }", ".", "x");
    BOOST_FAIL("invalid JSON accepted");
  } catch (const config::ConfigError& e) {
    BOOST_TEST(starts_with(e.what(), "config: invalid JSON"));
    BOOST_TEST(std::string(e.what()).find("line 2") != std::string::npos, e.what());
  }
  BOOST_CHECK_THROW(config::load_config_file("/nonexistent/cfg.json"), config::ConfigError);
}

BOOST_AUTO_TEST_CASE(point_sections) {
  const json values = {{0, 0}, {10, 1}, {20, 0}};
  expect_error([&](json& d) { d["sections"][0] = {{"span", 0}, {"points", {{"values", values}}}}; },
               "sections[0].points.values", "at least 4 entries, got 3");
  expect_error([&](json& d) { d["sections"][0] = {{"span", 0}, {"points", {{"values", values}, {"file", "a.csv"}}}}; },
               "sections[0].points", "exactly one of");
  expect_error([&](json& d) { d["sections"][0] = {{"span", 0}, {"points", {{"file", "no_such_file.csv"}}}}; },
               "sections[0].points.file", "cannot be opened");
  expect_error([&](json& d) { d["sections"][0] = {{"span", 0}, {"points", {{"file", "x.csv"}, {"unit", "ft"}}}}; },
               "sections[0].points.unit", "\"in\"");

  // A file with 3 points, relative to the base directory; and inline values converted from cm.
  test::TempDir dir("config");
  std::ofstream(dir.path / "three.csv") << "x,y\n0,0\n1,1\n2,0\n";
  json doc = example();
  doc["sections"][0] = {{"span", 0}, {"points", {{"file", "three.csv"}}}};
  const std::string msg = error_of(doc, false, dir.path);
  BOOST_TEST(starts_with(msg, "sections[0].points.file:"), msg);
  BOOST_TEST(msg.find("at least 4 points") != std::string::npos, msg);

  doc["sections"][0] = {{"span", 0}, {"points", {{"values", {{0, 0}, {1, 0.2}, {2, 0}, {1, -0.1}}}, {"unit", "cm"}, {"te_index", 2}}}};
  const config::Config c = config::parse_config(doc, dir.path, "t");
  const auto& p = std::get<blade::PointSectionDefinition>(c.blade.sections[0].shape);
  BOOST_TEST(p.points.size() == 4u);
  BOOST_TEST(p.points[1].x() == 10.0);
  BOOST_TEST(p.points[1].y() == 2.0);
  BOOST_TEST(p.te_index == 2);
  doc["sections"][0]["points"]["te_index"] = 4;
  BOOST_TEST(starts_with(error_of(doc, false, dir.path), "sections[0].points.te_index:"));

  // The C3X profile file (cm) by absolute path.
  doc["sections"][0] = {{"span", 0}, {"points", {{"file", COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv"}, {"unit", "cm"}}}};
  const config::Config c3x_config = config::parse_config(doc, ".", "t");
  const auto& c3x = std::get<blade::PointSectionDefinition>(c3x_config.blade.sections[0].shape);
  BOOST_TEST(c3x.points.size() == 78u);
  BOOST_TEST(std::abs(c3x.points[0].x() - 1.097) < 1e-12);  // 0.1097 cm
}

// Checks that only the blade model can make (crossing streamlines, impossible sections) come back as
// ConfigError naming the part of the config.
BOOST_AUTO_TEST_CASE(model_checks_name_the_field) {
  BOOST_TEST(error_of(example(), true) == "");
  // An explicit streamline that crosses the casing.
  expect_error(
      [](json& d) {
        d["flow_path"]["streamlines"] = {{{"span", 0.5}, {"points", {{-30.0, 300.0}, {20.0, 335.0}, {70.0, 300.0}}}}};
      },
      "flow_path", "", true);
  // A streamline below the hub.
  expect_error(
      [](json& d) {
        d["flow_path"]["streamlines"] = {{{"span", 0.5}, {"points", {{-30.0, 260.0}, {70.0, 265.0}}}}};
      },
      "flow_path", "", true);
  // A parametric section within every field's range whose metal angle is more than 90 deg from its
  // stagger (only the section model checks that combination).
  expect_error([](json& d) { d["sections"][1]["parametric"]["inlet_metal_angle_deg"] = 89.0; },
               "sections[1].parametric", "", true);
  expect_error([](json& d) { d["sections"][0]["parametric"]["le_radius"] = 4.5; }, "sections[0].parametric.le_radius",
               "< max_thickness / 2");
}

namespace {

void schema_property_names(const json& s, std::set<std::string>& names) {
  if (s.is_object()) {
    if (s.contains("properties") && s["properties"].is_object())
      for (const auto& p : s["properties"].items()) names.insert(p.key());
    for (const auto& v : s) schema_property_names(v, names);
  } else if (s.is_array()) {
    for (const auto& v : s) schema_property_names(v, names);
  }
}

void document_keys(const json& d, std::set<std::string>& keys) {
  if (d.is_object())
    for (const auto& p : d.items()) {
      keys.insert(p.key());
      document_keys(p.value(), keys);
    }
  else if (d.is_array())
    for (const auto& v : d) document_keys(v, keys);
}

}  // namespace

// The schema is draft-07 JSON and documents every key the example uses and every key the parser
// accepts in a point section and the options (those the example does not use).
BOOST_AUTO_TEST_CASE(schema_documents_the_fields) {
  const json schema = json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/schema/coolinggen.schema.json"));
  BOOST_TEST(schema.at("$schema").get<std::string>() == "http://json-schema.org/draft-07/schema#");
  std::set<std::string> names, keys;
  schema_property_names(schema, names);
  document_keys(example(), keys);
  for (const char* k : {"file", "values", "unit", "le_index", "te_index", "suction_side", "rotation_deg", "scale", "offset",
                        "theta_deg", "stations", "samples", "points_per_side", "product_name", "$schema", "span", "points"})
    keys.insert(k);
  for (const auto& k : keys) BOOST_TEST(names.count(k) == 1u, "schema lacks " << k);
}
