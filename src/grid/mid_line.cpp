#include "src/grid/mid_line.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "src/algo/ray_curve.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/fit/approximate.hpp"

namespace cg::grid::detail {

MidLine::MidLine(const BSplineCurve<2>& wall, double a_min, double a_max) {
  const int stations = 41;
  std::vector<Eigen::Matrix<double, 1, 1>> y;
  std::vector<double> x;
  for (int k = 1; k < stations; ++k) {
    const double a = a_min + (a_max - a_min) * 0.5 * (1 - std::cos(kPi * k / stations));
    const auto hits = line_curve_intersections(wall, Eigen::Vector2d(a, 0), Eigen::Vector2d(0, 1),
                                               -std::numeric_limits<double>::infinity(),
                                               std::numeric_limits<double>::infinity());
    if (hits.size() < 2) continue;
    x.push_back(a);
    y.emplace_back(0.5 * (hits.front().point.y() + hits.back().point.y()));
  }
  require(x.size() >= 8, "cascade grid: the section is too thin to find its mid-line");
  const int poles = 6;
  fit_ = fit_least_squares<1>(y, x, 3, approximation_knots(x, 3, poles));
  lo_ = x.front();
  hi_ = x.back();
}

double MidLine::y(double a) const {
  const double c = std::clamp(a, lo_, hi_);
  Eigen::Matrix<double, 1, 1> d[2];
  fit_.derivatives(c, 1, d);
  return d[0][0] + d[1][0] * (a - c);
}

}  // namespace cg::grid::detail
