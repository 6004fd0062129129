#pragma once
// Cell validity and wall checks of a structured grid.
//  - Jacobian: at every corner of every cell, (next - corner) x (previous - corner) with the corners in
//    the order (i, j), (i+1, j), (i+1, j+1), (i, j+1); all four positive = a valid, right-handed cell.
//    The scaled Jacobian divides by the two edge lengths (the sine of the corner angle, 1 = square).
//  - Wall: the angle between the first grid line off the wall and the wall tangent (the tangent of the
//    exact section curve at the wall node's parameter), and the first cell height.
#include <string>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/grid/block.hpp"

namespace cg::grid {

/// Smallest sine of the four corner angles of cell (i, j) (the scaled Jacobian; <= 0: inverted or
/// degenerate, the cell is not valid).
double cell_scaled_jacobian(const Block& b, int i, int j);

struct BlockQuality {
  std::string name;
  int cells = 0;
  int inverted_cells = 0;           ///< cells with a corner Jacobian <= 0
  double min_scaled_jacobian = 1;   ///< smallest sine of a corner angle (negative: inverted)
  double max_cell_ratio = 1;        ///< largest ratio of neighbouring cell sizes along a grid line
};

BlockQuality block_quality(const Block& b);

struct WallQuality {
  int wall_nodes = 0;
  double max_angle_deviation_deg = 0;  ///< |90 deg - angle(first grid line, wall tangent)|, max over nodes
  double min_first_cell_height = 0, max_first_cell_height = 0;
};

/// Wall checks of the j = 0 row of `b` (nodes i = 0..ni) lying on `curve` at parameters `params`.
WallQuality wall_quality(const Block& b, const BSplineCurve<2>& curve, const std::vector<double>& params);

}  // namespace cg::grid
