// mesh.cgns (src/mesh/mesh_cgns.hpp) of a light cooled blade built and meshed by the pipeline (the
// built-in example's mid-span section as a 12 mm straight blade with a two-chamber core, one filleted
// rib, hub inlets and a row of two film holes, coarse sizes; pipeline::run_build + write_mesh with
// "formats": ["msh", "vtu", "cgns"]) and of the cooled example blade with a tube insert (three zones,
// two interfaces of the coolant). Read back with the CGNS library's reading calls (cgnslib.h, none of
// our writer's code), with VTK's CGNS reader (the one ParaView uses) and checked by the CGNS tools'
// cgnscheck:
//  - one zone per region with the region's tetrahedron count; node counts, signed volumes all > 0
//    and their sum equal to the mesher's region volume (1e-9 relative: the same doubles summed in
//    another order);
//  - every TRI_3 section is a BC of the same name (FamilySpecified, PointRange = its element range,
//    FaceCenter) naming a family of the base; each triangle is a face of one of its zone's
//    tetrahedra with the normal pointing away from it, and the boundary of each zone is closed:
//    sum over its triangles of a . (b x c) / 6 equals the zone's volume (1e-9 relative, rounding of
//    ~1e4 terms of ~1e3 mm^3 each);
//  - per surface group, the triangles in CGNS (interface triangles counted half on each side) equal
//    the mesher's group counts; families named by feature kind and the interface family are there,
//    openings BCTypeUserDefined, walls BCWall;
//  - the interface: the same triangles (by node coordinates, exactly) on both sides, and a vertex
//    connectivity on both sides whose point pairs have identical coordinates;
//  - cgnscheck (warning level 3) reports no warning and no error.
// A hand-made two-tetrahedron mesh checks the name limit (MeshError, no file left).
#define BOOST_TEST_MODULE mesh_cgns
#include <boost/test/unit_test.hpp>

#include <cgnslib.h>
#include <vtkCGNSReader.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "brep/temp_files.hpp"
#include "export/cooled_part.hpp"
#include "support/short_blade.hpp"
#include "src/config/config.hpp"
#include "src/mesh/mesh_cgns.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/mesh_job.hpp"

using namespace cg;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json light_blade() {
  json d = test::short_example_blade("cgns_light", 12);
  d["cooling"] = json::parse(R"({
    "film_rows": [{"diameter": 0.4, "chord": -0.45, "count": 2, "inclination_deg": 35, "span_start": 0.35,
                   "span_end": 0.65, "chamber": 2}]
  })");
  d["cooling"]["core"] = test::two_chamber_core();
  d.erase("coolant");  // its per-row sinks name the example's rows; this mesh needs no network
  // Coarse: ~25k tetrahedra in ~10 s (the features' own refinement off).
  d["mesh"] = {{"max_size", 3.0}, {"min_size", 0.3}, {"curvature_elements", 8}, {"feature_curvature_elements", 0},
               {"formats", {"msh", "vtu", "cgns"}}};
  return d;
}

// ---- mesh.cgns as the CGNS library reads it ----

struct Patch {
  std::string name, family, interface_family;  // interface_family: AdditionalFamilyName "Interface"
  cgsize_t first = 0, last = 0;
  std::vector<std::array<cgsize_t, 3>> triangles;  // 1-based zone nodes
};
struct Connection {
  std::string name, donor;
  std::vector<cgsize_t> points, donor_points;
};
struct Zone {
  std::string name;
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<cgsize_t, 4>> tets;
  std::vector<Patch> patches;
  std::vector<Connection> connections;
  int bcs = 0;
};
struct CgnsMesh {
  int cell_dim = 0, phys_dim = 0;
  CGNS_ENUMT(LengthUnits_t) length = CGNS_ENUMV(LengthUnitsNull);
  std::map<std::string, CGNS_ENUMT(BCType_t)> families;
  std::vector<Zone> zones;
};

