#include "src/mesh/zone_boundaries.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

#include "src/mesh/coolant_domain.hpp"

namespace cg::mesh {
namespace {

using Key = std::array<std::size_t, 3>;  // node indices, ascending

Key key(std::size_t a, std::size_t b, std::size_t c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = k[0];
    for (int i = 1; i < 3; ++i) h ^= k[static_cast<std::size_t>(i)] + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
  }
};

// A tetrahedron that has the triangle as a face: its block and its fourth node.
struct Side {
  int block = 0;
  std::size_t opposite = 0;
};

// The tetrahedra on each side of every triangle (at most two).
std::vector<std::vector<Side>> triangle_sides(const MeshData& d) {
  std::unordered_map<Key, std::size_t, KeyHash> index;
  index.reserve(d.triangles.size());
  std::vector<char> on_boundary(d.points.size(), 0);
  for (std::size_t i = 0; i < d.triangles.size(); ++i) {
    const auto& n = d.triangles[i].nodes;
    if (!index.emplace(key(n[0], n[1], n[2]), i).second)
      throw MeshError("mesh: boundary triangle " + std::to_string(i) + " is listed twice");
    for (std::size_t v : n) on_boundary[v] = 1;
  }
  // Face f of a tetrahedron leaves out node 3 - f.
  static constexpr int kFace[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  std::vector<std::vector<Side>> sides(d.triangles.size());
  for (std::size_t b = 0; b < d.blocks.size(); ++b)
    for (const auto& t : d.blocks[b].tets)
      for (int f = 0; f < 4; ++f) {
        const std::size_t p = t[kFace[f][0]], q = t[kFace[f][1]], r = t[kFace[f][2]];
        if (!on_boundary[p] || !on_boundary[q] || !on_boundary[r]) continue;
        const auto it = index.find(key(p, q, r));
        if (it == index.end()) continue;
        auto& s = sides[it->second];
        if (s.size() == 2) throw MeshError("mesh: boundary triangle " + std::to_string(it->second) + " is a face of more than two tetrahedra");
        s.push_back({static_cast<int>(b), t[static_cast<std::size_t>(3 - f)]});
      }
  return sides;
}

}  // namespace

ZoneBoundaries zone_boundaries(const MeshData& d) {
  const std::vector<std::vector<Side>> sides = triangle_sides(d);
  ZoneBoundaries z;
  std::vector<std::map<std::pair<int, int>, BoundaryPatch>> patches(d.blocks.size());
  for (std::size_t i = 0; i < d.triangles.size(); ++i) {
    const auto& s = sides[i];
    if (s.empty()) throw MeshError("mesh: boundary triangle " + std::to_string(i) + " is a face of no tetrahedron");
    if (s.size() == 2 && s[0].block == s[1].block) {
      ++z.inner_triangles;
      continue;
    }
    for (std::size_t k = 0; k < s.size(); ++k) {
      const int partner = s.size() == 2 ? s[1 - k].block : -1;
      std::array<std::size_t, 3> n = d.triangles[i].nodes;
      const Eigen::Vector3d& a = d.points[n[0]];
      const Eigen::Vector3d normal = (d.points[n[1]] - a).cross(d.points[n[2]] - a);
      if (normal.dot(d.points[s[k].opposite] - a) > 0) std::swap(n[1], n[2]);  // point away from the tetrahedron
      BoundaryPatch& p = patches[static_cast<std::size_t>(s[k].block)][{d.triangles[i].group, partner}];
      p.group = d.triangles[i].group;
      p.partner = partner;
      p.triangles.push_back(n);
    }
  }
  z.regions.resize(d.blocks.size());
  for (std::size_t b = 0; b < d.blocks.size(); ++b)
    for (auto& [key_, p] : patches[b]) z.regions[b].patches.push_back(std::move(p));
  return z;
}

}  // namespace cg::mesh
