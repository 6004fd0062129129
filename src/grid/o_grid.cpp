// The single-block O-grid: every layer on the exact wall patches (see section_grid.hpp).
#include <algorithm>
#include <cmath>

#include "src/grid/builders.hpp"
#include "src/grid/distribution.hpp"
#include "src/grid/wall_nodes.hpp"

namespace cg::grid::detail {

void make_right_handed(BuiltGrid& g, int index) {
  const Block& b = g.grid.blocks[static_cast<std::size_t>(index)];
  double sum = 0;  // signed area: positive for a right-handed (i, j) block
  for (int j = 0; j < b.nj; ++j)
    for (int i = 0; i < b.ni; ++i) {
      const Eigen::Vector2d a = b.at(i + 1, j + 1) - b.at(i, j), c = b.at(i, j + 1) - b.at(i + 1, j);
      sum += a.x() * c.y() - a.y() * c.x();
    }
  if (sum >= 0) return;
  reverse_i(g.grid, index);
  if (index == g.wall_block) std::reverse(g.wall_params.begin(), g.wall_params.end());
}

BuiltGrid build_o_grid(const blade::SectionProfile& section, const WallPatches& patches, const SectionGridOptions& o) {
  BuiltGrid out;
  const int ni = o.cells_around, nj = o.cells_normal;
  const WallArc arc(section);
  out.wall_params = arc.params(clustered_wall_positions(section, arc, ni, o.wall_clustering));
  out.wall_params.back() = out.wall_params.front() + section.curve.period();  // the cut: same point
  const std::vector<double> s = geometric_then_uniform(o.first_cell_height, o.growth_ratio, nj, o.thickness);
  Block b("o_grid", ni, nj);
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j <= nj; ++j) b.at(i, j) = patches.point(out.wall_params[static_cast<std::size_t>(i)], s[static_cast<std::size_t>(j)]);
  for (int j = 0; j <= nj; ++j) b.at(ni, j) = b.at(0, j);
  out.grid.blocks.push_back(std::move(b));
  out.grid.boundaries.push_back({"wall", BoundaryKind::Wall, 0, {Face::JMin, 0, ni}});
  out.grid.boundaries.push_back({"outer", BoundaryKind::Farfield, 0, {Face::JMax, 0, ni}});
  out.grid.connections.push_back({"o_cut", 0, {Face::IMin, 0, nj}, 0, {Face::IMax, 0, nj}, false, Eigen::Vector2d::Zero()});
  out.wall_layers = nj;
  make_right_handed(out, 0);
  return out;
}

}  // namespace cg::grid::detail
