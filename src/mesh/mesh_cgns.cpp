#include "src/mesh/mesh_cgns.hpp"

#include <cgnslib.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "export/cgns_file.hpp"
#include "src/mesh/coolant_domain.hpp"
#include "src/mesh/zone_boundaries.hpp"

namespace cg::mesh {
namespace {

using io::cgns_check;

constexpr const char* kFile = "mesh.cgns";
constexpr const char* kVolumeSection = "Tetrahedra";

const std::string& checked_name(const std::string& name, const std::string& what) {
  if (name.empty() || name.size() > 32)
    throw MeshError(std::string(kFile) + ": the " + what + " name '" + name + "' has " + std::to_string(name.size()) +
                    " characters, CGNS allows 1 to 32 (use \"physical_groups\": \"kind\" or leave \"cgns\" out of mesh.formats)");
  return name;
}

cgsize_t checked_count(std::size_t n, const std::string& what) {
  if (n > static_cast<std::size_t>(CG_MAX_INT32))
    throw MeshError(std::string(kFile) + ": " + what + " has " + std::to_string(n) +
                    " entries, more than the 32-bit indices of this CGNS library allow");
  return static_cast<cgsize_t>(n);
}

// "interface_<a>_<b>": the metal region first, else the lower block index first.
std::string interface_name(const MeshData& d, int a, int b) {
  const auto& A = d.blocks[static_cast<std::size_t>(a)];
  const auto& B = d.blocks[static_cast<std::size_t>(b)];
  const bool swap = (A.fluid && !B.fluid) || (A.fluid == B.fluid && a > b);
  return checked_name("interface_" + (swap ? B.name + "_" + A.name : A.name + "_" + B.name), "interface family");
}

bool is_opening(const std::string& group) { return group.rfind("coolant_opening", 0) == 0; }

// The nodes of a block's tetrahedra, ascending; a node's index in its zone is its position + 1.
std::vector<std::size_t> zone_nodes(const MeshData::Block& b, std::size_t points) {
  std::vector<char> used(points, 0);
  for (const auto& t : b.tets)
    for (std::size_t n : t) used[n] = 1;
  std::vector<std::size_t> nodes;
  for (std::size_t n = 0; n < points; ++n)
    if (used[n]) nodes.push_back(n);
  return nodes;
}

cgsize_t local_index(const std::vector<std::size_t>& nodes, std::size_t n) {
  return static_cast<cgsize_t>(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin() + 1);
}

// Patch names, unique in the zone: the group's, with the other side appended when the group bounds
// the zone on several kinds of side.
std::vector<std::string> patch_names(const MeshData& d, const RegionBoundary& r) {
  std::map<int, int> sides;
  for (const auto& p : r.patches) ++sides[p.group];
  std::vector<std::string> names;
  for (const auto& p : r.patches) {
    std::string n = d.group_names[static_cast<std::size_t>(p.group)];
    if (sides[p.group] > 1) n += "_" + (p.partner < 0 ? std::string("outer") : d.blocks[static_cast<std::size_t>(p.partner)].name);
    if (n == kVolumeSection) n += "_faces";
    names.push_back(checked_name(n, "boundary patch"));
  }
  return names;
}

// Family_t per surface group and per interface.
void write_families(int fn, int B, const MeshData& d, const ZoneBoundaries& z) {
  std::set<int> groups;
  std::map<std::string, std::pair<int, int>> interfaces;
  for (std::size_t k = 0; k < z.regions.size(); ++k)
    for (const auto& p : z.regions[k].patches) {
      groups.insert(p.group);
      if (p.partner >= 0) interfaces.emplace(interface_name(d, static_cast<int>(k), p.partner), std::make_pair(static_cast<int>(k), p.partner));
    }
  auto family = [&](const std::string& name, CGNS_ENUMT(BCType_t) type) {
    int F = 0, BC = 0;
    cgns_check(cg_family_write(fn, B, checked_name(name, "family").c_str(), &F), "family " + name);
    cgns_check(cg_fambc_write(fn, B, F, "FamBC", type, &BC), "family BC " + name);
    return F;
  };
  for (int g : groups) {
    const std::string& name = d.group_names[static_cast<std::size_t>(g)];
    family(name, is_opening(name) ? CGNS_ENUMV(BCTypeUserDefined) : CGNS_ENUMV(BCWall));
  }
  for (const auto& [name, zones] : interfaces) {
    const int F = family(name, CGNS_ENUMV(BCTypeUserDefined));
    const std::string text = "Conformal interface between zones " + d.blocks[static_cast<std::size_t>(zones.first)].name + " and " +
                             d.blocks[static_cast<std::size_t>(zones.second)].name +
                             ": the same triangles and node coordinates on both sides (ZoneGridConnectivity " + name + ").";
    cgns_check(cg_goto(fn, B, "Family_t", F, "end"), "goto family " + name);
    cgns_check(cg_descriptor_write("Interface", text.c_str()), "descriptor " + name);
  }
}

// One zone: nodes, the tetrahedra, a TRI_3 section and a BC per boundary patch.
int write_zone(io::CgnsFile& out, int B, const MeshData& d, std::size_t k, const RegionBoundary& r, const std::vector<std::size_t>& nodes) {
  const int fn = out.id();
  const MeshData::Block& block = d.blocks[k];
  const std::string& zone_name = checked_name(block.name, "zone");
  cgsize_t size[3] = {checked_count(nodes.size(), "zone " + zone_name + " nodes"),
                      checked_count(block.tets.size(), "zone " + zone_name + " tetrahedra"), 0};
  int Z = 0;
  cgns_check(cg_zone_write(fn, B, zone_name.c_str(), size, CGNS_ENUMV(Unstructured), &Z), "zone " + zone_name);
  std::vector<double> xyz(nodes.size());
  const char* coordinate[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < nodes.size(); ++i) xyz[i] = d.points[nodes[i]][c];
    out.write_coordinate(B, Z, coordinate[c], xyz);
  }
  std::vector<cgsize_t> local(d.points.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) local[nodes[i]] = static_cast<cgsize_t>(i + 1);
  std::vector<cgsize_t> conn;
  conn.reserve(4 * block.tets.size());
  for (const auto& t : block.tets)
    for (std::size_t n : t) conn.push_back(local[n]);
  int S = 0;
  cgns_check(cg_section_write(fn, B, Z, kVolumeSection, CGNS_ENUMV(TETRA_4), 1, size[1], 0, conn.data(), &S),
             zone_name + " tetrahedra");
  const std::vector<std::string> names = patch_names(d, r);
  cgsize_t next = size[1] + 1;
  for (std::size_t j = 0; j < r.patches.size(); ++j) {
    const BoundaryPatch& p = r.patches[j];
    const std::string what = zone_name + " patch " + names[j];
    conn.clear();
    for (const auto& t : p.triangles)
      for (std::size_t n : t) conn.push_back(local[n]);
    const cgsize_t range[2] = {next, next + checked_count(p.triangles.size(), what) - 1};
    checked_count(static_cast<std::size_t>(range[1]), zone_name + " elements");
    cgns_check(cg_section_write(fn, B, Z, names[j].c_str(), CGNS_ENUMV(TRI_3), range[0], range[1], 0, conn.data(), &S), what);
    int BC = 0;
    cgns_check(cg_boco_write(fn, B, Z, names[j].c_str(), CGNS_ENUMV(FamilySpecified), CGNS_ENUMV(PointRange), 2, range, &BC), what);
    cgns_check(cg_boco_gridlocation_write(fn, B, Z, BC, CGNS_ENUMV(FaceCenter)), what + " location");
    cgns_check(cg_goto(fn, B, "Zone_t", Z, "ZoneBC_t", 1, "BC_t", BC, "end"), "goto " + what);
    cgns_check(cg_famname_write(d.group_names[static_cast<std::size_t>(p.group)].c_str()), what + " family");
    if (p.partner >= 0)
      cgns_check(cg_multifam_write("Interface", interface_name(d, static_cast<int>(k), p.partner).c_str()), what + " interface family");
    next = range[1] + 1;
  }
  return Z;
}

// Abutting1to1 vertex connectivity of every interface patch (from both sides, as each side lists it).
void write_interfaces(int fn, int B, const MeshData& d, const ZoneBoundaries& z, const std::vector<int>& zone,
                      const std::vector<std::vector<std::size_t>>& nodes) {
  for (std::size_t k = 0; k < z.regions.size(); ++k) {
    std::map<int, std::vector<std::size_t>> shared;  // partner -> global nodes
    for (const auto& p : z.regions[k].patches)
      if (p.partner >= 0)
        for (const auto& t : p.triangles) shared[p.partner].insert(shared[p.partner].end(), t.begin(), t.end());
    for (auto& [partner, global] : shared) {
      std::sort(global.begin(), global.end());
      global.erase(std::unique(global.begin(), global.end()), global.end());
      const auto& donor_nodes = nodes[static_cast<std::size_t>(partner)];
      std::vector<cgsize_t> here, there;
      for (std::size_t n : global) {
        here.push_back(local_index(nodes[k], n));
        there.push_back(local_index(donor_nodes, n));
      }
      const std::string name = interface_name(d, static_cast<int>(k), partner);
      const cgsize_t count = checked_count(global.size(), name);
      int I = 0;
      cgns_check(cg_conn_write(fn, B, zone[k], name.c_str(), CGNS_ENUMV(Vertex), CGNS_ENUMV(Abutting1to1), CGNS_ENUMV(PointList),
                               count, here.data(), d.blocks[static_cast<std::size_t>(partner)].name.c_str(), CGNS_ENUMV(Unstructured),
                               CGNS_ENUMV(PointListDonor), CGNS_ENUMV(Integer), count, there.data(), &I),
                 "connectivity " + name + " in " + d.blocks[k].name);
    }
  }
}

}  // namespace

std::string write_cgns_file(const FileWriter& files, const MeshData& data) {
  const ZoneBoundaries z = zone_boundaries(data);
  std::vector<std::vector<std::size_t>> nodes;
  for (const auto& b : data.blocks) nodes.push_back(zone_nodes(b, data.points.size()));
  files(kFile, [&](const std::filesystem::path& target) {
    write_renamed(target, [&](const std::filesystem::path& tmp) {
      io::CgnsFile out(tmp);
      const int fn = out.id(), B = out.write_base("coolinggen_mesh", 3, 3);
      write_families(fn, B, data, z);
      std::vector<int> zone;
      for (std::size_t k = 0; k < data.blocks.size(); ++k) zone.push_back(write_zone(out, B, data, k, z.regions[k], nodes[k]));
      write_interfaces(fn, B, data, z, zone, nodes);
      out.close();
    });
  });
  return kFile;
}

}  // namespace cg::mesh
