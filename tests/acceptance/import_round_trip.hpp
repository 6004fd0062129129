#pragma once
// Round trips with cooling (blade.import): an example's blade written as geomTurbo (the library's
// writer, no cooling needed) or as its uncooled solid in a named STEP file (the product's STEP writer),
// then `coolinggen build` of the same config with blade.import of that file, or of section tables of its
// sections (cli/section_tables.hpp), instead of its sections: a valid cooled part with the same feature
// names as the example's own build (read back from its STEP by OCCT), and the import's figures within
// 0.01 mm. Section tables and STEP
// cuts have no sides: their LE and TE are found by the rule `edges` (camber_edges.hpp).
#include <fstream>
#include <set>

#include <BRepCheck_Analyzer.hxx>
#include <TopExp_Explorer.hxx>

#include "acceptance/product_build.hpp"
#include "acceptance/readers.hpp"
#include "brep/step_read_back.hpp"
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
  cfg["output"]["formats"] = {"step"};
  std::ofstream(dir.path / "imported.json") << cfg.dump();
  const Run run = run_cli("build " + q(dir.path / "imported.json") + " -o " + q(dir.path / "out") + " -q", dir.path);
  BOOST_TEST_REQUIRE(run.exit_code == 0, run.err);
  const auto report = nlohmann::json::parse(read_text(dir.path / "out" / "report.json"));
  // The part as OCCT's STEP reader gets it: valid solids without free edges, the original's feature
  // names on the faces, and the original's volume within the import's tolerance times its surface (the
  // most a wall within blade.import.tolerance of the original can change it).
  const StepReadBack step = read_step_back(dir.path / "out" / "blade.step");
  BOOST_TEST_REQUIRE(step.ok);
  double volume_sum = 0, original_sum = 0;
  for (const TopoDS_Shape& shape : step.free_shapes)
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
      BOOST_TEST(BRepCheck_Analyzer(e.Current()).IsValid(), tag);
      BOOST_TEST(free_edges(e.Current()) == 0, tag);
      volume_sum += volume(e.Current());
    }
  for (const double v : built.volumes) original_sum += v;
  const double tolerance = report.at("model").at("import").at("tolerance_mm").get<double>();
  BOOST_TEST_MESSAGE(tag << ": imported part " << volume_sum << " mm^3, original " << original_sum << " mm^3");
  BOOST_TEST(std::abs(volume_sum - original_sum) <= tolerance * built.area, tag << ": " << volume_sum << " vs " << original_sum);
  const std::set<std::string> imported(step.face_names.begin(), step.face_names.end()),
      original(built.face_names.begin(), built.face_names.end());
  BOOST_TEST(imported == original, tag << ": feature names of the imported blade's part equal the original's");
  BOOST_TEST(report.at("model").at("import").at("format").get<std::string>() == tag);
  BOOST_TEST(report.at("model").at("import").at("deviation").at("max_mm").get<double>() <= 0.01);
}


}  // namespace cg::test
