#pragma once
// Mesh files besides gmsh's own .msh: VTK unstructured grids for ParaView, one per region
// (mesh_<region>.vtu: tetrahedra) and one of the boundary (mesh_surfaces.vtu: triangles with cell data
// "group_id" and the field-data table "group_names"). Files are written under a temporary name and
// renamed when complete, so a reader never sees half a file.
#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "src/mesh/mesh_options.hpp"

namespace cg::mesh {

struct MeshData {
  struct Block {
    std::string name;
    bool fluid = false;
    std::vector<std::array<std::size_t, 4>> tets;  ///< indices into points
  };
  struct Triangle {
    std::array<std::size_t, 3> nodes;
    int group = 0;  ///< index into group_names
  };
  std::vector<Eigen::Vector3d> points;
  std::vector<Block> blocks;
  std::vector<Triangle> triangles;
  std::vector<std::string> group_names;
};

/// Calls write(temporary path with the target's extension) and renames it to `target`; removes the
/// temporary and throws MeshError when write throws or leaves no file.
void write_renamed(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write);

/// Writes mesh_<block>.vtu per block and mesh_surfaces.vtu through `files`; returns the names.
std::vector<std::string> write_vtu_files(const FileWriter& files, const MeshData& data);

}  // namespace cg::mesh
