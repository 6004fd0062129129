#include "src/mesh/blade_mesher.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <GProp_GProps.hxx>
#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

#include "src/mesh/mesh_cgns.hpp"
#include "src/mesh/mesh_files.hpp"

namespace cg::mesh {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// gmsh is a process-wide singleton: initialise for one job, finalise on every exit path.
struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::logger::start();
  }
  ~GmshSession() {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// Last gmsh error (or warnings) for messages.
std::string gmsh_error() {
  std::string e;
  try {
    gmsh::logger::getLastError(e);
  } catch (...) {
  }
  return e.empty() ? "no message" : e;
}

struct Props {
  Eigen::Vector3d centre;
  double mass = 0;
};
Props occt_props(const TopoDS_Shape& s, int dim) {
  GProp_GProps g;
  if (dim == 3)
    BRepGProp::VolumeProperties(s, g, true);
  else
    BRepGProp::SurfaceProperties(s, g, true);
  const gp_Pnt c = g.CentreOfMass();
  return {{c.X(), c.Y(), c.Z()}, g.Mass()};
}
Props gmsh_props(int dim, int tag) {
  Props p;
  double x, y, z;
  gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
  gmsh::model::occ::getMass(dim, tag, p.mass);
  p.centre = {x, y, z};
  return p;
}

// Index of the shape in `ours` that matches gmsh entity (dim, tag): same centre (1e-6 of the part size)
// and same size (1e-6 relative). -1 when none.
int match(const std::vector<Props>& ours, const Props& g, double size) {
  int best = -1;
  double best_d = HUGE_VAL;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const double d = (ours[i].centre - g.centre).norm();
    if (d < best_d && std::abs(ours[i].mass - g.mass) <= 1e-6 * std::max(std::abs(g.mass), 1e-12)) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best_d <= 1e-6 * size ? best : -1;
}

// Volume to 1e-7 relative (the plain Gauss rule used for matching is off by up to 1e-2 on thin B-spline walls).
double accurate_volume(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::VolumeProperties(s, g, 1e-7, true);
  return g.Mass();
}

bool is_outer_metal(const std::string& kind) {
  return kind == "blade_wall" || kind == "hub" || kind == "casing" || kind == "tip_cap" || kind == "hub_floor";
}

// Smallest radius of curvature of a face: exact for cylinders, cones and spheres (the common tool
// shapes), else the largest principal curvature sampled on a 9 x 9 grid. Infinity for planes.
double smallest_curvature_radius(const TopoDS_Face& face) {
  const BRepAdaptor_Surface s(face);
  switch (s.GetType()) {
    case GeomAbs_Plane: return HUGE_VAL;
    case GeomAbs_Cylinder: return s.Cylinder().Radius();
    case GeomAbs_Sphere: return s.Sphere().Radius();
    default: break;
  }
  double kmax = 0;
  BRepLProp_SLProps props(s, 2, 1e-9);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double u = s.FirstUParameter() + (s.LastUParameter() - s.FirstUParameter()) * (0.02 + 0.96 * i / 8);
      const double v = s.FirstVParameter() + (s.LastVParameter() - s.FirstVParameter()) * (0.02 + 0.96 * j / 8);
      props.SetParameters(u, v);
      if (props.IsCurvatureDefined()) kmax = std::max({kmax, std::abs(props.MaxCurvature()), std::abs(props.MinCurvature())});
    }
  return kmax > 0 ? 1 / kmax : HUGE_VAL;
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
         {"regions", regions_j},
         {"surface_groups", groups},
         {"files", files_j},
         {"notes", notes},
         {"timings_s", {{"geometry", seconds_geometry}, {"surface", seconds_surface}, {"volume", seconds_volume}, {"total", seconds_total}}}};
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