#define CG(call) BOOST_REQUIRE_MESSAGE((call) == CG_OK, #call << ": " << cg_get_error())

void read_patches(int fn, int B, int Z, Zone& z) {
  int nsections = 0;
  CG(cg_nsections(fn, B, Z, &nsections));
  for (int S = 1; S <= nsections; ++S) {
    char name[33];
    CGNS_ENUMT(ElementType_t) type;
    cgsize_t first = 0, last = 0, size = 0;
    int nbndry = 0, parent = 0;
    CG(cg_section_read(fn, B, Z, S, name, &type, &first, &last, &nbndry, &parent));
    CG(cg_ElementDataSize(fn, B, Z, S, &size));
    std::vector<cgsize_t> conn(static_cast<std::size_t>(size));
    CG(cg_elements_read(fn, B, Z, S, conn.data(), nullptr));
    if (type == CGNS_ENUMV(TETRA_4)) {
      BOOST_TEST(first == 1);
      for (std::size_t i = 0; i + 3 < conn.size(); i += 4) z.tets.push_back({conn[i], conn[i + 1], conn[i + 2], conn[i + 3]});
      BOOST_TEST(z.tets.size() == static_cast<std::size_t>(last - first + 1));
      continue;
    }
    BOOST_TEST_REQUIRE(type == CGNS_ENUMV(TRI_3), z.name << " section " << name << " type " << type);
    Patch p{name, "", "", first, last, {}};
    for (std::size_t i = 0; i + 2 < conn.size(); i += 3) p.triangles.push_back({conn[i], conn[i + 1], conn[i + 2]});
    BOOST_TEST(p.triangles.size() == static_cast<std::size_t>(last - first + 1), name);
    z.patches.push_back(p);
  }
}

void read_bcs(int fn, int B, int Z, Zone& z) {
  CG(cg_nbocos(fn, B, Z, &z.bcs));
  for (int BC = 1; BC <= z.bcs; ++BC) {
    char name[33], family[33];
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) ptset;
    CGNS_ENUMT(DataType_t) normal_type;
    CGNS_ENUMT(GridLocation_t) location;
    cgsize_t npnts = 0, normal_size = 0;
    int normal_index[3], ndataset = 0;
    CG(cg_boco_info(fn, B, Z, BC, name, &type, &ptset, &npnts, normal_index, &normal_size, &normal_type, &ndataset));
    BOOST_TEST(type == CGNS_ENUMV(FamilySpecified), name);
    BOOST_TEST_REQUIRE(ptset == CGNS_ENUMV(PointRange), name);
    BOOST_TEST_REQUIRE(npnts == 2);
    cgsize_t range[2];
    CG(cg_boco_read(fn, B, Z, BC, range, nullptr));
    CG(cg_boco_gridlocation_read(fn, B, Z, BC, &location));
    BOOST_TEST(location == CGNS_ENUMV(FaceCenter), name);
    auto p = std::find_if(z.patches.begin(), z.patches.end(), [&](const Patch& q) { return q.name == name; });
    BOOST_TEST_REQUIRE((p != z.patches.end()), z.name << ": BC " << name << " has no section of its name");
    BOOST_TEST(range[0] == p->first, name);
    BOOST_TEST(range[1] == p->last, name);
    CG(cg_goto(fn, B, "Zone_t", Z, "ZoneBC_t", 1, "BC_t", BC, "end"));
    CG(cg_famname_read(family));
    p->family = family;
    int nmulti = 0;
    CG(cg_nmultifam(&nmulti));
    BOOST_TEST(nmulti <= 1);
    if (nmulti == 1) {
      char label[33];
      CG(cg_multifam_read(1, label, family));
      BOOST_TEST(std::string(label) == "Interface");
      p->interface_family = family;
    }
  }
}

