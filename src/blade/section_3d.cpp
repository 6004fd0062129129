#include "src/blade/section_3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade::detail {

BSplineCurve<3> section_in_plane(const BSplineCurve<2>& c, double z) {
  const auto& h = c.homogeneous_poles();
  BSplineCurve<3>::HPoles g(4, h.cols());
  g.row(0) = h.row(0);
  g.row(1) = h.row(1);
  g.row(2) = z * h.row(2);  // homogeneous: w z
  g.row(3) = h.row(2);
  return BSplineCurve<3>::from_homogeneous(c.degree(), c.knots(), std::move(g), c.is_periodic());
}

MappedSection map_closed_section(const BSplineCurve<2>& curve,
                                 const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& F, double tol,
                                 int min_points) {
  require(curve.is_periodic(), "map_closed_section: the section curve must be closed (periodic)");
  require(tol > 0, "map_closed_section: tolerance must be > 0");
  // Distinct knots of one period [first, first + T).
  std::vector<double> breaks;
  const auto& U = curve.knots();
  for (int i = curve.degree(); i < curve.num_poles(); ++i) {
    const double k = U[static_cast<std::size_t>(i)];
    if (breaks.empty() || k > breaks.back()) breaks.push_back(k);
  }
  const double first = curve.first_param(), T = curve.period();
  breaks.push_back(first + T);
  const int spans = static_cast<int>(breaks.size()) - 1;
  int m = 1;
  while (m * spans < min_points) m *= 2;
  for (; m <= 4096; m *= 2) {
    std::vector<double> params;
    std::vector<Eigen::Vector3d> pts;
    for (int s = 0; s < spans; ++s)
      for (int k = 0; k < m; ++k) {
        const double t = breaks[static_cast<std::size_t>(s)] +
                         (breaks[static_cast<std::size_t>(s) + 1] - breaks[static_cast<std::size_t>(s)]) * k / m;
        params.push_back((t - first) / T);  // period 1 from the start of C's domain
        pts.push_back(F(curve.point(t)));
      }
    const std::vector<double> knots = periodic_interpolation_knots(params, 3);
    BSplineCurve<3> c3 = interpolate_closed<3>(pts, 3, params, knots);
    double err = 0;
    for (std::size_t i = 0; i < params.size(); ++i) {
      const double a = params[i], b = i + 1 < params.size() ? params[i + 1] : 1.0;
      for (double f : {0.25, 0.5, 0.75}) {
        const double v = a + f * (b - a);
        err = std::max(err, (c3.point(v) - F(curve.point(first + v * T))).norm());
      }
    }
    if (err <= tol) return {std::move(c3), err, m};
  }
  throw AlgorithmFailure("map_closed_section: the placed section could not be interpolated to " + std::to_string(tol) +
                         " mm with 4096 intervals per knot span");
}

}  // namespace cg::blade::detail
