#include "src/blade_import/outline_checks.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "src/core/constants.hpp"

namespace cg::blade_import {

std::optional<OutlineFault> run_fault(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& lines, bool closed,
                                      const std::string& subject, const std::string& order) {
  const std::size_t n = p.size(), segments = closed ? n : n - 1;
  for (std::size_t i = 0; i < segments; ++i) {
    const std::size_t a = (i + 1) % n, c = (i + 2) % n;
    if ((p[a] - p[i]).norm() < 1e-6)
      return OutlineFault{lines[a], "duplicated point: " + subject + "'s points at lines " + std::to_string(lines[i]) +
                                        " and " + std::to_string(lines[a]) + " coincide"};
    if (!closed && i + 2 >= n) continue;
    const Eigen::Vector3d d0 = (p[a] - p[i]).normalized(), d1 = (p[c] - p[a]).normalized();
    if ((p[c] - p[a]).norm() >= 1e-6 && d0.dot(d1) < std::cos(135.0 * kPi / 180))
      return OutlineFault{lines[a], "points out of order: " + subject + " turns back at line " + std::to_string(lines[a]) +
                                        " (points must run " + order + ")"};
  }
  return std::nullopt;
}

std::optional<OutlineFault> crossing_fault(const std::vector<Eigen::Vector3d>& loop, const std::vector<int>& lines) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : loop) c += p;
  c /= static_cast<double>(loop.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : loop) cov += (p - c) * (p - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  const Eigen::Vector3d e1 = es.eigenvectors().col(2), e2 = es.eigenvectors().col(1);
  std::vector<Eigen::Vector2d> q;
  for (const auto& p : loop) q.emplace_back((p - c).dot(e1), (p - c).dot(e2));
  const std::size_t n = q.size();
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a0 = q[i], a1 = q[(i + 1) % n];
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing segment
      const Eigen::Vector2d b0 = q[j], b1 = q[(j + 1) % n];
      const double d1 = cross(a1 - a0, b0 - a0), d2 = cross(a1 - a0, b1 - a0);
      const double d3 = cross(b1 - b0, a0 - b0), d4 = cross(b1 - b0, a1 - b0);
      if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0)
        return OutlineFault{lines[i], "the outline crosses itself: the segment from line " + std::to_string(lines[i]) + " to " +
                                          std::to_string(lines[(i + 1) % n]) + " crosses the one from line " +
                                          std::to_string(lines[j]) + " to " + std::to_string(lines[(j + 1) % n])};
    }
  }
  return std::nullopt;
}

}  // namespace cg::blade_import
