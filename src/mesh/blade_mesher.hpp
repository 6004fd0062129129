#pragma once
// `coolinggen mesh`: tetrahedral meshes of the blade metal and of the coolant domain with gmsh's C++ API.
//
// The OCCT compound of conformal_domains() (metal bodies and coolant sharing their interface faces) is
// handed to gmsh directly (gmsh::model::occ::importShapesNativePointer: gmsh 4.8 is built on the same
// OCCT), so gmsh meshes our exact B-rep, not a re-import through a file. gmsh entities are matched to
// our faces and solids by centre of mass and size (gmsh computes them with the same BRepGProp).
// Physical groups: one volume group per region ("blade", "insert_1", "coolant") and one surface group
// per feature kind (or face name): the boundary conditions of a CFD set-up. Elementary entities are named
// too (gmsh::model::setEntityName: volumes by region, surfaces by face name), which gmsh's CGNS writer
// uses for its family names. Sizes: mesh_sizes.hpp (graded from the cooling features); 2D:
// surface_mesh.hpp (Frontal-Delaunay, Delaunay on periodic faces with many holes, our own fold check);
// 3D HXT (parallel Delaunay). Quality, volumes and the conformity of the metal/coolant interface are
// computed from the final nodes by src/mesh/mesh_quality.hpp.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"
#include "src/core/progress.hpp"
#include "src/mesh/coolant_domain.hpp"
#include "src/mesh/mesh_options.hpp"
#include "src/mesh/mesh_quality.hpp"

namespace cg::mesh {

struct RegionMesh {
  std::string name;
  bool fluid = false;
  TetQuality tets;
  double brep_volume = 0;  ///< mm^3, of the region's solids (BRepGProp)
};

struct SurfaceGroup {
  std::string name;  ///< feature kind or face name
  std::size_t triangles = 0;
  int faces = 0;     ///< B-rep faces in the group
};

struct MeshResult {
  std::vector<RegionMesh> regions;
  std::vector<SurfaceGroup> surfaces;
  std::size_t nodes = 0, triangles = 0, tetrahedra = 0, inverted = 0;
  double min_quality = 0;
  /// Triangles of faces shared by two regions (metal/coolant, insert/coolant) and how many of them are
  /// not a face of a tetrahedron on both sides (0 = conformal interface).
  std::size_t interface_triangles = 0, nonconformal_triangles = 0;
  int surfaces_frontal_delaunay = 0, surfaces_delaunay = 0;  ///< 2D algorithm per gmsh surface
  std::vector<std::string> surfaces_remeshed;                ///< faces re-meshed with MeshAdapt (fold check)
  std::size_t size_samples = 0;                              ///< points of the graded size field
  double removed_volume = 0;        ///< mm^3, V(uncooled) - V(blade): what the cooling features removed
  double insert_volume = 0;         ///< mm^3, bodies after the blade (inserts) standing in the cavities
  double coolant_brep_volume = 0;   ///< mm^3
  double coolant_mesh_volume = 0;   ///< mm^3, sum of the coolant tetrahedra
  std::vector<std::string> files;  ///< names written
  std::vector<std::string> notes;
  /// geometry: coolant domain, conformal fuse, import; sizes: the size field; surface: 1D + 2D + fold
  /// check; volume: 3D + optimisation; output: statistics and files.
  double seconds_geometry = 0, seconds_sizes = 0, seconds_surface = 0, seconds_volume = 0, seconds_output = 0, seconds_total = 0;

  /// For report.json: counts, quality, volumes, groups, timings.
  nlohmann::ordered_json to_json() const;
};

/// Meshes the part's bodies (options.metal) and its coolant domain (options.coolant; `uncooled` is the
/// blade solid before the features, its faces named in `uncooled_faces`) and writes the selected files
/// through `files`: mesh.msh, mesh_<region>.vtu, mesh_surfaces.vtu, mesh.cgns. `progress` (optional) sees the
/// steps and may stop the job between them (Cancelled). Throws MeshError when the options are out of
/// range or a step fails (the message names the step).
MeshResult mesh_blade(const brep::Part& part, const TopoDS_Shape& uncooled, const std::vector<brep::NamedFace>& uncooled_faces,
                      const FileWriter& files, const MeshOptions& options, ProgressSink* progress = nullptr);

}  // namespace cg::mesh
