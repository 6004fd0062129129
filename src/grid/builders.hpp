#pragma once
// The two grid layouts of section_grid.hpp (internal to src/grid).
#include <utility>
#include <vector>

#include "src/blade/section.hpp"
#include "src/grid/block.hpp"
#include "src/grid/section_grid.hpp"
#include "src/grid/wall_patches.hpp"

namespace cg::grid::detail {

struct BuiltGrid {
  MultiBlockGrid grid;
  int wall_block = 0;               ///< the O-grid; its j = 0 row is the wall
  std::vector<double> wall_params;  ///< curve parameter of every wall node, i = 0..ni (after orientation)
  int wall_layers = 0;
};

/// Smallest and largest a (axial coordinate) of the section, from 2000 curve samples.
std::pair<double, double> axial_range(const blade::SectionProfile& section);

/// Resolved options: every default filled in (see section_grid.cpp).
BuiltGrid build_o_grid(const blade::SectionProfile& section, const WallPatches& patches, const SectionGridOptions& o);
BuiltGrid build_cascade_grid(const blade::SectionProfile& section, const WallPatches& patches,
                             const SectionGridOptions& o, int wall_layers);

/// Puts a block into right-handed orientation (reversing i) when its cells are left-handed.
void make_right_handed(BuiltGrid& g, int block);

}  // namespace cg::grid::detail
