// The hand-off formats through the pipeline (src/pipeline write_outputs) on a cooled build result (the
// example blade with chambers, film holes and an insert, made in the test): every selected file and
// only those, each non-empty; report.json lists them and carries the passage table; report.md is
// rendered from the same report; a selection writes only its files; write_mesh writes the mesh files
// and the "mesh" statistics. CG_KEEP_OUTPUTS=DIR keeps the full run's files in DIR for inspection.
#define BOOST_TEST_MODULE handoff_outputs
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "brep/temp_files.hpp"
#include "export/cooled_part.hpp"
#include "export/glb_file.hpp"
#include "src/config/builtin_example.hpp"
#include "src/pipeline/mesh_job.hpp"
#include "src/pipeline/outputs.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

// A build result of the cooled example, as the pipeline will produce once features are applied.
pipeline::BuildResult cooled_result(const test::CooledPart& p) {
  pipeline::BuildResult r;
  r.model = p.model;
  r.part = p.part;
  r.uncooled = {p.uncooled, p.uncooled_faces};
  for (const auto& b : r.part) r.checks.push_back(brep::verify_solid(b.geometry.shape));
  return r;
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> n;
  for (const auto& e : fs::directory_iterator(dir)) n.insert(e.path().filename().string());
  return n;
}

// blade.glb: glTF 2.0 binary, one primitive per face of every body, positions in metres with Y up
// (glTF's axes: x, z, -y of the part's millimetres), within the viewing deflection of the part's
// bounding box (OCCT's), one material per feature kind, not metallic.
void check_glb(const fs::path& file, const brep::Part& part) {
  const test::GlbFile g = test::read_glb(file);
  BOOST_TEST(g.version == 2u);
  BOOST_TEST(g.length == fs::file_size(file));
  BOOST_TEST(g.bin_bytes > 0u);
  std::size_t faces = 0;
  Bnd_Box box;
  for (const auto& b : part) {
    faces += b.geometry.faces.size();
    BRepBndLib::AddOptimal(b.geometry.shape, box, false, false);
  }
  const nlohmann::json& j = g.gltf;
  BOOST_TEST_REQUIRE(j.at("meshes").size() == 1u);
  const nlohmann::json& prims = j.at("meshes").at(0).at("primitives");
  BOOST_TEST(prims.size() == faces);
  for (const auto& n : j.at("nodes")) BOOST_TEST((!n.contains("matrix") && !n.contains("scale")), n.dump());
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const auto& p : prims) {
    const nlohmann::json& a = j.at("accessors").at(p.at("attributes").at("POSITION").get<int>());
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], a.at("min").at(k).get<double>());
      hi[k] = std::max(hi[k], a.at("max").at(k).get<double>());
    }
  }
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double tol = 1e-4;  // m: 0.1 mm, above the viewing deflection of this part
  BOOST_TEST(std::abs(lo[0] - x0 / 1000) < tol);
  BOOST_TEST(std::abs(hi[0] - x1 / 1000) < tol);
  BOOST_TEST(std::abs(lo[1] - z0 / 1000) < tol);  // Y up: the part's z
  BOOST_TEST(std::abs(hi[1] - z1 / 1000) < tol);
  BOOST_TEST(std::abs(lo[2] + y1 / 1000) < tol);  // glTF z = -y
  BOOST_TEST(std::abs(hi[2] + y0 / 1000) < tol);
  std::set<std::string> kinds;
  for (const auto& b : part)
    for (const auto& f : b.geometry.faces) kinds.insert(brep::feature_kind(f.name));
  BOOST_TEST(j.at("materials").size() == kinds.size());
  for (const auto& m : j.at("materials")) BOOST_TEST(m.at("pbrMetallicRoughness").at("metallicFactor").get<double>() == 0.0);
}

}  // namespace

// Every format of the one list (src/config/output_format.hpp) has one writer, in the list's order.
BOOST_AUTO_TEST_CASE(every_format_has_a_writer) {
  const std::vector<pipeline::OutputWriter>& w = pipeline::output_writers();
  BOOST_TEST_REQUIRE(w.size() == std::size(config::kOutputFormats));
  for (std::size_t i = 0; i < w.size(); ++i) {
    BOOST_TEST(config::output_format_name(w[i].format) == config::kOutputFormats[i].name);
    BOOST_TEST(!w[i].files.empty(), config::kOutputFormats[i].name);
  }
}

