#include "src/grid/grid_repair.hpp"

#include <algorithm>
#include <vector>

#include "src/grid/grid_quality.hpp"

namespace cg::grid::detail {

void untangle(Block& b, int j0, int rounds) {
  const int ni = b.ni;
  auto inverted = [&](int i, int j) { return !(cell_scaled_jacobian(b, i, j) > 0); };
  for (int round = 0; round < rounds; ++round) {
    std::vector<char> mark(static_cast<std::size_t>(ni * (b.nj + 1)), 0);
    bool any = false;
    for (int j = j0; j < b.nj; ++j)
      for (int i = 0; i < ni; ++i)
        if (inverted(i, j)) {
          any = true;
          for (int dj = -2; dj <= 3; ++dj)
            for (int di = -2; di <= 3; ++di) {
              const int jj = j + dj;
              if (jj > j0 && jj < b.nj) mark[static_cast<std::size_t>(jj * ni + ((i + di) % ni + ni) % ni)] = 1;
            }
        }
    if (!any) return;
    for (int sweep = 0; sweep < 5; ++sweep)
      for (int j = j0 + 1; j < b.nj; ++j)
        for (int i = 0; i < ni; ++i)
          if (mark[static_cast<std::size_t>(j * ni + i)])
            b.at(i, j) = 0.25 * (b.at((i + 1) % ni, j) + b.at((i + ni - 1) % ni, j) + b.at(i, j + 1) + b.at(i, j - 1));
    for (int j = 0; j <= b.nj; ++j) b.at(ni, j) = b.at(0, j);
  }
}

void improve_worst_cells(Block& b, int j0, double threshold, int sweeps) {
  const int ni = b.ni;
  auto local = [&](int i, int j) {
    const int im = (i + ni - 1) % ni;
    return std::min({cell_scaled_jacobian(b, im, j - 1), cell_scaled_jacobian(b, i, j - 1), cell_scaled_jacobian(b, im, j), cell_scaled_jacobian(b, i, j)});
  };
  auto ratio = [&](int i, int j) {
    const double l = (b.at(i, j) - b.at((i + ni - 1) % ni, j)).norm(), r = (b.at((i + 1) % ni, j) - b.at(i, j)).norm();
    const double d = (b.at(i, j) - b.at(i, j - 1)).norm(), u = (b.at(i, j + 1) - b.at(i, j)).norm();
    return std::max({l / r, r / l, d / u, u / d});
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    int moved = 0;
    for (int j = j0 + 1; j < b.nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const double before = local(i, j);
        if (before >= threshold) continue;
        const double ratio_limit = std::max(3.0, ratio(i, j));
        const Eigen::Vector2d old = b.at(i, j);
        b.at(i, j) = 0.25 * (b.at((i + 1) % ni, j) + b.at((i + ni - 1) % ni, j) + b.at(i, j + 1) + b.at(i, j - 1));
        if (i == 0) b.at(ni, j) = b.at(0, j);
        if (local(i, j) > before && ratio(i, j) <= ratio_limit) {
          ++moved;
        } else {
          b.at(i, j) = old;
          if (i == 0) b.at(ni, j) = old;
        }
      }
    if (moved == 0) break;
  }
}

}  // namespace cg::grid::detail
