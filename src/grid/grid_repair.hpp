#pragma once
// Repairs of a structured block that is periodic in i (node ni = node 0), for the cascade O-grid
// (internal to src/grid). Rows j <= j0 (the exact wall layers) and j = nj (the outer boundary) never move.
#include "src/grid/block.hpp"

namespace cg::grid::detail {

/// Local untangling: the nodes j0 < j < nj around cells with a non-positive corner Jacobian (and their
/// neighbours) move to the mean of their four neighbours, a few sweeps at a time, until no cell is
/// inverted (or `rounds` is used up).
void untangle(Block& b, int j0, int rounds);

/// Quality-guarded smoothing (in the spirit of Freitag's smart Laplacian): a node j0 < j < nj whose four
/// cells include one with scaled Jacobian below `threshold` moves to the mean of its four neighbours
/// only if the worst of its four cells gets better and the ratio of its neighbouring edge lengths along
/// either grid line stays below max(3, before). It never inverts a cell and leaves good regions (and so
/// the wall-normal clustering) alone.
void improve_worst_cells(Block& b, int j0, double threshold, int sweeps);

}  // namespace cg::grid::detail
