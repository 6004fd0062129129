#pragma once
// One run of the product for the acceptance tests: `coolinggen build [CONFIG] -o DIR` as a user runs it
// (the CLI binary, every output format of the config), built once per test program; the checks then
// read the files it wrote with readers that are not ours (acceptance/readers.hpp). What the part should
// be comes from the run's report.json and from blade.brep (OCCT's native format, written by
// BRepTools: the exact shapes, without names).
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>

#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "acceptance/readers.hpp"
#include "brep/temp_files.hpp"
#include "cli/run_cli.hpp"
#include "src/brep/named_shape.hpp"
#include "src/config/builtin_example.hpp"

namespace cg::test {

struct ProductBuild {
  std::filesystem::path dir;
  Run run;
  nlohmann::json report;
  std::vector<std::string> bodies;            ///< body names, in the order of blade.brep's solids
  std::vector<double> volumes;                ///< mm^3 per body, sorted (blade.brep)
  std::multiset<std::string> face_names;      ///< every face's feature name (report.json "bodies")
  std::map<std::string, int> faces_per_kind;  ///< feature kind -> faces
  int faces = 0;
  double area = 0;                            ///< mm^2, all bodies
  double stl_deflection = 0.01;               ///< mm, the config's output.stl_deflection
  std::string product;                        ///< the config's output.product_name (default: its name)
  std::string step_schema = "AP242";          ///< the config's output.step_schema

  const std::filesystem::path file(const std::string& name) const { return dir / name; }
};

/// Runs the build once per process into a directory that lives as long as the process.
/// `config`: a path below data/examples, or "" for the built-in example.
inline const ProductBuild& product_build(const std::string& config) {
  static std::map<std::string, ProductBuild> builds;
  static std::vector<std::unique_ptr<TempDir>> dirs;
  const auto found = builds.find(config);
  if (found != builds.end()) return found->second;
  dirs.push_back(std::make_unique<TempDir>("acceptance"));
  ProductBuild b;
  b.dir = dirs.back()->path / "out";
  const std::string source = config.empty() ? "" : q(std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples" / config) + " ";
  b.run = run_cli("build " + source + "-o " + q(b.dir) + " -q", dirs.back()->path);
  BOOST_TEST_REQUIRE(b.run.exit_code == 0, "coolinggen build " << config << ": " << b.run.err);
  b.report = nlohmann::json::parse(read_text(b.dir / "report.json"));
  const nlohmann::json cfg = nlohmann::json::parse(
      config.empty() ? std::string(config::builtin_example_json())
                     : read_text(std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples" / config));
  const nlohmann::json out = cfg.value("output", nlohmann::json::object());
  b.stl_deflection = out.value("stl_deflection", b.stl_deflection);
  b.product = out.value("product_name", cfg.at("name").get<std::string>());
  b.step_schema = out.value("step_schema", b.step_schema);
  for (const auto& body : b.report.at("bodies")) {
    b.bodies.push_back(body.at("name").get<std::string>());
    BOOST_TEST(body.at("valid").get<bool>(), b.bodies.back());
    for (const auto& [name, count] : body.at("faces").items())
      for (int k = 0; k < count.get<int>(); ++k) {
        b.face_names.insert(name);
        ++b.faces_per_kind[brep::feature_kind(name)];
        ++b.faces;
      }
    b.area += body.at("surface_area_mm2").get<double>();
  }
  TopoDS_Shape exact;
  BRep_Builder builder;
  BOOST_TEST_REQUIRE(BRepTools::Read(exact, (b.dir / "blade.brep").string().c_str(), builder));
  for (TopExp_Explorer e(exact, TopAbs_SOLID); e.More(); e.Next()) b.volumes.push_back(volume(e.Current()));
  std::sort(b.volumes.begin(), b.volumes.end());
  BOOST_TEST_REQUIRE(count_shapes(exact, TopAbs_FACE) == b.faces, "blade.brep has the report's faces");
  BOOST_TEST_REQUIRE(b.volumes.size() == b.bodies.size(), "blade.brep has a solid per body");
  return builds.emplace(config, std::move(b)).first->second;
}

}  // namespace cg::test