void read_connections(int fn, int B, int Z, Zone& z) {
  int n = 0;
  CG(cg_nconns(fn, B, Z, &n));
  for (int I = 1; I <= n; ++I) {
    char name[33], donor[33];
    CGNS_ENUMT(GridLocation_t) location;
    CGNS_ENUMT(GridConnectivityType_t) type;
    CGNS_ENUMT(PointSetType_t) ptset, donor_ptset;
    CGNS_ENUMT(ZoneType_t) donor_zone;
    CGNS_ENUMT(DataType_t) donor_type;
    cgsize_t npnts = 0, ndonor = 0;
    CG(cg_conn_info(fn, B, Z, I, name, &location, &type, &ptset, &npnts, donor, &donor_zone, &donor_ptset, &donor_type, &ndonor));
    BOOST_TEST(location == CGNS_ENUMV(Vertex));
    BOOST_TEST(type == CGNS_ENUMV(Abutting1to1));
    BOOST_TEST(ptset == CGNS_ENUMV(PointList));
    BOOST_TEST(donor_ptset == CGNS_ENUMV(PointListDonor));
    BOOST_TEST(donor_zone == CGNS_ENUMV(Unstructured));
    BOOST_TEST_REQUIRE(npnts == ndonor);
    Connection c{name, donor, std::vector<cgsize_t>(static_cast<std::size_t>(npnts)), std::vector<cgsize_t>(static_cast<std::size_t>(npnts))};
    CG(cg_conn_read(fn, B, Z, I, c.points.data(), CGNS_ENUMV(Integer), c.donor_points.data()));
    z.connections.push_back(c);
  }
}

CgnsMesh read_cgns(const fs::path& file) {
  CgnsMesh m;
  int fn = 0, nbases = 0, nzones = 0, nfamilies = 0;
  CG(cg_open(file.c_str(), CG_MODE_READ, &fn));
  CG(cg_nbases(fn, &nbases));
  BOOST_TEST_REQUIRE(nbases == 1);
  char name[33];
  CG(cg_base_read(fn, 1, name, &m.cell_dim, &m.phys_dim));
  CG(cg_goto(fn, 1, "end"));
  CGNS_ENUMT(MassUnits_t) mass;
  CGNS_ENUMT(TimeUnits_t) time;
  CGNS_ENUMT(TemperatureUnits_t) temperature;
  CGNS_ENUMT(AngleUnits_t) angle;
  CG(cg_units_read(&mass, &m.length, &time, &temperature, &angle));
  CG(cg_nfamilies(fn, 1, &nfamilies));
  for (int F = 1; F <= nfamilies; ++F) {
    int nboco = 0, ngeo = 0;
    CG(cg_family_read(fn, 1, F, name, &nboco, &ngeo));
    BOOST_TEST_REQUIRE(nboco == 1, name);
    char bc_name[33];
    CGNS_ENUMT(BCType_t) type;
    CG(cg_fambc_read(fn, 1, F, 1, bc_name, &type));
    m.families[name] = type;
  }
  CG(cg_nzones(fn, 1, &nzones));
  for (int Z = 1; Z <= nzones; ++Z) {
    Zone z;
    cgsize_t size[3];
    CGNS_ENUMT(ZoneType_t) type;
    CG(cg_zone_read(fn, 1, Z, name, size));
    CG(cg_zone_type(fn, 1, Z, &type));
    BOOST_TEST(type == CGNS_ENUMV(Unstructured));
    z.name = name;
    z.nodes.resize(static_cast<std::size_t>(size[0]));
    std::vector<double> c(z.nodes.size());
    const cgsize_t lo = 1, hi = size[0];
    for (int k = 0; k < 3; ++k) {
      const char* axis[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
      CG(cg_coord_read(fn, 1, Z, axis[k], CGNS_ENUMV(RealDouble), &lo, &hi, c.data()));
      for (std::size_t i = 0; i < c.size(); ++i) z.nodes[i][k] = c[i];
    }
    read_patches(fn, 1, Z, z);
    BOOST_TEST(z.tets.size() == static_cast<std::size_t>(size[1]), z.name);
    read_bcs(fn, 1, Z, z);
    read_connections(fn, 1, Z, z);
    m.zones.push_back(std::move(z));
  }
  CG(cg_close(fn));
  return m;
}

double tet_volume(const Zone& z, const std::array<cgsize_t, 4>& t) {
  const Eigen::Vector3d& a = z.nodes[static_cast<std::size_t>(t[0] - 1)];
  return (z.nodes[static_cast<std::size_t>(t[1] - 1)] - a)
             .cross(z.nodes[static_cast<std::size_t>(t[2] - 1)] - a)
             .dot(z.nodes[static_cast<std::size_t>(t[3] - 1)] - a) /
         6;
}

const Zone& zone_named(const CgnsMesh& m, const std::string& name) {
  for (const Zone& z : m.zones)
    if (z.name == name) return z;
  BOOST_FAIL("no zone " << name);
  return m.zones.front();
}

// A triangle by its node coordinates, independent of node order: the sorted corner triples.
using CoordTriangle = std::array<std::array<double, 3>, 3>;
CoordTriangle by_coordinates(const Zone& z, const std::array<cgsize_t, 3>& t) {
  CoordTriangle c;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = z.nodes[static_cast<std::size_t>(t[static_cast<std::size_t>(i)] - 1)];
    c[static_cast<std::size_t>(i)] = {p.x(), p.y(), p.z()};
  }
  std::sort(c.begin(), c.end());
  return c;
}

