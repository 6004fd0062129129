#include "src/mesh/blade_mesher.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "src/brep/solid_integrals.hpp"
#include "src/mesh/gmsh_session.hpp"
#include "src/mesh/mesh_cgns.hpp"
#include "src/mesh/mesh_files.hpp"
#include "src/mesh/mesh_sizes.hpp"
#include "src/mesh/surface_mesh.hpp"

namespace cg::mesh {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// gmsh volumes and surfaces of the imported compound, matched to our regions and named faces.
struct ModelMap {
  std::vector<std::vector<int>> region_volumes;  ///< per region: gmsh volume tags
  std::map<int, int> region_of_volume;
  std::vector<ModelSurface> surfaces;             ///< every gmsh surface with its face and name
  std::map<std::string, std::vector<int>> groups; ///< surface physical group -> gmsh surface tags
};

using ShapeIndex = NCollection_DataMap<TopoDS_Shape, int, TopTools_ShapeMapHasher>;

// Tags of the shapes of one type in `imported`: gmsh's importShapesNativePointer returns one (dim, tag)
// per TopExp_Explorer occurrence of a solid, then of a face, ... of the compound (OCC_Internals::
// _multiBind), so the k-th entry of dimension `dim` is the k-th occurrence. Checked: the same shape
// always gets the same tag, and gmsh's bounding box of each tag is the one BRepBndLib gives the shape.
ShapeIndex imported_tags(const TopoDS_Shape& compound, const gmsh::vectorpair& imported, TopAbs_ShapeEnum type, int dim,
                         double size) {
  std::vector<int> tags;
  for (const auto& [d, t] : imported)
    if (d == dim) tags.push_back(t);
  ShapeIndex index;
  std::size_t k = 0;
  for (TopExp_Explorer e(compound, type); e.More(); e.Next(), ++k) {
    if (k >= tags.size()) throw MeshError("mesh: gmsh imported fewer entities of dimension " + std::to_string(dim) + " than the compound has");
    if (const int* t = index.Seek(e.Current())) {
      if (*t != tags[k]) throw MeshError("mesh: gmsh gave one shape two tags");
      continue;
    }
    Bnd_Box ours;
    BRepBndLib::Add(e.Current(), ours);
    double a[6], g[6];
    ours.Get(a[0], a[1], a[2], a[3], a[4], a[5]);
    gmsh::model::occ::getBoundingBox(dim, tags[k], g[0], g[1], g[2], g[3], g[4], g[5]);
    for (int i = 0; i < 6; ++i)
      if (std::abs(a[i] - g[i]) > 1e-9 * size)
        throw MeshError("mesh: gmsh entity (" + std::to_string(dim) + ", " + std::to_string(tags[k]) + ") is not the shape imported in its place");
    index.Bind(e.Current(), tags[k]);
  }
  if (k != tags.size()) throw MeshError("mesh: gmsh imported more entities of dimension " + std::to_string(dim) + " than the compound has");
  return index;
}

ModelMap match_model(const ConformalDomains& domains, const gmsh::vectorpair& imported, GroupBy group_by) {
  Bnd_Box box;
  BRepBndLib::Add(domains.compound, box);
  const double size = std::sqrt(box.SquareExtent());
  const ShapeIndex volume_tag = imported_tags(domains.compound, imported, TopAbs_SOLID, 3, size);
  const ShapeIndex surface_tag = imported_tags(domains.compound, imported, TopAbs_FACE, 2, size);
  ModelMap m;
  m.region_volumes.resize(domains.regions.size());
  for (std::size_t k = 0; k < domains.regions.size(); ++k)
    for (const TopoDS_Shape& s : domains.regions[k].solids) {
      const int* tag = volume_tag.Seek(s);
      if (!tag) throw MeshError("mesh: a solid of region " + domains.regions[k].name + " is not in the gmsh model");
      m.region_volumes[k].push_back(*tag);
      m.region_of_volume[*tag] = static_cast<int>(k);
    }
  if (static_cast<int>(m.region_of_volume.size()) != volume_tag.Extent())
    throw MeshError("mesh: a gmsh volume belongs to no region");
  for (const brep::NamedFace& f : domains.faces) {
    const int* tag = surface_tag.Seek(f.face);
    if (!tag) throw MeshError("mesh: face " + f.name + " is not in the gmsh model");
    m.surfaces.push_back({*tag, f.face, f.name});
    m.groups[group_by == GroupBy::Kind ? brep::feature_kind(f.name) : f.name].push_back(*tag);
  }
  if (static_cast<int>(m.surfaces.size()) != surface_tag.Extent()) throw MeshError("mesh: a gmsh surface has no named face");
  return m;
}

// Physical groups (regions, surface groups) and the names of the elementary entities.
void name_model(const ConformalDomains& domains, const ModelMap& m) {
  for (std::size_t k = 0; k < domains.regions.size(); ++k) {
    if (m.region_volumes[k].empty()) throw MeshError("mesh: region " + domains.regions[k].name + " has no gmsh volume");
    const int g = gmsh::model::addPhysicalGroup(3, m.region_volumes[k]);
    gmsh::model::setPhysicalName(3, g, domains.regions[k].name);
    for (int v : m.region_volumes[k]) gmsh::model::setEntityName(3, v, domains.regions[k].name);
  }
  for (const auto& [name, tags] : m.groups) {
    const int g = gmsh::model::addPhysicalGroup(2, tags);
    gmsh::model::setPhysicalName(2, g, name);
  }
  for (const ModelSurface& s : m.surfaces) gmsh::model::setEntityName(2, s.tag, s.name);
}

// Nodes, tetrahedra per region and boundary triangles per group from gmsh; the interface triangles
// (surfaces between volumes of two regions) on the side.
MeshData extract_mesh(const ConformalDomains& domains, const ModelMap& m, std::vector<InterfaceTriangle>& interface) {
  MeshData data;
  std::vector<std::size_t> tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(tags, coord, param, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> index;
  index.reserve(tags.size());
  data.points.resize(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    index[tags[i]] = i;
    data.points[i] = {coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]};
  }
  for (std::size_t k = 0; k < domains.regions.size(); ++k) {
    MeshData::Block block{domains.regions[k].name, domains.regions[k].fluid, {}};
    for (int vtag : m.region_volumes[k]) {
      std::vector<std::size_t> etags, ntags;
      gmsh::model::mesh::getElementsByType(4, etags, ntags, vtag);  // 4-node tetrahedra
      for (std::size_t e = 0; e + 3 < ntags.size(); e += 4)
        block.tets.push_back({index.at(ntags[e]), index.at(ntags[e + 1]), index.at(ntags[e + 2]), index.at(ntags[e + 3])});
    }
    data.blocks.push_back(std::move(block));
  }
  std::map<int, int> group_of_surface;
  for (const auto& [name, stags] : m.groups) {
    for (int t : stags) group_of_surface[t] = static_cast<int>(data.group_names.size());
    data.group_names.push_back(name);
  }
  for (const ModelSurface& s : m.surfaces) {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(2, s.tag, up, down);
    std::set<int> sides;
    for (int v : up) sides.insert(m.region_of_volume.at(v));
    std::vector<std::size_t> etags, ntags;
    gmsh::model::mesh::getElementsByType(2, etags, ntags, s.tag);  // 3-node triangles
    for (std::size_t e = 0; e + 2 < ntags.size(); e += 3) {
      const std::array<std::size_t, 3> t{index.at(ntags[e]), index.at(ntags[e + 1]), index.at(ntags[e + 2])};
      data.triangles.push_back({t, group_of_surface.at(s.tag)});
      if (sides.size() == 2)
        interface.push_back({t, {static_cast<std::size_t>(*sides.begin()), static_cast<std::size_t>(*sides.rbegin())}});
    }
  }
  return data;
}

}  // namespace

