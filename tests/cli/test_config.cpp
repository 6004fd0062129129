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
#include "cli/star_profile.hpp"
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
// "booleans.allow_perturbation": false reaches every boolean step of the passages and the film holes.
BOOST_AUTO_TEST_CASE(allow_perturbation_reaches_the_feature_definitions) {
  json doc = example();
  const config::Config a = config::parse_config(doc, ".", "test");
  BOOST_TEST((a.cooling.passages.retries == features::PerturbedRetries::Any));
  doc["booleans"] = {{"allow_perturbation", false}};
  const config::Config b = config::parse_config(doc, ".", "test");
  BOOST_TEST((b.cooling.passages.retries == features::PerturbedRetries::SameGeometry));
  BOOST_TEST((b.cooling.film.retries == features::PerturbedRetries::SameGeometry));
}

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
  expect_error([](json& d) { d["output"]["iges_mode"] = "msbo"; }, "output.iges_mode", "\"brep\"");
  expect_error([](json& d) { d["cooling"] = json::object(); }, "cooling", "no cooling feature given");
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
  expect_error([](json& d) { d["booleans"] = {{"allow_perturbation", 0}}; }, "booleans.allow_perturbation",
               "must be true or false, got number");
  expect_error([](json& d) { d["booleans"] = {{"allow_perturbations", false}}; }, "booleans.allow_perturbations", "unknown");
  BOOST_CHECK_THROW(config::parse_config(json::array(), ".", "x"), config::ConfigError);
  try {
    config::parse_config_text("{\"units\": \"mm\",\n \"flow_path\": }", ".", "x");
    BOOST_FAIL("invalid JSON accepted");
  } catch (const config::ConfigError& e) {
    BOOST_TEST(starts_with(e.what(), "config line 2, column 15: syntax error"), e.what());
    BOOST_TEST(std::string(e.what()).find("json.exception") == std::string::npos, e.what());
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
  json doc = example();
  doc["coolant"]["sinks"].erase("rows");  // its keys are exit rows' names, not fields
  document_keys(doc, keys);
  for (const char* k : {"file", "values", "unit", "le_index", "te_index", "suction_side", "rotation_deg", "scale", "offset",
                        "theta_deg", "stations", "samples", "points_per_side", "product_name", "$schema", "span", "points",
                        "formats", "files", "frame", "tolerance", "spans", "samples_per_side", "edges"})
    keys.insert(k);
  for (const auto& k : keys) BOOST_TEST(names.count(k) == 1u, "schema lacks " << k);
}

// The format names of both schemas are the one list of output formats (src/config/output_format.hpp).
BOOST_AUTO_TEST_CASE(schemas_list_the_output_formats) {
  const json schema = json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/schema/coolinggen.schema.json"));
  const json study = json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/schema/study.schema.json"));
  std::vector<std::string> all;
  for (const config::OutputFormatInfo& f : config::kOutputFormats) all.push_back(f.name);
  const json& formats = schema.at("definitions").at("output_options").at("properties").at("formats");
  BOOST_TEST(formats.at("items").at("enum").get<std::vector<std::string>>() == all);
  BOOST_TEST(formats.at("default").get<std::vector<std::string>>() ==
             config::output_format_names(config::default_output_formats()));
  BOOST_TEST(study.at("properties").at("outputs").at("items").at("enum").get<std::vector<std::string>>() == all);
}

