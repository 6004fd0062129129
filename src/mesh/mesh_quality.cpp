#include "src/mesh/mesh_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_map>

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

namespace {

// A triangle as its sorted node triple.
struct TriKey {
  std::size_t a, b, c;
  bool operator==(const TriKey& o) const { return a == o.a && b == o.b && c == o.c; }
};
struct TriHash {
  std::size_t operator()(const TriKey& k) const {
    std::size_t h = k.a * 0x9E3779B97F4A7C15ull;
    h ^= k.b + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= k.c + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    return h;
  }
};
TriKey key(std::size_t a, std::size_t b, std::size_t c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

}  // namespace

std::size_t nonconformal_triangles(const std::vector<InterfaceTriangle>& interface,
                                   const std::vector<const std::vector<std::array<std::size_t, 4>>*>& blocks) {
  // For each interface triangle: which of its two blocks have a tetrahedron with it as a face (bit 0, 1).
  std::unordered_map<TriKey, std::pair<std::size_t, unsigned>, TriHash> seen;
  seen.reserve(2 * interface.size());
  for (std::size_t i = 0; i < interface.size(); ++i) seen[key(interface[i].nodes[0], interface[i].nodes[1], interface[i].nodes[2])] = {i, 0u};
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (const auto& t : *blocks[b])
      for (int skip = 0; skip < 4; ++skip) {
        std::size_t n[3], k = 0;
        for (int j = 0; j < 4; ++j)
          if (j != skip) n[k++] = t[static_cast<std::size_t>(j)];
        const auto it = seen.find(key(n[0], n[1], n[2]));
        if (it == seen.end()) continue;
        const InterfaceTriangle& f = interface[it->second.first];
        if (f.blocks[0] == b) it->second.second |= 1u;
        if (f.blocks[1] == b) it->second.second |= 2u;
      }
  std::size_t bad = 0;
  for (const auto& [k, v] : seen) bad += v.second != 3u;
  // A triangle listed twice (the same node triple on two interface faces) counts once in `seen`: count
  // the duplicates as non-conformal too, since two faces cannot share a triangle.
  return bad + (interface.size() - seen.size());
}

}  // namespace cg::mesh
