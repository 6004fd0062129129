// gmsh meshes of cooled test parts (made in the test: tests/export/cooled_part.hpp): the built-in
// example rotor blade with two chambers, film holes and an insert, and the C3X vane. Checked from the
// nodes and elements gmsh returns (src/mesh/mesh_quality.hpp, independent of gmsh's own measures):
//  - zero inverted tetrahedra in every region, positive minimum radius ratio;
//  - the coolant B-rep volume equals removed volume minus insert volume to 1e-6 relative (both are
//    BRepGProp integrals at 1e-7 accuracy), and the coolant mesh volume to 0.5 % (the bound:
//    chordal error of the tetrahedral faces on curved walls);
//  - each metal region's mesh volume within 0.5 % of its B-rep volume;
//  - physical groups named per region and per feature kind in mesh.msh; .vtu files written.
#define BOOST_TEST_MODULE blade_mesh
#include <boost/test/unit_test.hpp>

#include <set>

#include "brep/temp_files.hpp"
#include "export/cooled_part.hpp"
#include "src/mesh/blade_mesher.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

void check_mesh(const test::CooledPart& p, const char* tag, const mesh::MeshOptions& o) {
  test::TempDir dir(std::string("mesh_") + tag);
  const mesh::MeshResult r = mesh::mesh_blade(p.part, p.uncooled, p.uncooled_faces, mesh::directory_writer(dir.path), o);
  BOOST_TEST_MESSAGE(tag << ": " << r.to_json().dump());
  BOOST_TEST(r.inverted == 0u);
  BOOST_TEST(r.min_quality > 0.0);
  BOOST_TEST_REQUIRE(r.regions.size() == p.part.size() + 1);
  double inserts = 0;
  for (std::size_t b = 1; b < p.part.size(); ++b) inserts += test::volume_of(p.part[b].geometry.shape);
  const double expected = p.removed_volume - inserts;
  BOOST_TEST(std::abs(r.coolant_brep_volume - expected) <= 1e-6 * expected, r.coolant_brep_volume << " vs " << expected);
  BOOST_TEST(std::abs(r.coolant_mesh_volume - expected) <= 5e-3 * expected, r.coolant_mesh_volume << " vs " << expected);
  for (const auto& reg : r.regions) {
    BOOST_TEST(reg.tets.elements > 0u, reg.name);
    BOOST_TEST(reg.tets.inverted == 0u, reg.name);
    BOOST_TEST(std::abs(reg.tets.volume - reg.brep_volume) <= 5e-3 * reg.brep_volume, reg.name << " " << reg.tets.volume << " vs " << reg.brep_volume);
  }
  std::set<std::string> groups;
  for (const auto& g : r.surfaces) groups.insert(g.name);
  for (const char* g : {"blade_wall", "hub", "casing", "chamber", "film_row", "insert", "coolant_opening_hub",
                        "coolant_opening_blade_wall"})
    BOOST_TEST(groups.count(g) == 1u, g);
  const std::string msh = test::read_text(dir.path / "mesh.msh");
  for (const char* n : {"\"blade\"", "\"coolant\"", "\"insert_1\"", "\"chamber\"", "\"film_row\""})
    BOOST_TEST(msh.find(n) != std::string::npos, n);
  for (const char* f : {"mesh.msh", "mesh_blade.vtu", "mesh_insert_1.vtu", "mesh_coolant.vtu", "mesh_surfaces.vtu"})
    BOOST_TEST(fs::file_size(dir.path / f) > 100u, f);
}

}  // namespace

BOOST_AUTO_TEST_CASE(example_blade_metal_and_coolant) {
  test::CooledPartOptions o;
  o.holes = 4;
  o.chamber_top = 0.5;  // shorter chambers: a cheaper test, the same features
  mesh::MeshOptions m;
  m.max_size = 2.0;
  check_mesh(test::cooled_example(o), "example", m);
}

BOOST_AUTO_TEST_CASE(c3x_vane_metal_and_coolant) {
  test::CooledPartOptions o;
  o.holes = 3;
  o.chamber_top = 0.35;  // the C3X chambers are wide: keep them short for a cheap test
  mesh::MeshOptions m;
  m.max_size = 6.0;

  check_mesh(test::cooled_c3x(o), "c3x", m);
}

BOOST_AUTO_TEST_CASE(bad_options_are_refused) {
  const test::CooledPart p = test::cooled_example({0, 0, false, 0.3, 0.85});
  mesh::MeshOptions m;
  m.min_size = 3;
  m.max_size = 1;
  test::TempDir dir("mesh_bad");
  BOOST_CHECK_THROW(mesh::mesh_blade(p.part, p.uncooled, {}, mesh::directory_writer(dir.path), m), mesh::MeshError);
  BOOST_TEST(dir.entries().empty());
}
