// Config fields of the hand-off outputs and the mesh command: defaults, values read, and errors that
// name the field path and the allowed range (ConfigError), as for every other config field.
#define BOOST_TEST_MODULE handoff_config
#include <boost/test/unit_test.hpp>

#include <functional>
#include <nlohmann/json.hpp>

#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

using namespace cg;
using nlohmann::json;

namespace {

config::Config parse(const std::function<void(json&)>& edit) {
  json doc = json::parse(config::builtin_example_json());
  edit(doc);
  return config::parse_config(doc, ".", "test");
}

void expect_error(const std::function<void(json&)>& edit, const std::string& path, const std::string& detail) {
  try {
    parse(edit);
    BOOST_ERROR("no error for " << path);
  } catch (const config::ConfigError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find(path) != std::string::npos, m);
    BOOST_TEST(m.find(detail) != std::string::npos, m);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(defaults) {
  const config::Config c = parse([](json& d) { d.erase("output"); });
  BOOST_TEST(c.output.step_schema == "AP242");
  BOOST_TEST(c.output.iges_mode == "faces");
  // every format written by default (README, Outputs), in the order they are written; the network
  // because the built-in example has "cooling" and "coolant"
  BOOST_TEST(config::output_format_names(c.output.formats) ==
             (std::vector<std::string>{"step", "iges", "brep", "stl", "vtk", "glb", "preview", "sections", "network", "html", "report_md"}));
  BOOST_TEST(c.output.stl_deflection == 0.01);
  BOOST_TEST(c.output.section_spans.size() == 5u);
  BOOST_TEST(c.mesh.max_size == 1.5);
  BOOST_TEST(c.mesh.metal);
  BOOST_TEST(c.mesh.coolant);
  BOOST_TEST(c.mesh.msh);
  BOOST_TEST(c.mesh.vtu);
  BOOST_TEST(!c.mesh.cgns);  // mesh.cgns on request
}

BOOST_AUTO_TEST_CASE(values_are_read) {
  const config::Config c = parse([](json& d) {
    d["output"] = {{"formats", {"step", "iges"}}, {"stl_deflection", 0.05}, {"section_spans", {0.2, 0.8}}};
    d["mesh"] = {{"max_size", 3.0}, {"min_size", 0.1}, {"domains", {"coolant"}}, {"formats", {"msh"}},
                 {"physical_groups", "face_name"}, {"threads", 1}, {"optimize", false}, {"feature_curvature_elements", 30}};
  });
  BOOST_TEST((c.output.formats == std::vector<config::OutputFormat>{config::OutputFormat::Step, config::OutputFormat::Iges}));
  BOOST_TEST(c.output.stl_deflection == 0.05);
  BOOST_TEST(c.output.section_spans == (std::vector<double>{0.2, 0.8}));
  BOOST_TEST(c.mesh.max_size == 3.0);
  BOOST_TEST(c.mesh.min_size == 0.1);
  BOOST_TEST(!c.mesh.metal);
  BOOST_TEST(c.mesh.coolant);
  BOOST_TEST(c.mesh.msh);
  BOOST_TEST(!c.mesh.vtu);
  BOOST_TEST(!c.mesh.cgns);
  BOOST_TEST(c.mesh.group_by_face_name);
  BOOST_TEST(!c.mesh.optimize);
  BOOST_TEST(c.mesh.feature_curvature_elements == 30);
}

BOOST_AUTO_TEST_CASE(errors_name_the_field) {
  expect_error([](json& d) { d["output"]["formats"] = {"step", "gltf"}; }, "output.formats[1]: unknown output format \"gltf\"",
               "(allowed: \"step\", \"iges\", \"brep\"");
  expect_error([](json& d) { d["output"]["formats"] = {"stl", "step", "stl"}; }, "output.formats[2]", "\"stl\" is listed twice");
  expect_error([](json& d) { d["output"]["formats"] = {"step", 3}; }, "output.formats[1]", "string");
  expect_error([](json& d) { d["output"]["stl_deflection"] = 0; }, "output.stl_deflection", "[0.0001, 10]");
  expect_error([](json& d) { d["output"]["section_spans"] = {0.5, 0.4}; }, "output.section_spans[1]", "increasing");
  expect_error([](json& d) { d["output"]["section_spans"] = {1.5}; }, "output.section_spans[0]", "[0, 1]");
  expect_error([](json& d) { d["mesh"] = {{"max_size", -1}}; }, "mesh.max_size", "[0.01, 1000]");
  expect_error([](json& d) { d["mesh"] = {{"max_size", 1}, {"min_size", 2}}; }, "mesh.min_size", "max_size");
  expect_error([](json& d) { d["mesh"] = {{"domains", {"air"}}}; }, "mesh.domains[0]", "coolant");
  expect_error([](json& d) { d["mesh"] = {{"optimize", 1}}; }, "mesh.optimize", "true or false");
  expect_error([](json& d) { d["mesh"] = {{"formats", {"cgsn"}}}; }, "mesh.formats[0]", "\"cgns\"");
  expect_error([](json& d) { d["mesh"] = {{"formats", {"cgns", "cgns"}}}; }, "mesh.formats[1]", "twice");
  expect_error([](json& d) { d["mesh"] = {{"formats", json::array()}}; }, "mesh.formats", "between 1 and 3");
  expect_error([](json& d) { d["mesh"] = {{"domains", {"metal", "metal"}}}; }, "mesh.domains[1]", "twice");
  expect_error([](json& d) { d["mesh"] = {{"size", 1}}; }, "mesh", "size");
  expect_error([](json& d) { d["mesh"] = 3; }, "mesh", "object");
}

// coolant.sinks.rows: a static pressure per exit row over its kind's; exit row names only (a row the
// blade does not have, e.g. in a variant with fewer film rows, has no exit to apply to).
BOOST_AUTO_TEST_CASE(coolant_sink_rows) {
  const config::Config c = parse([](json& d) { d["coolant"]["sinks"]["rows"] = {{"film_row_2", 1.2e6}, {"te_slots", 1.1e6}}; });
  BOOST_TEST(c.coolant->sink("film_row_2", config::SinkKind::PressureSide) == 1.2e6);
  BOOST_TEST(c.coolant->sink("te_slots", config::SinkKind::TrailingEdge) == 1.1e6);
  BOOST_TEST(c.coolant->sink("film_row_1", config::SinkKind::PressureSide) == c.coolant->sink(config::SinkKind::PressureSide));
  BOOST_TEST(parse([](json& d) { d["coolant"]["sinks"]["rows"] = {{"film_row_9", 1.2e6}}; }).coolant->sink_by_row.size() == 1u);
  expect_error([](json& d) { d["coolant"]["sinks"]["rows"] = {{"film_rows_2", 1.2e6}}; }, "coolant.sinks.rows.film_rows_2",
               "film_row_1, film_row_2, film_row_3, film_row_4, film_row_5, showerhead_1, showerhead_2, showerhead_3, te_slots");
  expect_error([](json& d) { d["coolant"]["sinks"]["rows"] = {{"film_row_2", 3e6}}; }, "coolant.sinks.rows.film_row_2", "Pa");
  expect_error([](json& d) { d["coolant"]["sinks"]["rows"] = 1.2e6; }, "coolant.sinks.rows", "must be an object");
}