nlohmann::ordered_json MeshResult::to_json() const {
  using json = nlohmann::ordered_json;
  json regions_j = json::array();
  for (const auto& r : regions)
    regions_j.push_back({{"name", r.name},
                         {"fluid", r.fluid},
                         {"tetrahedra", r.tets.elements},
                         {"inverted", r.tets.inverted},
                         {"min_quality", r.tets.min_quality},
                         {"mean_quality", r.tets.mean_quality},
                         {"quality_histogram", r.tets.histogram},
                         {"mesh_volume_mm3", r.tets.volume},
                         {"brep_volume_mm3", r.brep_volume}});
  json groups = json::array();
  for (const auto& g : surfaces) groups.push_back({{"name", g.name}, {"faces", g.faces}, {"triangles", g.triangles}});
  json files_j = files;
  json j{{"nodes", nodes},
         {"triangles", triangles},
         {"tetrahedra", tetrahedra},
         {"inverted", inverted},
         {"min_quality", min_quality},
         {"quality_measure", "radius ratio 3 r_in / R_circ (1 = regular tetrahedron)"},
         {"interface_triangles", interface_triangles},
         {"nonconformal_interface_triangles", nonconformal_triangles},
         {"surface_algorithms",
          {{"frontal_delaunay", surfaces_frontal_delaunay}, {"delaunay", surfaces_delaunay}, {"remeshed_meshadapt", surfaces_remeshed}}},
         {"size_field_samples", size_samples},
         {"regions", regions_j},
         {"surface_groups", groups},
         {"files", files_j},
         {"notes", notes},
         {"timings_s",
          {{"geometry", seconds_geometry},
           {"sizes", seconds_sizes},
           {"surface", seconds_surface},
           {"volume", seconds_volume},
           {"quality_and_files", seconds_output},
           {"total", seconds_total}}}};
  if (coolant_brep_volume > 0) {
    // The coolant fills what the features removed except the inserts standing in it.
    const double expected = removed_volume - insert_volume;
    j["coolant"] = {{"removed_volume_mm3", removed_volume},
                    {"insert_volume_mm3", insert_volume},
                    {"expected_volume_mm3", expected},
                    {"brep_volume_mm3", coolant_brep_volume},
                    {"mesh_volume_mm3", coolant_mesh_volume},
                    {"brep_vs_expected_relative", (coolant_brep_volume - expected) / expected},
                    {"mesh_vs_expected_relative", (coolant_mesh_volume - expected) / expected}};
  }
  return j;
}

