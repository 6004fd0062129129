#include "src/grid/grid_quality.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg::grid {

namespace {
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

double cell_scaled_jacobian(const Block& b, int i, int j) {
  const Eigen::Vector2d p[4] = {b.at(i, j), b.at(i + 1, j), b.at(i + 1, j + 1), b.at(i, j + 1)};
  double q = 1;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = p[(k + 1) % 4] - p[k], c = p[(k + 3) % 4] - p[k];
    const double la = a.norm(), lc = c.norm();
    q = std::min(q, la > 0 && lc > 0 ? cross(a, c) / (la * lc) : -1.0);  // a collapsed edge counts as inverted
  }
  return q;
}

BlockQuality block_quality(const Block& b) {
  BlockQuality q;
  q.name = b.name;
  q.cells = b.cells();
  for (int j = 0; j < b.nj; ++j)
    for (int i = 0; i < b.ni; ++i) {
      const double s = cell_scaled_jacobian(b, i, j);
      q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, s);
      if (!(s > 0)) ++q.inverted_cells;
    }
  // Neighbouring cell sizes along i and j lines (edge lengths of consecutive edges).
  for (int j = 0; j <= b.nj; ++j)
    for (int i = 1; i < b.ni; ++i) {
      const double l0 = (b.at(i, j) - b.at(i - 1, j)).norm(), l1 = (b.at(i + 1, j) - b.at(i, j)).norm();
      if (l0 > 0 && l1 > 0) q.max_cell_ratio = std::max(q.max_cell_ratio, std::max(l0 / l1, l1 / l0));
    }
  for (int i = 0; i <= b.ni; ++i)
    for (int j = 1; j < b.nj; ++j) {
      const double l0 = (b.at(i, j) - b.at(i, j - 1)).norm(), l1 = (b.at(i, j + 1) - b.at(i, j)).norm();
      if (l0 > 0 && l1 > 0) q.max_cell_ratio = std::max(q.max_cell_ratio, std::max(l0 / l1, l1 / l0));
    }
  return q;
}

WallQuality wall_quality(const Block& b, const BSplineCurve<2>& curve, const std::vector<double>& params) {
  require(static_cast<int>(params.size()) == b.ni + 1, "wall_quality: one parameter per wall node needed");
  WallQuality w;
  w.wall_nodes = b.ni + 1;
  w.min_first_cell_height = HUGE_VAL;
  for (int i = 0; i <= b.ni; ++i) {
    Eigen::Vector2d d[2];
    curve.derivatives(params[static_cast<std::size_t>(i)], 1, d);
    const Eigen::Vector2d line = b.at(i, 1) - b.at(i, 0);
    const double h = line.norm();
    const double c = std::abs(d[1].dot(line)) / (d[1].norm() * h);
    w.max_angle_deviation_deg = std::max(w.max_angle_deviation_deg, std::asin(std::min(1.0, c)) * 180.0 / kPi);
    w.min_first_cell_height = std::min(w.min_first_cell_height, h);
    w.max_first_cell_height = std::max(w.max_first_cell_height, h);
  }
  return w;
}

}  // namespace cg::grid