BOOST_AUTO_TEST_CASE(all_and_selected_outputs) {
  test::CooledPartOptions o;
  o.holes = 3;
  const test::CooledPart p = test::cooled_example(o);
  const pipeline::BuildResult r = cooled_result(p);
  BOOST_TEST_REQUIRE(r.valid(), r.failed_checks());
  config::Config c = config::builtin_example_config();
  c.output.product_name = "hpt_rotor_cooled";
  // The fixture part has no passage report to make a coolant network of: the network is checked on the
  // product's own build (tests/acceptance, network_checks.hpp).
  auto& f = c.output.formats;
  f.erase(std::remove(f.begin(), f.end(), config::OutputFormat::Network), f.end());
  test::TempDir dir("handoff");
  const char* keep = std::getenv("CG_KEEP_OUTPUTS");
  const fs::path out = keep ? fs::path(keep) : dir.path / "out";
  const pipeline::WrittenOutputs w = pipeline::write_outputs(c, r, out);
  std::set<std::string> expected{"blade.step",         "blade.igs",    "blade.brep", "blade.stl",  "blade.vtm", "blade_blade.vtp",
                                 "blade_insert_1.vtp", "sections.svg", "blade.glb",  "report.html", "report.md", "report.json"};
  const std::set<std::string> written(w.files.begin(), w.files.end());
  if (written.count("preview.png")) expected.insert("preview.png");
  BOOST_TEST(written == expected);
  BOOST_TEST(names_in(out) == expected);  // nothing else, no temporaries
  for (const auto& f : w.files) BOOST_TEST(fs::file_size(out / f) > 100u, f);
  const auto report = nlohmann::json::parse(test::read_text(out / "report.json"));
  BOOST_TEST(report.at("valid").get<bool>());
  BOOST_TEST(report.at("sections").size() == c.output.section_spans.size());
  BOOST_TEST(report.at("sections").at(1).at("passages").size() == 2u);  // both chambers at span 0.3
  if (!written.count("preview.png")) BOOST_TEST(report.at("notes").at(0).get<std::string>().find("preview.png skipped") == 0u);
  const std::string md = test::read_text(out / "report.md");
  for (const char* s : {"## Checks", "## Coolant passages along span", "chamber_1_wall", "`blade.igs`", "## Solid"})
    BOOST_TEST(md.find(s) != std::string::npos, s);

  check_glb(out / "blade.glb", r.part);

  // Only STL and BREP (plus report.json).
  c.output.formats = {config::OutputFormat::Stl, config::OutputFormat::Brep};
  const pipeline::WrittenOutputs w2 = pipeline::write_outputs(c, r, dir.path / "sel");
  BOOST_TEST(names_in(dir.path / "sel") == (std::set<std::string>{"blade.stl", "blade.brep", "report.json"}));
  BOOST_TEST(w2.files.size() == 3u);
}

BOOST_AUTO_TEST_CASE(mesh_job_writes_mesh_and_report) {
  test::CooledPartOptions o;
  o.chambers = 1;
  o.holes = 1;
  o.insert = false;
  o.chamber_top = 0.4;
  const test::CooledPart p = test::cooled_example(o);
  const pipeline::BuildResult r = cooled_result(p);
  config::Config c = config::builtin_example_config();
  c.mesh.max_size = 4;
  c.mesh.feature_curvature_elements = 16;
  test::TempDir dir("meshjob");
  const pipeline::MeshOutputs w = pipeline::write_mesh(c, r, dir.path / "m");
  BOOST_TEST(names_in(dir.path / "m") == (std::set<std::string>{"mesh.msh", "mesh_blade.vtu", "mesh_coolant.vtu",
                                                                 "mesh_surfaces.vtu", "report.md", "report.json"}));
  const auto report = nlohmann::json::parse(test::read_text(dir.path / "m" / "report.json"));
  BOOST_TEST(report.at("mesh").at("inverted").get<int>() == 0);
  BOOST_TEST(report.at("mesh").at("tetrahedra").get<int>() > 0);
  BOOST_TEST(test::read_text(dir.path / "m" / "report.md").find("## Mesh") != std::string::npos);
}
