#pragma once
// Options of `coolinggen mesh` (config section "mesh", data/schema/coolinggen.schema.json).
#include <filesystem>
#include <functional>
#include <string>

namespace cg::mesh {

enum class GroupBy { Kind, FaceName };

struct MeshOptions {
  double max_size = 1.5;          ///< mm, largest element edge, > 0
  double min_size = 0.05;         ///< mm, smallest element edge, (0, max_size]
  /// Elements per 2 pi of curvature on every surface (gmsh Mesh.MeshSizeFromCurvature): resolves the
  /// leading and trailing edges of the outer wall. 0 = off.
  int curvature_elements = 16;
  /// Elements per 2 pi of curvature on the cooling features (every face that is not outer metal:
  /// blade_wall, hub, casing, tip_cap, hub_floor): the refinement on small features. Every point of such
  /// a face needs 2 pi rho / N, rho its smaller principal radius of curvature there, clamped to
  /// [min_size, max_size] (mesh_sizes.hpp). 40 keeps the volume of a cylindrical passage within 0.5 %
  /// (the inscribed polygon loses 1 - N sin(2 pi / N) / (2 pi) = 0.41 % of the area at N = 40). 0 = off.
  int feature_curvature_elements = 40;
  /// Growth of the element size away from those features, mm per mm, (0, 2]: at distance d from a
  /// feature point of size h the size is h + size_growth * d, up to max_size. The peak memory of gmsh's
  /// volume mesher grows with the tetrahedra: on the built-in example 0.25 gave 10.7 M tetrahedra and
  /// 3.7 GB, 0.3 gave 9.1 M and 3.4 GB, 0.35 gave 8.0 M and 3.2 GB (the coolant volume within 0.012 %
  /// in all three); 0.3 keeps the 4 GB goal with a margin.
  double size_growth = 0.3;
  bool metal = true;              ///< mesh the metal bodies (blade, inserts)
  bool coolant = true;            ///< mesh the coolant domain (when the blade has cavities)
  bool write_msh = true;          ///< mesh.msh (gmsh 4.1, physical groups only)
  bool write_vtu = true;          ///< mesh_<region>.vtu (tetrahedra) and mesh_surfaces.vtu (triangles)
  bool write_cgns = false;        ///< mesh.cgns (src/mesh/mesh_cgns.hpp: a zone per region, families, interfaces)
  GroupBy groups = GroupBy::Kind; ///< surface physical groups per feature kind or per full face name
  int threads = 2;                ///< gmsh threads (HXT volume mesher, surface meshing), >= 1
  bool optimize = true;           ///< gmsh's tetrahedron optimisation (Mesh.Optimize)
};

/// Writes one output file: `writer(target)` must create `target` (atomically); `name` is a plain file
/// name. directory_writer(dir) writes dir / name; the pipeline passes its OutputDirectory.
using FileWriter =
    std::function<void(const std::string& name, const std::function<void(const std::filesystem::path& target)>& writer)>;
FileWriter directory_writer(const std::filesystem::path& dir);

}  // namespace cg::mesh
