// gmsh meshes of blades built by the features (pipeline::run_build): a light variant of the built-in
// example (LE chamber, 3-pass serpentine with filleted ribs and turnarounds, turbulators, pressure-side
// TE slots with one pin row, a shaped and a cylindrical film row and the showerhead over 10 % of the
// span) meshed through pipeline::write_mesh as `coolinggen mesh` does, and a light variant of the C3X
// film vane (its impingement insert is a second metal body) through mesh::mesh_blade. Coarser sizes than
// the defaults keep each case near 30 s (bench_export_mesh meshes the full example with the defaults).
// Checked:
//  - zero inverted tetrahedra in every region, positive minimum radius ratio (src/mesh/mesh_quality.hpp,
//    from the nodes, independent of gmsh's measures);
//  - the interfaces are conformal: every triangle of a face between two regions is a face of a
//    tetrahedron on both sides;
//  - the coolant B-rep volume equals removed minus insert volume (both from BRepGProp here, not the
//    mesher's integrals) to 1e-6 relative (two integrals at 1e-7), the coolant mesh volume to 0.5 %
//    (the bound: chordal error of the tetrahedral faces on curved walls), each metal region's
//    mesh volume its B-rep volume to 0.5 %;
//  - mesh.msh read back with meshio (tests/mesh/read_msh.py, Debian python3-meshio: not our code and
//    not gmsh's): the same physical names, nodes, tetrahedra per region, triangles per surface group and
//    region volumes (1e-9: the same nodes summed in another order), no inverted tetrahedron, every
//    boundary triangle a face of some tetrahedron and the triangles between two regions the mesher's
//    interface triangles;
//  - gmsh's elementary entities named: volumes after their region, surfaces after their face (read from
//    the live gmsh model while mesh.msh is written);
//  - the .vtu files written; out-of-range options refused before any file is written.
#define BOOST_TEST_MODULE blade_mesh
#include <boost/test/unit_test.hpp>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <gmsh.h>

#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "brep/temp_files.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/mesh/blade_mesher.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/mesh_job.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;