namespace {

// The ConfigError of parsing `text` ("" if none).
std::string text_error(const std::string& text) {
  try {
    config::parse_config_text(text, ".", "t", "cfg.json");
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// Issue 8 item 7: what a JSON library accepts silently is refused, in the text's terms and without the
// library's exception ids.
BOOST_AUTO_TEST_CASE(strict_json_text) {
  const std::string ex = config::builtin_example_json();
  // A duplicate key: the last value would silently win ("unit": "cm", "unit": "mm" -> 10x too small).
  std::string dup = ex;
  dup.replace(dup.find("\"units\": \"mm\""), 13, "\"units\": \"cm\", \"units\": \"mm\"");
  BOOST_TEST(text_error(dup).rfind("units: duplicate key", 0) == 0u, text_error(dup));
  dup = ex;
  const auto chord = dup.find("\"chord\"", dup.find("\"span\": 0.5"));
  dup.insert(chord, "\"chord\": 20, ");
  BOOST_TEST(text_error(dup).rfind("sections[1].parametric.chord: duplicate key", 0) == 0u, text_error(dup));
  // Duplicates inside arrays of objects and in point values are found at their path too.
  BOOST_TEST(text_error(R"({"a": [{"b": 1}, {"c": {"d": 1, "d": 2}}]})").rfind("a[1].c.d: duplicate key", 0) == 0u);
  // Numbers beyond a double: a config error at its line and column, not an internal error.
  const std::string big = "{\"units\": \"mm\",\n  \"flow_path\": {\"type\": \"straight\", \"span\": 1e99999}}";
  const std::string msg = text_error(big);
  BOOST_TEST(msg.rfind("cfg.json line 2, column 45: number out of range", 0) == 0u, msg);
  BOOST_TEST(msg.find("1e99999") != std::string::npos, msg);
  BOOST_TEST(text_error("{\"x\": -1e400}").find("out of range") != std::string::npos);
  // Syntax errors: line and column of the offending token, no "[json.exception.parse_error.101]".
  for (const std::string& bad : {std::string("{\"units\": \"mm\",\n\n  \"flow_path\" 3}"), std::string(""), std::string("{\"a\": tru}")}) {
    const std::string m = text_error(bad);
    BOOST_TEST(m.rfind("cfg.json line ", 0) == 0u, m);
    BOOST_TEST(m.find("json.exception") == std::string::npos, m);
    BOOST_TEST(m.find("[json") == std::string::npos, m);
  }
  BOOST_TEST(text_error("{\"units\": \"mm\",\n\n  \"flow_path\" 3}").rfind("cfg.json line 3, column 15: syntax error", 0) == 0u);
  // The document parsed strictly is the same as the library's.
  BOOST_TEST(config::parse_config_text(ex, ".", "t").source == json::parse(ex));
}

// JSON Schema counts 97.0 as an integer; 97.5 is not one. Range errors show the value as given.
BOOST_AUTO_TEST_CASE(integers_as_json_schema_counts_them) {
  json d = example();
  d["blade"]["chordwise_samples"] = 97.0;
  d["sections"][0]["parametric"]["points_per_side"] = 1e2;
  const config::Config c = config::parse_config(d, ".", "t");
  BOOST_TEST(c.blade.options.chordwise_samples == 97);
  BOOST_TEST(std::get<blade::ParametricSectionDefinition>(c.blade.sections[0].shape).points_per_side == 100);
  expect_error([](json& x) { x["blade"]["chordwise_samples"] = 97.5; }, "blade.chordwise_samples", "must be an integer, got number 97.5");
  expect_error([](json& x) { x["blade"]["chordwise_samples"] = 4.0; }, "blade.chordwise_samples", "[8, 2000], got 4.0");
  expect_error([](json& x) { x["blade"]["chordwise_samples"] = 1e30; }, "blade.chordwise_samples", "[8, 2000]");
  expect_error([](json& x) { x["blade"]["chordwise_samples"] = 3000000000ull; }, "blade.chordwise_samples", "[8, 2000]");
  // 4 significant digits without padding, never "0.100000".
  expect_error([](json& x) { x["flow_path"]["streamlines"] = {0.3, 0.1}; }, "flow_path.streamlines[1]",
               "got 0.1 after 0.3");
  expect_error([](json& x) { x["blade"]["overbuild"] = 0.7; }, "blade.overbuild", "got 0.7");
  expect_error([](json& x) { x["sections"][0]["parametric"]["chord"] = -1e-9; }, "sections[0].parametric.chord",
               "(0, 100000] mm, got -1e-09");
}

// Point files: an index column is recognised, other unnamed layouts are refused, and problems with
// the points are reported by file line.
BOOST_AUTO_TEST_CASE(point_files_columns_and_lines) {
  test::TempDir dir("config_points");
  const auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir.path / name) << text; };
  const auto doc_for = [&](const std::string& file) {
    json d = example();
    d["sections"] = {{{"span", 0}, {"points", {{"file", file}}}}};
    d["flow_path"] = {{"type", "straight"}, {"span", 50}};
    return d;
  };
  const auto points_of = [&](const std::string& file) {
    const config::Config c = config::parse_config(doc_for(file), dir.path, "t");
    return std::get<blade::PointSectionDefinition>(c.blade.sections[0].shape).points;
  };
  const std::string xy = "0,0\n10,1\n20,0\n10,-1\n";
  write("xy.csv", xy);
  write("i1.csv", "1,0,0\n2,10,1\n3,20,0\n4,10,-1\n");
  write("i0.csv", "0 0 0\n1 10 1\n2 20 0\n3 10 -1\n");
  write("ixy.csv", "i,x,y\n7,0,0\n3,10,1\n9,20,0\n1,10,-1\n");
  BOOST_TEST(points_of("i1.csv") == points_of("xy.csv"));
  BOOST_TEST(points_of("i0.csv") == points_of("xy.csv"));
  BOOST_TEST(points_of("ixy.csv") == points_of("xy.csv"));
  // (x, y, z) or any other unnamed three columns: ambiguous, refused naming the file field.
  write("xyz.csv", "0,0,5\n10,1,5\n20,0,5\n10,-1,5\n");
  write("four.csv", "1,0,0,0\n2,10,1,0\n3,20,0,0\n4,10,-1,0\n");
  write("noxy.csv", "a,b,c\n0,0,5\n10,1,5\n20,0,5\n10,-1,5\n");
  for (const char* f : {"xyz.csv", "four.csv", "noxy.csv"}) {
    const std::string m = error_of(doc_for(f), false, dir.path);
    BOOST_TEST(starts_with(m, "sections[0].points.file:"), m);
    BOOST_TEST(m.find("ambiguous") != std::string::npos, m);
    BOOST_TEST(m.find("header") != std::string::npos, m);
  }
  // Coincident and crossing points by file line (comments and the header count as lines).
  write("dup.csv", "# profile\nx,y\n0,0\n10,1\n10,1\n20,0\n10,-1\n");
  std::string m = error_of(doc_for("dup.csv"), true, dir.path);
  BOOST_TEST(starts_with(m, "sections[0].points.file:"), m);
  BOOST_TEST(m.find("line 4 and line 5 give the same point") != std::string::npos, m);
  write("cross.csv", "x,y\n0,0\n10,1\n10,-1\n20,0\n");
  m = error_of(doc_for("cross.csv"), true, dir.path);
  BOOST_TEST(m.find("crosses itself: segment line 3 - line 4 crosses segment line 5 - line 2") != std::string::npos, m);
  // Inline values: by their JSON path.
  json d = doc_for("xy.csv");
  d["sections"][0]["points"] = {{"values", {{0, 0}, {10, 1}, {10, 1}, {20, 0}, {10, -1}}}};
  m = error_of(d, true);
  BOOST_TEST(starts_with(m, "sections[0].points.values:"), m);
  BOOST_TEST(m.find("values[1] and values[2] give the same point") != std::string::npos, m);
}

// A failed LE/TE detection is a config error naming the section, with the le_index/te_index remedy.
BOOST_AUTO_TEST_CASE(le_te_detection_failure_gives_the_remedy) {
  test::TempDir dir("config_star");
  test::write_star_csv(dir.path / "star.csv", "# a five-pointed star: no leading or trailing edge to detect\n");
  json d = example();
  d["flow_path"] = {{"type", "straight"}, {"span", 50}};
  d["sections"] = {{{"span", 0}, {"points", {{"file", "star.csv"}}}}};
  const std::string m = error_of(d, true, dir.path);
  BOOST_TEST(starts_with(m, "sections[0].points: LE/TE detection"), m);
  BOOST_TEST(m.find("give \"le_index\" and \"te_index\" in sections[0].points") != std::string::npos, m);
  BOOST_TEST(m.find("index 0 is line 3, index 9 is line 12") != std::string::npos, m);
  d["sections"][0]["points"]["le_index"] = 0;
  d["sections"][0]["points"]["te_index"] = 5;
  BOOST_TEST(error_of(d, true, dir.path) == "");
}

BOOST_AUTO_TEST_CASE(config_file_errors) {
  test::TempDir dir("config_files");
  std::ofstream(dir.path / "a.json") << "{}";
  const auto message = [](const fs::path& p) {
    try {
      config::load_config_file(p);
    } catch (const config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message(dir.path) == "config: " + dir.path.string() + " is a directory, not a config file (it contains a.json)");
  BOOST_TEST(message(dir.path / "none.json") == "config: " + (dir.path / "none.json").string() + " does not exist");
  BOOST_TEST(message(dir.path / "a.json") == "units: missing (required)");
}

// blade.import.edges chooses the LE / TE rule of outlines without sides; a geomTurbo file's sides give
// them, so the field is refused there (before the file is read), naming the field and the formats.
BOOST_AUTO_TEST_CASE(import_edges_only_without_sides) {
  const std::string e = text_error(
      R"({"units": "mm", "blade": {"import": {"format": "geomturbo", "file": "a.geomTurbo", "edges": "camber_line"}}})");
  BOOST_TEST(e.rfind("blade.import.edges: is only for \"sections\", \"step\" and \"iges\"", 0) == 0u, e);
  const std::string bad = text_error(
      R"({"units": "mm", "flow_path": {"span": 10}, "blade": {"import": {"format": "step", "file": "a.step", "edges": "middle"}}})");
  BOOST_TEST(bad.rfind("blade.import.edges:", 0) == 0u, bad);
  BOOST_TEST(bad.find("camber_line") != std::string::npos, bad);
}
