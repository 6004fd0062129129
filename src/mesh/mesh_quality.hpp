#pragma once
// Quality of a tetrahedral mesh, computed from the node coordinates (independent of gmsh):
// signed volume (inverted = volume <= 0 in gmsh's node order, which is positive for valid elements)
// and the normalised radius ratio rho = 3 r_in / R_circ (1 for the regular tetrahedron, 0 for a
// degenerate one; r_in = 3 V / surface area, R_circ from the edge lengths: Crelle's formula
// 24 V R = sqrt((aA + bB + cC)(aA + bB - cC)(aA - bB + cC)(-aA + bB + cC)), a/A, b/B, c/C the
// lengths of opposite edges).
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace cg::mesh {

struct TetQuality {
  std::size_t elements = 0;
  std::size_t inverted = 0;   ///< signed volume <= 0
  double min_quality = 0;     ///< smallest radius ratio (0 when there are no elements)
  double mean_quality = 0;
  double volume = 0;          ///< sum of signed volumes, mm^3
  std::array<std::size_t, 5> histogram{};  ///< radius ratio in [0,0.1), [0.1,0.2), [0.2,0.3), [0.3,0.5), [0.5,1]
};

/// Signed volume of the tetrahedron (p0, p1, p2, p3): det[p1 - p0, p2 - p0, p3 - p0] / 6.
double tet_volume(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3);
/// Radius ratio (see above) of a tetrahedron; 0 when degenerate.
double tet_radius_ratio(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3);

/// Quality of the tetrahedra `tets` (node indices into `points`).
TetQuality tet_quality(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<std::size_t, 4>>& tets);

/// A boundary triangle on a face shared by two regions (indices of `blocks`).
struct InterfaceTriangle {
  std::array<std::size_t, 3> nodes;
  std::array<std::size_t, 2> blocks;
};

/// Interface triangles that are not a face of some tetrahedron of each of their two blocks: 0 when
/// the mesh is conformal across every interface (the regions share the interface's nodes and
/// triangles). `blocks[b]`: the tetrahedra of block b.
std::size_t nonconformal_triangles(const std::vector<InterfaceTriangle>& interface,
                                   const std::vector<const std::vector<std::array<std::size_t, 4>>*>& blocks);

}  // namespace cg::mesh