// ---- the checks, on any mesh.cgns and the MeshResult of the same run ----

void check_zones(const CgnsMesh& cg, const mesh::MeshResult& m) {
  BOOST_TEST(cg.cell_dim == 3);
  BOOST_TEST(cg.phys_dim == 3);
  BOOST_TEST(cg.length == CGNS_ENUMV(Millimeter));
  BOOST_TEST_REQUIRE(cg.zones.size() == m.regions.size());
  std::size_t nodes = 0;
  for (std::size_t k = 0; k < m.regions.size(); ++k) {
    const Zone& z = zone_named(cg, m.regions[k].name);  // the library lists zones by name, not as written
    BOOST_TEST(z.tets.size() == m.regions[k].tets.elements, z.name);
    double volume = 0;
    std::size_t inverted = 0;
    std::vector<char> used(z.nodes.size(), 0);
    for (const auto& t : z.tets) {
      const double v = tet_volume(z, t);
      volume += v;
      inverted += v <= 0;
      for (cgsize_t n : t) {
        BOOST_TEST_REQUIRE((n >= 1 && n <= static_cast<cgsize_t>(z.nodes.size())));
        used[static_cast<std::size_t>(n - 1)] = 1;
      }
    }
    BOOST_TEST(inverted == 0u, z.name);
    BOOST_TEST(std::count(used.begin(), used.end(), 1) == static_cast<long>(z.nodes.size()), z.name << ": unused nodes");
    BOOST_TEST(std::abs(volume - m.regions[k].tets.volume) <= 1e-9 * volume, z.name << " " << volume << " vs " << m.regions[k].tets.volume);
    nodes += z.nodes.size();
    BOOST_TEST_MESSAGE(z.name << ": " << z.nodes.size() << " nodes, " << z.tets.size() << " tetrahedra, " << z.patches.size()
                              << " patches, " << z.connections.size() << " connections");
  }
  BOOST_TEST(nodes > m.nodes);  // interface nodes are stored once per side
}