namespace {

using Report = std::function<void(const std::string& step, double fraction)>;

// Counts, quality and volumes per region, conformity of the interfaces, triangles per surface group.
void statistics(const ConformalDomains& domains, const ModelMap& model, const MeshData& data,
                const std::vector<InterfaceTriangle>& interface, MeshResult& r) {
  r.nodes = data.points.size();
  std::vector<const std::vector<std::array<std::size_t, 4>>*> blocks;
  for (std::size_t k = 0; k < domains.regions.size(); ++k) {
    const MeshData::Block& block = data.blocks[k];
    RegionMesh rm{block.name, block.fluid, tet_quality(data.points, block.tets), 0};
    for (const auto& s : domains.regions[k].solids) rm.brep_volume += brep::volume_of(s);
    if (rm.fluid) r.coolant_mesh_volume += rm.tets.volume;
    r.tetrahedra += rm.tets.elements;
    r.inverted += rm.tets.inverted;
    r.regions.push_back(rm);
    blocks.push_back(&block.tets);
  }
  r.min_quality = 1;
  for (const auto& rm : r.regions) r.min_quality = std::min(r.min_quality, rm.tets.min_quality);
  r.interface_triangles = interface.size();
  r.nonconformal_triangles = nonconformal_triangles(interface, blocks);
  r.triangles = data.triangles.size();
  std::vector<std::size_t> per_group(data.group_names.size(), 0);
  for (const auto& t : data.triangles) ++per_group[static_cast<std::size_t>(t.group)];
  for (std::size_t g = 0; g < data.group_names.size(); ++g)
    r.surfaces.push_back({data.group_names[g], per_group[g], static_cast<int>(model.groups.at(data.group_names[g]).size())});
}

// Everything done in gmsh: import, names, sizes, surface and volume mesh, statistics, files.
void mesh_domains(const ConformalDomains& domains, const FileWriter& files, const MeshOptions& o, const Report& report,
                  Clock::time_point t_start, MeshResult& r) {
  GmshSession session;
  gmsh::model::add("coolinggen");
  gmsh::vectorpair imported;
  gmsh::model::occ::importShapesNativePointer(&domains.compound, imported, /*highestDimOnly=*/false);
  gmsh::model::occ::synchronize();
  const ModelMap model = match_model(domains, imported, o.groups);
  name_model(domains, model);
  r.seconds_geometry = since(t_start);

  auto t = Clock::now();
  const std::unique_ptr<GradedSizeField> field = install_sizes(model.surfaces, o);
  r.size_samples = field->samples();
  r.seconds_sizes = since(t);
  gmsh::option::setNumber("Mesh.Algorithm3D", 10);  // HXT: parallel Delaunay
  gmsh::option::setNumber("Mesh.Optimize", o.optimize ? 1 : 0);
  gmsh::option::setNumber("General.NumThreads", o.threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", o.threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", o.threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", o.threads);

  report("surface mesh", 0.25);
  t = Clock::now();
  const SurfaceMeshStats stats = mesh_surfaces(model.surfaces);
  r.surfaces_frontal_delaunay = stats.frontal_delaunay;
  r.surfaces_delaunay = stats.delaunay;
  r.surfaces_remeshed = stats.remeshed;
  for (const std::string& f : stats.remeshed)
    r.notes.push_back("face " + f + ": folded triangles after Delaunay, re-meshed with MeshAdapt");
  r.seconds_surface = since(t);
  report("volume mesh", 0.45);
  t = Clock::now();
  generate(3, "volume mesh");
  r.seconds_volume = since(t);

  // gmsh writes mesh.msh; then the mesh comes over and gmsh's copy is freed before the statistics and
  // the .vtu files (on the built-in example that copy is the larger part of the peak memory).
  report("quality and files", 0.9);
  t = Clock::now();
  if (o.write_msh) {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    files("mesh.msh", [&](const std::filesystem::path& target) {
      write_renamed(target, [&](const std::filesystem::path& tmp) { gmsh::write(tmp.string()); });
    });
    r.files.push_back("mesh.msh");
  }
  std::vector<InterfaceTriangle> interface;
  const MeshData data = extract_mesh(domains, model, interface);
  gmsh::model::mesh::clear();
  statistics(domains, model, data, interface, r);
  if (o.write_vtu) {
    const auto vtu = write_vtu_files(files, data);
    r.files.insert(r.files.end(), vtu.begin(), vtu.end());
  }
  if (o.write_cgns) r.files.push_back(write_cgns_file(files, data));
  r.seconds_output = since(t);
}

}  // namespace

MeshResult mesh_blade(const brep::Part& part, const TopoDS_Shape& uncooled, const std::vector<brep::NamedFace>& uncooled_faces,
                      const FileWriter& files, const MeshOptions& o, ProgressSink* progress) {
  if (part.empty()) throw MeshError("mesh: the part has no bodies");
  if (!(o.max_size > 0) || !(o.min_size > 0) || o.min_size > o.max_size)
    throw MeshError("mesh: sizes must satisfy 0 < min_size <= max_size");
  if (!(o.size_growth > 0) || o.size_growth > 2) throw MeshError("mesh: size_growth must be in (0, 2]");
  if (!o.metal && !o.coolant) throw MeshError("mesh: neither metal nor coolant selected");
  const auto t_start = Clock::now();
  // Steps with their share of a typical run (for the progress bar); a stop is honoured between them.
  const Report report = [&](const std::string& step, double fraction) {
    check_cancel(progress, "meshing, before " + step);
    report_progress(progress, fraction, step);
  };
  MeshResult r;

  // Geometry: coolant, conformal compound, names.
  report("coolant domain and conformal interfaces", 0.0);
  CoolantDomain coolant;
  if (o.coolant) {
    coolant = coolant_domain(part, uncooled, uncooled_faces);
    r.removed_volume = coolant.removed_volume;
    for (std::size_t b = 1; b < part.size(); ++b) r.insert_volume += brep::volume_of(part[b].geometry.shape);
    r.coolant_brep_volume = coolant.volume;
    if (coolant.solids == 0) r.notes.push_back("the blade has no cavities: no coolant domain to mesh");
  }
  const brep::Part metal = o.metal ? part : brep::Part{};
  if (metal.empty() && coolant.solids == 0) throw MeshError("mesh: nothing to mesh (metal off and no coolant domain)");
  // Without metal, the coolant alone still needs its faces named: fuse it with nothing.
  const ConformalDomains domains = conformal_domains(metal, coolant);
  try {
    mesh_domains(domains, files, o, report, t_start, r);
  } catch (const std::string& e) {  // gmsh's API throws its error messages as strings
    throw MeshError("mesh: gmsh: " + e);
  }
  r.seconds_total = since(t_start);
  return r;
}

}  // namespace cg::mesh
