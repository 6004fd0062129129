#include "src/mesh/mesh_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cg::mesh {

double tet_volume(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  return (p1 - p0).dot((p2 - p0).cross(p3 - p0)) / 6.0;
}

double tet_radius_ratio(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  const double v = std::abs(tet_volume(p0, p1, p2, p3));
  if (!(v > 0)) return 0;
  const double area = 0.5 * ((p1 - p0).cross(p2 - p0).norm() + (p1 - p0).cross(p3 - p0).norm() +
                             (p2 - p0).cross(p3 - p0).norm() + (p2 - p1).cross(p3 - p1).norm());
  const double r_in = 3 * v / area;
  // Opposite edge pairs: (01, 23), (02, 13), (03, 12).
  const double aA = (p1 - p0).norm() * (p3 - p2).norm(), bB = (p2 - p0).norm() * (p3 - p1).norm(),
               cC = (p3 - p0).norm() * (p2 - p1).norm();
  const double prod = (aA + bB + cC) * (aA + bB - cC) * (aA - bB + cC) * (-aA + bB + cC);
  if (!(prod > 0)) return 0;
  const double r_circ = std::sqrt(prod) / (24 * v);
  return std::clamp(3 * r_in / r_circ, 0.0, 1.0);
}

TetQuality tet_quality(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<std::size_t, 4>>& tets) {
  TetQuality q;
  q.elements = tets.size();
  if (tets.empty()) return q;
  q.min_quality = 1;
  double sum = 0;
  for (const auto& t : tets) {
    const auto& a = points[t[0]];
    const auto& b = points[t[1]];
    const auto& c = points[t[2]];
    const auto& d = points[t[3]];
    const double v = tet_volume(a, b, c, d);
    q.volume += v;
    if (!(v > 0)) ++q.inverted;
    const double rho = tet_radius_ratio(a, b, c, d);
    q.min_quality = std::min(q.min_quality, rho);
    sum += rho;
    ++q.histogram[rho < 0.1 ? 0 : rho < 0.2 ? 1 : rho < 0.3 ? 2 : rho < 0.5 ? 3 : 4];
  }
  q.mean_quality = sum / static_cast<double>(tets.size());
  return q;
}

}  // namespace cg::mesh