void check_boundaries(const CgnsMesh& cg) {
  static constexpr int kFace[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  for (const Zone& z : cg.zones) {
    std::map<std::array<cgsize_t, 3>, cgsize_t> opposite;  // sorted face -> the tetrahedron's fourth node
    double volume = 0;
    for (const auto& t : z.tets) {
      volume += tet_volume(z, t);
      for (int f = 0; f < 4; ++f) {
        std::array<cgsize_t, 3> k{t[kFace[f][0]], t[kFace[f][1]], t[kFace[f][2]]};
        std::sort(k.begin(), k.end());
        opposite[k] = t[static_cast<std::size_t>(3 - f)];
      }
    }
    double enclosed = 0;
    std::size_t not_faces = 0, inward = 0;
    for (const Patch& p : z.patches)
      for (const auto& t : p.triangles) {
        std::array<cgsize_t, 3> k = t;
        std::sort(k.begin(), k.end());
        const auto it = opposite.find(k);
        if (it == opposite.end()) {
          ++not_faces;
          continue;
        }
        const Eigen::Vector3d& a = z.nodes[static_cast<std::size_t>(t[0] - 1)];
        const Eigen::Vector3d& b = z.nodes[static_cast<std::size_t>(t[1] - 1)];
        const Eigen::Vector3d& c = z.nodes[static_cast<std::size_t>(t[2] - 1)];
        inward += (b - a).cross(c - a).dot(z.nodes[static_cast<std::size_t>(it->second - 1)] - a) >= 0;
        enclosed += a.dot(b.cross(c)) / 6;
      }
    BOOST_TEST(not_faces == 0u, z.name);
    BOOST_TEST(inward == 0u, z.name);
    BOOST_TEST(std::abs(enclosed - volume) <= 1e-9 * volume, z.name << ": boundary encloses " << enclosed << ", tetrahedra " << volume);
  }
}

void check_families(const CgnsMesh& cg, const mesh::MeshResult& m, std::initializer_list<const char*> expected) {
  const auto& fam = cg.families;
  for (const char* f : expected) BOOST_TEST(fam.count(f) == 1u, f);
  for (const auto& [name, type] : fam) {
    const bool user = name.rfind("coolant_opening", 0) == 0 || name.rfind("interface_", 0) == 0;
    BOOST_TEST(type == (user ? CGNS_ENUMV(BCTypeUserDefined) : CGNS_ENUMV(BCWall)), name);
  }
  // Per group: outer triangles once, interface triangles once per side (2 * group count in total).
  std::map<std::string, std::size_t> twice;
  for (const Zone& z : cg.zones) {
    BOOST_TEST(static_cast<std::size_t>(z.bcs) == z.patches.size(), z.name);
    for (const Patch& p : z.patches) {
      BOOST_TEST(fam.count(p.family) == 1u, z.name << " " << p.name << " -> " << p.family);
      if (!p.interface_family.empty()) {
        BOOST_TEST(fam.count(p.interface_family) == 1u, p.interface_family);
        BOOST_TEST(p.interface_family.find(z.name) != std::string::npos, p.interface_family);
      }
      twice[p.family] += (p.interface_family.empty() ? 2 : 1) * p.triangles.size();
    }
  }
  for (const mesh::SurfaceGroup& g : m.surfaces) BOOST_TEST(twice[g.name] == 2 * g.triangles, g.name);
  BOOST_TEST(twice.size() == m.surfaces.size());
}

// Every connection: its donor lists the same interface (same triangles by coordinates, both sides), its
// points are the zone's nodes on that interface, and each point pair has identical coordinates.
void check_interfaces(const CgnsMesh& cg, std::size_t expected_connections) {
  auto triangles_of = [](const Zone& z, const std::string& family) {
    std::set<CoordTriangle> s;
    for (const Patch& p : z.patches)
      if (p.interface_family == family)
        for (const auto& t : p.triangles) s.insert(by_coordinates(z, t));
    return s;
  };
  std::size_t connections = 0;
  for (const Zone& z : cg.zones)
    for (const Connection& c : z.connections) {
      ++connections;
      const Zone& donor = zone_named(cg, c.donor);
      BOOST_TEST(c.name.find(z.name) != std::string::npos, c.name);
      BOOST_TEST(c.name.find(donor.name) != std::string::npos, c.name);
      const auto here = triangles_of(z, c.name), there = triangles_of(donor, c.name);
      BOOST_TEST(here.size() > 10u, c.name);
      BOOST_TEST((here == there), c.name << ": " << here.size() << " vs " << there.size() << " triangles");
      std::set<cgsize_t> listed(c.points.begin(), c.points.end()), on_patches;
      for (const Patch& p : z.patches)
        if (p.interface_family == c.name)
          for (const auto& t : p.triangles) on_patches.insert(t.begin(), t.end());
      BOOST_TEST((listed == on_patches), z.name << " " << c.name << ": " << listed.size() << " points, " << on_patches.size() << " on the interface");
      std::size_t moved = 0;
      for (std::size_t i = 0; i < c.points.size(); ++i)
        moved += z.nodes[static_cast<std::size_t>(c.points[i] - 1)] != donor.nodes[static_cast<std::size_t>(c.donor_points[i] - 1)];
      BOOST_TEST(moved == 0u, z.name << " " << c.name << ": point pairs with different coordinates");
    }
  BOOST_TEST(connections == expected_connections);
}

void check_with_cgnscheck(const fs::path& file) {
  const fs::path log = file.parent_path() / "cgnscheck.log";
  const std::string cmd = "cgnscheck -w3 '" + file.string() + "' > '" + log.string() + "' 2>&1";
  BOOST_TEST_REQUIRE(std::system(cmd.c_str()) == 0, "cgnscheck (Debian cgns-convert) failed or is missing: " << test::read_text(log));
  const std::string text = test::read_text(log);
  BOOST_TEST(text.find("checking complete") != std::string::npos, text);
  for (const char* bad : {"WARNING", "ERROR", " warnings", " errors"}) BOOST_TEST(text.find(bad) == std::string::npos, text);
}

// The reader ParaView uses: per zone a block "Internal" (the tetrahedra) and one per BC patch (compared
// as sorted (name, cells) lists: the reader's block order is its own).
void check_with_vtk(const fs::path& file, const CgnsMesh& cg) {
  vtkNew<vtkCGNSReader> reader;
  reader->SetFileName(file.c_str());
  reader->LoadBndPatchOn();
  reader->Update();
  std::vector<std::pair<std::string, vtkIdType>> blocks, expected;
  vtkNew<vtkDataObjectTreeIterator> it;
  it->SetDataSet(vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput()));
  it->VisitOnlyLeavesOn();
  it->TraverseSubTreeOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    const char* name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    blocks.emplace_back(name ? name : "", ds ? ds->GetNumberOfCells() : -1);
  }
  for (const Zone& z : cg.zones) {
    expected.emplace_back("Internal", static_cast<vtkIdType>(z.tets.size()));
    for (const Patch& p : z.patches) expected.emplace_back(p.name, static_cast<vtkIdType>(p.triangles.size()));
  }
  std::sort(blocks.begin(), blocks.end());
  std::sort(expected.begin(), expected.end());
  BOOST_TEST((blocks == expected), blocks.size() << " blocks read, " << expected.size() << " expected");
}

