#pragma once
// The boundary of each region of a conformal tetrahedral mesh, split into patches by surface group and
// by what lies on the other side: nothing (an outer boundary of the region: blade_wall, hub,
// coolant_opening_hub, ...) or another region (an interface: the chamber faces between blade and
// coolant, the insert faces between insert_1 and coolant). Found from the tetrahedra themselves: a
// boundary triangle bounds the regions whose tetrahedra have it as a face, so no gmsh adjacency is
// needed. Each region's copy of a triangle is oriented with its normal out of that region, so an
// interface appears twice, with opposite orientations. A triangle that is a face of two tetrahedra of
// the same region (a face inside a region) bounds neither side and is counted in `inner_triangles`.
#include <array>
#include <cstddef>
#include <vector>

#include "src/mesh/mesh_files.hpp"

namespace cg::mesh {

struct BoundaryPatch {
  int group = 0;     ///< index into MeshData::group_names
  int partner = -1;  ///< block on the other side; -1 for an outer boundary of the region
  std::vector<std::array<std::size_t, 3>> triangles;  ///< node indices into MeshData::points, normal out of the region
};

struct RegionBoundary {
  std::vector<BoundaryPatch> patches;  ///< sorted by (group, partner)
};

struct ZoneBoundaries {
  std::vector<RegionBoundary> regions;  ///< one per MeshData::blocks entry
  std::size_t inner_triangles = 0;
};

/// Classifies every triangle of `data`. Throws MeshError when a triangle is a face of no tetrahedron
/// or of more than two (the mesh is not conformal).
ZoneBoundaries zone_boundaries(const MeshData& data);

}  // namespace cg::mesh
