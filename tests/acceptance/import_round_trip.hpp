#pragma once
// Round trips with cooling (blade.import): an example's blade written as geomTurbo (the library's
// writer, no cooling needed) or as its uncooled solid in a named STEP file (the product's STEP writer),
// then `coolinggen build` of the same config with blade.import of that file, or of section tables of its
// sections (cli/section_tables.hpp), instead of its sections: a valid cooled part with the same feature
// names as the example's own build, and the import's figures within 0.01 mm. Section tables and STEP
// cuts have no sides: their LE and TE are found by the rule `edges` (camber_edges.hpp).
#include <fstream>
#include <set>

#include "acceptance/product_build.hpp"
#include "cli/section_tables.hpp"
#include "export/step_writer.hpp"
#include "src/blade_import/geomturbo_writer.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/config.hpp"

namespace cg::test {

enum class ImportVia { GeomTurbo, Tables, Step };

/// `edges`: blade.import.edges for tables and STEP ("" = not given: the default).
inline void expect_round_trip_cools_the_same(const ProductBuild& built, const std::string& example, ImportVia via,
                                             const std::string& edges = "") {
  const char* tags[] = {"geomturbo", "sections", "step"};
  const std::string tag = tags[static_cast<int>(via)];
  TempDir dir("acceptance_import_" + tag);
  const auto source = std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples" / example;
  const blade::BladeModel model = config::build_model(config::load_config_file(source));
  auto cfg = nlohmann::json::parse(read_text(source));
  if (via == ImportVia::Step) {
    const brep::BladeSolid solid = brep::build_blade_solid(model);
    io::write_step(dir.path / "blade.step", solid.solid, solid.faces);
    cfg["blade"]["import"] = {{"format", "step"}, {"file", "blade.step"}};
  } else {
    blade_import::write_geomturbo_file((dir.path / "blade.geomTurbo").string(), model);
    if (via == ImportVia::Tables) {
      const nlohmann::json doc = tables_import(dir.path / "blade.geomTurbo", dir.path, cfg.at("flow_path"));
      cfg["blade"]["import"] = doc.at("blade").at("import");
    } else {
      cfg.erase("flow_path");
      cfg["blade"]["import"] = {{"format", "geomturbo"}, {"file", "blade.geomTurbo"}};
    }
  }
  if (!edges.empty()) cfg["blade"]["import"]["edges"] = edges;
  cfg.erase("sections");
  cfg["output"]["formats"] = nlohmann::json::array();
  std::ofstream(dir.path / "imported.json") << cfg.dump();
  const Run run = run_cli("build " + q(dir.path / "imported.json") + " -o " + q(dir.path / "out") + " -q", dir.path);
  BOOST_TEST_REQUIRE(run.exit_code == 0, run.err);
  const auto report = nlohmann::json::parse(read_text(dir.path / "out" / "report.json"));
  std::multiset<std::string> names;
  for (const auto& body : report.at("bodies")) {
    BOOST_TEST(body.at("valid").get<bool>());
    for (const auto& [name, count] : body.at("faces").items())
      for (int k = 0; k < count.get<int>(); ++k) names.insert(name);
  }
  const std::set<std::string> imported(names.begin(), names.end()), original(built.face_names.begin(), built.face_names.end());
  BOOST_TEST(imported == original, tag << ": feature names of the imported blade's part equal the original's");
  BOOST_TEST(report.at("model").at("import").at("format").get<std::string>() == tag);
  BOOST_TEST(report.at("model").at("import").at("deviation").at("max_mm").get<double>() <= 0.01);
}


}  // namespace cg::test