void check_all(const fs::path& file, const mesh::MeshResult& m, std::initializer_list<const char*> families,
               std::size_t connections) {
  BOOST_TEST_REQUIRE(std::count(m.files.begin(), m.files.end(), "mesh.cgns") == 1);
  BOOST_TEST_MESSAGE("mesh: " << m.to_json().dump());
  BOOST_TEST_MESSAGE("mesh.cgns: " << fs::file_size(file) << " bytes");
  const CgnsMesh cg = read_cgns(file);
  check_zones(cg, m);
  check_boundaries(cg);
  check_families(cg, m, families);
  check_interfaces(cg, connections);
  check_with_cgnscheck(file);
  check_with_vtk(file, cg);
}

}  // namespace

BOOST_AUTO_TEST_CASE(light_blade_built_by_the_pipeline) {
  test::TempDir dir("mesh_cgns");
  const config::Config c = config::parse_config(light_blade(), COOLINGGEN_SOURCE_DIR "/data/examples", "test");
  BOOST_TEST_REQUIRE(c.mesh.cgns);
  const pipeline::BuildResult b = pipeline::run_build(c);
  BOOST_TEST_REQUIRE(b.valid(), b.failed_checks());
  const pipeline::MeshOutputs out = pipeline::write_mesh(c, b, dir.path);
  BOOST_TEST_REQUIRE(out.mesh.regions.size() == 2u);  // blade, coolant
  check_all(dir.path / "mesh.cgns", out.mesh,
            {"blade_wall", "hub", "casing", "chamber", "rib", "film_row", "coolant_opening_hub", "coolant_opening_blade_wall",
             "interface_blade_coolant"},
            2);
}