namespace {

struct Built {
  config::Config config;
  pipeline::BuildResult build;
};

// A config of data/examples edited (file "" = the built-in example), built once per process.
const Built& built(const std::string& file, const std::function<void(json&)>& edit) {
  static std::map<std::string, std::unique_ptr<Built>> cache;
  auto& slot = cache[file];
  if (!slot) {
    json doc = json::parse(file.empty() ? std::string(config::builtin_example_json())
                                        : test::read_text(COOLINGGEN_SOURCE_DIR "/data/examples/" + file));
    edit(doc);
    slot = std::make_unique<Built>();
    slot->config = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", file.empty() ? "hpt_rotor" : file);
    slot->build = pipeline::run_build(slot->config);
    BOOST_TEST_REQUIRE(slot->build.valid(), slot->build.failed_checks());
  }
  return *slot;
}

// Sizes for a test: about half a million tetrahedra instead of the defaults' millions.
json light_mesh(double max_size) {
  return {{"max_size", max_size}, {"min_size", 0.1}, {"curvature_elements", 12}, {"feature_curvature_elements", 24}, {"size_growth", 0.5}};
}

const Built& rotor() {
  return built("", [](json& d) {
    auto& c = d["cooling"];
    c["film_rows"] = json::array({c["film_rows"][0], c["film_rows"][1]});  // the shaped row and a cylindrical one
    for (auto& r : c["film_rows"]) r["span_start"] = 0.5, r["span_end"] = 0.6;
    c["showerhead"]["span_start"] = 0.5;
    c["showerhead"]["span_end"] = 0.6;
    c["core"]["trailing_edge"]["pitch"] = 8.0;
    c["core"]["trailing_edge"]["pin_fins"]["spanwise_pitch"] = 8.0;
    c["core"]["trailing_edge"]["pin_fins"]["rows"] = 1;
    for (auto& t : c["core"]["turbulators"]) t["pitch"] = 10.0;
    d["mesh"] = light_mesh(3.0);
  });
}

const Built& c3x() {
  return built("c3x_film_vane.json", [](json& d) {
    auto& c = d["cooling"];
    for (auto& r : c["film_rows"]) r["span_start"] = 0.45, r["span_end"] = 0.55;
    c["showerhead"]["rows"] = 2;
    c["showerhead"]["span_start"] = 0.45;
    c["showerhead"]["span_end"] = 0.55;
    c["inserts"][0]["jets"]["spacing_x_d"] = 20;
    c["inserts"][0]["jets"]["spacing_y_d"] = 20;
    d["mesh"] = light_mesh(8.0);
    d["mesh"]["min_size"] = 0.15;
  });
}

double occt_volume(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::VolumeProperties(s, g, 1e-7, /*OnlyClosed=*/true);
  return g.Mass();
}

// A python3 that imports meshio and numpy: the one on PATH, else Debian's.
std::string meshio_python() {
  for (const char* py : {"python3", "/usr/bin/python3"})
    if (std::system((std::string(py) + " -c 'import meshio, numpy' > /dev/null 2>&1").c_str()) == 0) return py;
  return "";
}

// mesh.msh as meshio reads it (read_msh.py); fails the test when it cannot be read.
json read_back(const fs::path& msh) {
  const std::string py = meshio_python();
  BOOST_TEST_REQUIRE(!py.empty(), "no python3 with meshio and numpy (Debian python3-meshio, scripts/install-deps.sh)");
  const fs::path out = msh.parent_path() / "read_back.json";
  const std::string cmd = py + " '" COOLINGGEN_SOURCE_DIR "/tests/mesh/read_msh.py' '" + msh.string() + "' '" + out.string() + "'";
  BOOST_TEST_REQUIRE(std::system(cmd.c_str()) == 0, cmd);
  return json::parse(test::read_text(out));
}

void check_mesh(const mesh::MeshResult& r, const pipeline::BuildResult& b, const fs::path& dir,
                const std::vector<std::string>& kinds) {
  BOOST_TEST(r.inverted == 0u);
  BOOST_TEST(r.min_quality > 0.0);
  BOOST_TEST(r.interface_triangles > 0u);
  BOOST_TEST(r.nonconformal_triangles == 0u);
  BOOST_TEST_REQUIRE(r.regions.size() == b.part.size() + 1);
  double inserts = 0;
  for (std::size_t k = 1; k < b.part.size(); ++k) inserts += occt_volume(b.part[k].geometry.shape);
  const double expected = occt_volume(b.uncooled.shape) - occt_volume(b.part[0].geometry.shape) - inserts;
  BOOST_TEST(std::abs(r.coolant_brep_volume - expected) <= 1e-6 * expected, r.coolant_brep_volume << " vs " << expected);
  BOOST_TEST(std::abs(r.coolant_mesh_volume - expected) <= 5e-3 * expected, r.coolant_mesh_volume << " vs " << expected);
  for (std::size_t k = 0; k < r.regions.size(); ++k) {
    const auto& reg = r.regions[k];
    BOOST_TEST(reg.name == (k < b.part.size() ? b.part[k].name : std::string("coolant")));
    BOOST_TEST(reg.tets.elements > 0u, reg.name);
    BOOST_TEST(reg.tets.inverted == 0u, reg.name);
    BOOST_TEST(std::abs(reg.tets.volume - reg.brep_volume) <= 5e-3 * reg.brep_volume, reg.name << " " << reg.tets.volume << " vs " << reg.brep_volume);
  }
  std::set<std::string> groups;
  for (const auto& g : r.surfaces) groups.insert(g.name);
  for (const std::string& k : kinds) BOOST_TEST(groups.count(k) == 1u, k);

  const json f = read_back(dir / "mesh.msh");
  BOOST_TEST(f.at("nodes").get<std::size_t>() == r.nodes);
  BOOST_TEST(f.at("inverted").get<std::size_t>() == 0u);
  BOOST_TEST(f.at("triangles_in_no_region").get<std::size_t>() == 0u);
  BOOST_TEST(f.at("triangles_between_regions").get<std::size_t>() == r.interface_triangles);
  std::set<std::string> names;
  for (const auto& reg : r.regions) {
    names.insert(reg.name);
    BOOST_TEST(f.at("physical_names").value(reg.name, 0) == 3, reg.name);
    BOOST_TEST(f.at("tetrahedra").value(reg.name, std::size_t{0}) == reg.tets.elements, reg.name);
    BOOST_TEST(std::abs(f.at("volume").value(reg.name, 0.0) - reg.tets.volume) <= 1e-9 * reg.tets.volume, reg.name);
  }
  for (const auto& g : r.surfaces) {
    names.insert(g.name);
    BOOST_TEST(f.at("physical_names").value(g.name, 0) == 2, g.name);
    BOOST_TEST(f.at("triangles").value(g.name, std::size_t{0}) == g.triangles, g.name);
  }
  BOOST_TEST(f.at("physical_names").size() == names.size());
  for (const std::string& file : r.files) BOOST_TEST(fs::file_size(dir / file) > 100u, file);
  BOOST_TEST(r.files.size() == b.part.size() + 3);  // mesh.msh, a .vtu per region, mesh_surfaces.vtu
}

}  // namespace

