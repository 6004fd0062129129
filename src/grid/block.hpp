#pragma once
// Structured multi-block grids in the plane of a blade section (mm): blocks of (ni + 1) x (nj + 1)
// nodes, named boundary conditions on node ranges of block faces, and node-to-node (1-to-1) connections
// between faces, periodic ones with their translation. This is the information the writers
// (export/grid_*) need for VTK, Plot3D and CGNS.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace cg::grid {

/// One structured block: node (i, j), i = 0..ni, j = 0..nj, stored at j * (ni + 1) + i. Blocks are
/// right-handed: (x_i x x_j) > 0 in every cell of a valid block.
struct Block {
  std::string name;
  int ni = 0, nj = 0;  ///< cells
  std::vector<Eigen::Vector2d> nodes;

  Block() = default;
  Block(std::string name, int ni, int nj);
  int cells() const { return ni * nj; }
  Eigen::Vector2d& at(int i, int j) { return nodes[static_cast<std::size_t>(j * (ni + 1) + i)]; }
  const Eigen::Vector2d& at(int i, int j) const { return nodes[static_cast<std::size_t>(j * (ni + 1) + i)]; }
};

enum class Face { IMin, IMax, JMin, JMax };

/// Nodes begin..end (inclusive) along a face: the i index on the J faces, the j index on the I faces.
/// begin > end runs the range backwards (used to pair donor nodes in order).
struct FaceRange {
  Face face = Face::JMin;
  int begin = 0, end = 0;
  int nodes() const { return (end >= begin ? end - begin : begin - end) + 1; }
  int node(int k) const { return end >= begin ? begin + k : begin - k; }
};

/// Node (i, j) of the k-th node of a face range.
Eigen::Vector2i face_node(const Block& b, const FaceRange& r, int k);

enum class BoundaryKind { Wall, Inlet, Outlet, Farfield };
const char* boundary_kind_name(BoundaryKind k);

struct BoundaryCondition {
  std::string name;
  BoundaryKind kind = BoundaryKind::Wall;
  int block = 0;
  FaceRange range;
};

/// Node k of `range` on `block` coincides with node k of `donor_range` on `donor` after adding
/// `translation` (zero for a plain interface; the pitch vector for a periodic pair).
struct Connection {
  std::string name;
  int block = 0;
  FaceRange range;
  int donor = 0;
  FaceRange donor_range;
  bool periodic = false;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
};

struct MultiBlockGrid {
  std::vector<Block> blocks;
  std::vector<BoundaryCondition> boundaries;
  std::vector<Connection> connections;
  int cells() const;
  int nodes() const;
};

/// Largest distance between paired nodes of a connection (after the translation).
double connection_mismatch(const MultiBlockGrid& g, const Connection& c);

/// Reverses the i direction of block b (node (i, j) -> (ni - i, j)) and updates every boundary and
/// connection range that refers to it.
void reverse_i(MultiBlockGrid& g, int b);

}  // namespace cg::grid
