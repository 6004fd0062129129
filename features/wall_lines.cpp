#include "features/wall_lines.hpp"

#include <algorithm>

namespace cg::features {

namespace detail {
const double kGauss8Nodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
const double kGauss8Weights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                  0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
}  // namespace detail

WallLines::WallLines(const BSplineSurface<3>& outer, const BSplineSurface<3>& inner)
    : outer_(outer), inner_(inner), inner_surface_(&inner) {}

Eigen::Vector3d WallLines::inner_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double len = (b - a).norm();
  const RaySurfaceHit h = inner_.first_hit(a, (b - a) / len, len);
  return h.found ? inner_surface_->normal(h.u, h.v) : Eigen::Vector3d::Zero();
}

std::vector<double> WallLines::crossings(RaySurfaceCaster& caster, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  std::vector<double> out;
  const double len = (b - a).norm();
  if (!(len > 0)) return out;
  const Eigen::Vector3d d = (b - a) / len;
  // Restart just past each hit (1e-9 mm: far below any feature, far above the hit's rounding).
  constexpr double kStep = 1e-9;
  double s = 0;
  while (s < len) {
    const RaySurfaceHit h = caster.first_hit(a + s * d, d, len - s);
    if (!h.found) break;
    s += h.ray_param;
    out.push_back(s / len);
    s += kStep;
    if (out.size() > 64) break;  // a line grazing a surface: the caller's region check fails
  }
  return out;
}

std::vector<double> WallLines::outer_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return crossings(outer_, a, b);
}
std::vector<double> WallLines::inner_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return crossings(inner_, a, b);
}

Intervals WallLines::intervals(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Region start, Region wanted,
                               Region* end, bool chamber) {
  std::vector<std::pair<double, bool>> events;  // (t, true: outer wall)
  for (double t : outer_crossings(a, b)) events.emplace_back(t, true);
  if (chamber)
    for (double t : inner_crossings(a, b)) events.emplace_back(t, false);
  std::sort(events.begin(), events.end());
  // The chamber lies inside the blade: the two toggles are tracked separately.
  bool in_blade = start != Region::Outside, in_chamber = start == Region::Chamber;
  auto region = [&] { return !in_blade ? Region::Outside : in_chamber ? Region::Chamber : Region::Material; };
  Intervals out;
  double t0 = 0;
  for (const auto& [t, outer] : events) {
    if (region() == wanted && t > t0) out.emplace_back(t0, t);
    (outer ? in_blade : in_chamber) = !(outer ? in_blade : in_chamber);
    t0 = t;
  }
  if (region() == wanted && t0 < 1) out.emplace_back(t0, 1.0);
  if (end) *end = region();
  return out;
}

double total(const Intervals& iv) {
  double s = 0;
  for (const auto& [a, b] : iv) s += b - a;
  return s;
}

}  // namespace cg::features