BOOST_AUTO_TEST_CASE(example_blade_with_an_insert) {
  // Three zones, the coolant meeting the blade and the insert: the cooled example blade with the tube
  // insert of tests/export/cooled_part.hpp, meshed directly, mesh.cgns alone.
  test::CooledPartOptions o;
  o.holes = 2;
  o.chamber_top = 0.5;
  const test::CooledPart p = test::cooled_example(o);
  mesh::MeshOptions m;
  m.max_size = 3.0;
  m.min_size = 0.3;
  m.curvature_elements = 8;
  m.feature_curvature_elements = 0;
  m.write_msh = m.write_vtu = false;
  m.write_cgns = true;
  test::TempDir dir("mesh_cgns_insert");
  const mesh::MeshResult r = mesh::mesh_blade(p.part, p.uncooled, p.uncooled_faces, mesh::directory_writer(dir.path), m);
  BOOST_TEST_REQUIRE(r.regions.size() == 3u);  // blade, insert_1, coolant
  check_all(dir.path / "mesh.cgns", r, {"chamber", "film_row", "insert", "interface_blade_coolant", "interface_insert_1_coolant"}, 4);
}

BOOST_AUTO_TEST_CASE(names_beyond_32_characters_are_refused) {
  // Two tetrahedra sharing the face (0, 1, 2): metal below, coolant above.
  mesh::MeshData d;
  d.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  d.blocks = {{"blade", false, {{0, 2, 1, 3}}}, {"coolant", true, {{0, 1, 2, 4}}}};
  d.group_names = {"a_group_name_that_is_longer_than_32_characters", "chamber"};
  d.triangles = {{{0, 1, 2}, 1}, {{0, 1, 3}, 0}, {{0, 2, 3}, 0}, {{1, 2, 3}, 0}, {{0, 1, 4}, 0}, {{0, 2, 4}, 0}, {{1, 2, 4}, 0}};
  test::TempDir dir("mesh_cgns_names");
  try {
    mesh::write_cgns_file(mesh::directory_writer(dir.path), d);
    BOOST_ERROR("no error");
  } catch (const mesh::MeshError& e) {
    BOOST_TEST(std::string(e.what()).find("a_group_name_that_is_longer_than_32_characters") != std::string::npos, e.what());
    BOOST_TEST(std::string(e.what()).find("physical_groups") != std::string::npos, e.what());
  }
  BOOST_TEST(dir.entries().empty());
  // With short names the same mesh is written: an interface of one triangle, three outer triangles per side.
  d.group_names[0] = "blade_wall";
  BOOST_TEST(mesh::write_cgns_file(mesh::directory_writer(dir.path), d) == "mesh.cgns");
  const CgnsMesh m = read_cgns(dir.path / "mesh.cgns");
  BOOST_TEST_REQUIRE(m.zones.size() == 2u);
  for (const Zone& z : m.zones) {
    BOOST_TEST_REQUIRE(z.patches.size() == 2u);
    BOOST_TEST(z.patches[0].name == "blade_wall");
    BOOST_TEST(z.patches[0].triangles.size() == 3u);
    BOOST_TEST(z.patches[1].interface_family == "interface_blade_coolant");
    BOOST_TEST(z.connections.size() == 1u);
  }
}
