#include "src/mesh/size_field.hpp"

#include <algorithm>

namespace cg::mesh {
namespace {

constexpr int kLeafSamples = 8;

double box_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (x.cwiseMax(lo).cwiseMin(hi) - x).norm();
}

}  // namespace

GradedSizeField::GradedSizeField(std::vector<Sample> samples, double growth, double max_size)
    : samples_(std::move(samples)), growth_(growth), max_size_(max_size) {
  if (!samples_.empty()) {
    nodes_.reserve(2 * samples_.size() / kLeafSamples + 2);
    build(0, static_cast<int>(samples_.size()));
  }
}

// Node over samples_[begin, end): split at the median of the longest box side.
int GradedSizeField::build(int begin, int end) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Node n;
  n.begin = begin;
  n.end = end;
  n.lo = n.hi = samples_[static_cast<std::size_t>(begin)].point;
  n.min_size = samples_[static_cast<std::size_t>(begin)].size;
  for (int i = begin; i < end; ++i) {
    const Sample& s = samples_[static_cast<std::size_t>(i)];
    n.lo = n.lo.cwiseMin(s.point);
    n.hi = n.hi.cwiseMax(s.point);
    n.min_size = std::min(n.min_size, s.size);
  }
  if (end - begin > kLeafSamples) {
    int axis = 0;
    (n.hi - n.lo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(samples_.begin() + begin, samples_.begin() + mid, samples_.begin() + end,
                     [axis](const Sample& a, const Sample& b) { return a.point[axis] < b.point[axis]; });
    n.left = build(begin, mid);
    n.right = build(mid, end);
  }
  nodes_[static_cast<std::size_t>(id)] = n;
  return id;
}

void GradedSizeField::search(int id, const Eigen::Vector3d& x, double& best) const {
  const Node& n = nodes_[static_cast<std::size_t>(id)];
  if (n.min_size + growth_ * box_distance(x, n.lo, n.hi) >= best) return;
  if (n.left < 0) {
    for (int i = n.begin; i < n.end; ++i) {
      const Sample& s = samples_[static_cast<std::size_t>(i)];
      best = std::min(best, s.size + growth_ * (x - s.point).norm());
    }
    return;
  }
  // Nearer child first: its bound is usually the tighter one.
  const Node& l = nodes_[static_cast<std::size_t>(n.left)];
  const Node& r = nodes_[static_cast<std::size_t>(n.right)];
  const bool left_first = l.min_size + growth_ * box_distance(x, l.lo, l.hi) <= r.min_size + growth_ * box_distance(x, r.lo, r.hi);
  search(left_first ? n.left : n.right, x, best);
  search(left_first ? n.right : n.left, x, best);
}

double GradedSizeField::operator()(const Eigen::Vector3d& x) const {
  double best = max_size_;
  if (!nodes_.empty()) search(0, x, best);
  return best;
}

}  // namespace cg::mesh