BOOST_AUTO_TEST_CASE(rotor_through_the_pipeline) {
  const Built& b = rotor();
  test::TempDir dir("mesh_rotor");
  const pipeline::MeshOutputs out = pipeline::write_mesh(b.config, b.build, dir.path);
  BOOST_TEST_MESSAGE("rotor: " << out.mesh.to_json().dump());
  check_mesh(out.mesh, b.build, dir.path,
             {"blade_wall", "hub", "casing", "tip_cap", "hub_floor", "chamber", "rib", "turnaround", "turbulator", "te_slot",
              "pin_fin", "inlet", "film_row", "showerhead", "coolant_opening_hub", "coolant_opening_blade_wall"});
  const json report = json::parse(test::read_text(dir.path / "report.json"));
  BOOST_TEST(report.at("mesh").at("nonconformal_interface_triangles").get<std::size_t>() == 0u);
}

BOOST_AUTO_TEST_CASE(c3x_film_vane_with_insert) {
  const Built& b = c3x();
  test::TempDir dir("mesh_c3x");
  // While gmsh writes mesh.msh its model is live: read the names of its elementary entities.
  std::map<std::pair<int, int>, std::string> entity_names;
  const mesh::FileWriter plain = mesh::directory_writer(dir.path);
  const mesh::FileWriter files = [&](const std::string& name, const std::function<void(const fs::path&)>& writer) {
    if (name == "mesh.msh") {
      gmsh::vectorpair entities;
      gmsh::model::getEntities(entities);
      for (const auto& [dim, tag] : entities) {
        std::string n;
        gmsh::model::getEntityName(dim, tag, n);
        if (dim >= 2) entity_names[{dim, tag}] = n;
      }
    }
    plain(name, writer);
  };
  const mesh::MeshResult r = mesh::mesh_blade(b.build.part, b.build.uncooled.shape, b.build.uncooled.faces, files,
                                              pipeline::mesh_options(b.config.mesh));
  BOOST_TEST_MESSAGE("c3x: " << r.to_json().dump());
  check_mesh(r, b.build, dir.path,
             {"blade_wall", "hub", "casing", "tip_cap", "hub_floor", "chamber", "rib", "inlet", "film_row", "showerhead",
              "insert", "coolant_opening_hub", "coolant_opening_blade_wall"});
  std::set<std::string> regions, kinds;
  for (const auto& reg : r.regions) regions.insert(reg.name);
  for (const auto& g : r.surfaces) kinds.insert(g.name);
  std::size_t surfaces = 0;
  for (const auto& [dt, name] : entity_names) {
    if (dt.first == 3) BOOST_TEST(regions.count(name) == 1u, "volume " << dt.second << " named '" << name << "'");
    if (dt.first == 2) {
      ++surfaces;
      BOOST_TEST(kinds.count(brep::feature_kind(name)) == 1u, "surface " << dt.second << " named '" << name << "'");
    }
  }
  std::size_t faces = 0;
  for (const auto& g : r.surfaces) faces += static_cast<std::size_t>(g.faces);
  BOOST_TEST(surfaces == faces);
}

BOOST_AUTO_TEST_CASE(bad_options_are_refused) {
  const Built& b = rotor();
  test::TempDir dir("mesh_bad");
  mesh::MeshOptions m;
  m.min_size = 3;
  m.max_size = 1;
  BOOST_CHECK_THROW(mesh::mesh_blade(b.build.part, b.build.uncooled.shape, {}, mesh::directory_writer(dir.path), m), mesh::MeshError);
  m = {};
  m.size_growth = 0;
  BOOST_CHECK_THROW(mesh::mesh_blade(b.build.part, b.build.uncooled.shape, {}, mesh::directory_writer(dir.path), m), mesh::MeshError);
  BOOST_TEST(dir.entries().empty());
}