MeshResult mesh_blade(const brep::Part& part, const TopoDS_Shape& uncooled, const std::vector<brep::NamedFace>& uncooled_faces,
                      const FileWriter& files, const MeshOptions& o, ProgressSink* progress) {
  if (part.empty()) throw MeshError("mesh: the part has no bodies");
  if (!(o.max_size > 0) || !(o.min_size > 0) || o.min_size > o.max_size)
    throw MeshError("mesh: sizes must satisfy 0 < min_size <= max_size");
  if (!o.metal && !o.coolant) throw MeshError("mesh: neither metal nor coolant selected");
  const auto t_start = Clock::now();
  // Steps with their share of a typical run (for the progress bar); a stop is honoured between them.
  auto report = [&](const std::string& step, double fraction) {
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
    for (std::size_t b = 1; b < part.size(); ++b) r.insert_volume += accurate_volume(part[b].geometry.shape);
    r.coolant_brep_volume = coolant.volume;
    if (coolant.solids == 0) r.notes.push_back("the blade has no cavities: no coolant domain to mesh");
  }
  const brep::Part metal = o.metal ? part : brep::Part{};
  if (metal.empty() && coolant.solids == 0) throw MeshError("mesh: nothing to mesh (metal off and no coolant domain)");
  // Without metal, the coolant alone still needs its faces named: fuse it with nothing.
  const ConformalDomains domains = conformal_domains(metal, coolant);

  GmshSession session;
  gmsh::model::add("coolinggen");
  gmsh::vectorpair imported;
  gmsh::model::occ::importShapesNativePointer(&domains.compound, imported, /*highestDimOnly=*/false);
  gmsh::model::occ::synchronize();
  r.seconds_geometry = since(t_start);

  double size = 0;
  {
    std::vector<double> xyz(6);
    gmsh::model::getBoundingBox(-1, -1, xyz[0], xyz[1], xyz[2], xyz[3], xyz[4], xyz[5]);
    size = std::hypot(xyz[3] - xyz[0], xyz[4] - xyz[1], xyz[5] - xyz[2]);
  }

  // Volumes -> regions.
  std::vector<Props> solid_props;
  std::vector<int> solid_region;
  for (std::size_t k = 0; k < domains.regions.size(); ++k)
    for (const auto& s : domains.regions[k].solids) {
      solid_props.push_back(occt_props(s, 3));
      solid_region.push_back(static_cast<int>(k));
    }
  gmsh::vectorpair volumes, surfaces;
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::getEntities(surfaces, 2);
  std::vector<std::vector<int>> region_tags(domains.regions.size());
  for (const auto& [dim, tag] : volumes) {
    const int i = match(solid_props, gmsh_props(3, tag), size);
    if (i < 0) throw MeshError("mesh: gmsh volume " + std::to_string(tag) + " matches no solid of the part");
    region_tags[static_cast<std::size_t>(solid_region[static_cast<std::size_t>(i)])].push_back(tag);
  }
  for (std::size_t k = 0; k < domains.regions.size(); ++k) {
    if (region_tags[k].empty()) throw MeshError("mesh: region " + domains.regions[k].name + " has no gmsh volume");
    const int g = gmsh::model::addPhysicalGroup(3, region_tags[k]);
    gmsh::model::setPhysicalName(3, g, domains.regions[k].name);
  }
  // Surfaces -> feature groups.
  std::vector<Props> face_props;
  for (const auto& f : domains.faces) face_props.push_back(occt_props(f.face, 2));
  std::map<std::string, std::vector<int>> group_tags;
  std::map<int, int> face_of_surface;
  for (const auto& [dim, tag] : surfaces) {
    const int i = match(face_props, gmsh_props(2, tag), size);
    if (i < 0) throw MeshError("mesh: gmsh surface " + std::to_string(tag) + " matches no named face");
    const std::string& name = domains.faces[static_cast<std::size_t>(i)].name;
    face_of_surface[tag] = i;
    group_tags[o.groups == GroupBy::Kind ? brep::feature_kind(name) : name].push_back(tag);
  }
  std::map<int, std::string> group_of_surface;
  for (const auto& [name, tags] : group_tags) {
    const int g = gmsh::model::addPhysicalGroup(2, tags);
    gmsh::model::setPhysicalName(2, g, name);
    for (int t : tags) group_of_surface[t] = name;
  }

  // Sizes and algorithms.
  gmsh::option::setNumber("Mesh.MeshSizeMax", o.max_size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", o.min_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", o.curvature_elements);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  if (o.feature_curvature_elements > 0) {
    // Small features: point sizes from each cooling face's curvature (see MeshOptions). A vertex shared
    // by several faces (a hole's exit circle on the wall and on the opening) keeps the smallest size.
    std::map<int, double> point_size;
    for (const auto& [dim, tag] : surfaces) {
      const auto& f = domains.faces[static_cast<std::size_t>(face_of_surface.at(tag))];
      if (is_outer_metal(brep::feature_kind(f.name))) continue;
      const double rho = smallest_curvature_radius(f.face);
      if (!std::isfinite(rho)) continue;  // planar
      const double h = std::clamp(2 * M_PI * rho / o.feature_curvature_elements, o.min_size, o.max_size);
      gmsh::vectorpair pts;
      gmsh::model::getBoundary({{2, tag}}, pts, false, false, true);
      for (const auto& [pd, pt] : pts) {
        auto [it, added] = point_size.emplace(pt, h);
        if (!added) it->second = std::min(it->second, h);
      }
    }
    for (const auto& [pt, h] : point_size) gmsh::model::mesh::setSize({{0, pt}}, h);
  }
  gmsh::option::setNumber("Mesh.Algorithm", 6);     // Frontal-Delaunay surfaces
  gmsh::option::setNumber("Mesh.Algorithm3D", 10);  // HXT: parallel Delaunay
  gmsh::option::setNumber("Mesh.Optimize", o.optimize ? 1 : 0);
  gmsh::option::setNumber("General.NumThreads", o.threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", o.threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", o.threads);

  try {
    report("surface mesh", 0.25);
    auto t = Clock::now();
    gmsh::model::mesh::generate(2);
    r.seconds_surface = since(t);
    report("volume mesh", 0.45);
    t = Clock::now();
    gmsh::model::mesh::generate(3);
    r.seconds_volume = since(t);
  } catch (const std::exception& e) {
    throw MeshError(std::string("mesh: gmsh failed: ") + e.what() + " (" + gmsh_error() + ")");
  }

  // Nodes and elements back, quality per region.
  report("quality and files", 0.9);
  MeshData data;
  {
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
    r.nodes = tags.size();
    for (std::size_t k = 0; k < domains.regions.size(); ++k) {
      MeshData::Block block{domains.regions[k].name, domains.regions[k].fluid, {}};
      for (int vtag : region_tags[k]) {
        std::vector<std::size_t> etags, ntags;
        gmsh::model::mesh::getElementsByType(4, etags, ntags, vtag);  // 4-node tetrahedra
        for (std::size_t e = 0; e + 3 < ntags.size(); e += 4)
          block.tets.push_back({index.at(ntags[e]), index.at(ntags[e + 1]), index.at(ntags[e + 2]), index.at(ntags[e + 3])});
      }
      RegionMesh rm{domains.regions[k].name, domains.regions[k].fluid, tet_quality(data.points, block.tets), 0};
      for (const auto& s : domains.regions[k].solids) rm.brep_volume += accurate_volume(s);
      if (rm.fluid) r.coolant_mesh_volume += rm.tets.volume;
      r.tetrahedra += rm.tets.elements;
      r.inverted += rm.tets.inverted;
      r.regions.push_back(rm);
      data.blocks.push_back(std::move(block));
    }
    r.min_quality = 1;
    for (const auto& rm : r.regions) r.min_quality = std::min(r.min_quality, rm.tets.min_quality);
    std::map<std::string, SurfaceGroup> groups;
    for (const auto& [name, tags2] : group_tags) groups[name] = {name, 0, static_cast<int>(tags2.size())};
    for (const auto& [dim, stag] : surfaces) {
      std::vector<std::size_t> etags, ntags;
      gmsh::model::mesh::getElementsByType(2, etags, ntags, stag);  // 3-node triangles
      const std::string& g = group_of_surface.at(stag);
      const int gid = static_cast<int>(std::distance(group_tags.begin(), group_tags.find(g)));
      for (std::size_t e = 0; e + 2 < ntags.size(); e += 3)
        data.triangles.push_back({{index.at(ntags[e]), index.at(ntags[e + 1]), index.at(ntags[e + 2])}, gid});
      groups[g].triangles += etags.size();
      r.triangles += etags.size();
    }
    for (const auto& [name, tags2] : group_tags) data.group_names.push_back(name);
    for (auto& [name, g] : groups) r.surfaces.push_back(g);
  }

  if (o.write_msh) {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    files("mesh.msh", [&](const std::filesystem::path& target) {
      write_renamed(target, [&](const std::filesystem::path& tmp) { gmsh::write(tmp.string()); });
    });
    r.files.push_back("mesh.msh");
  }
  if (o.write_vtu) {
    const auto vtu = write_vtu_files(files, data);
    r.files.insert(r.files.end(), vtu.begin(), vtu.end());
  }
  if (o.write_cgns) r.files.push_back(write_cgns_file(files, data));
  r.seconds_total = since(t_start);
  return r;
}

}  // namespace cg::mesh
