#pragma once
// The element size near the small features of a cooled blade, graded into the rest of the part:
//
//   h(x) = min(max_size, min over samples s of (h_s + growth * |x - s|))
//
// Samples lie along the boundary curves of the cooling features (film holes, fillets, pins, ...), each
// with the size its feature needs (blade_mesher.cpp: 2 pi rho / N). Away from a feature the size grows
// linearly at `growth` (0.25: the next element along a ray is at most ~25 % larger than the previous
// one) until it reaches max_size. gmsh calls this through gmsh::model::mesh::setSizeCallback for curves,
// surfaces and volumes instead of extending boundary sizes across a face by interpolation: on a wall
// pierced by many small holes that interpolation fills the whole face with the holes' size (the built-in
// example's outer wall got 2.3 M triangles that way).
//
// Queries are exact (no sampling of the field itself): a k-d tree over the samples, each node with its
// bounding box and its smallest h, searched branch and bound (a node is skipped when
// h_min(node) + growth * distance(x, box) cannot beat the best so far). The field is immutable after
// construction, so concurrent queries from gmsh's threads are safe.
#include <Eigen/Core>
#include <vector>

namespace cg::mesh {

class GradedSizeField {
 public:
  struct Sample {
    Eigen::Vector3d point;
    double size = 0;  ///< mm, > 0
  };

  /// `growth` > 0 (size increase per unit distance), `max_size` > 0 (mm). No samples: max_size everywhere.
  GradedSizeField(std::vector<Sample> samples, double growth, double max_size);

  /// h(x) as above, mm. Thread-safe.
  double operator()(const Eigen::Vector3d& x) const;

  std::size_t samples() const { return samples_.size(); }

 private:
  struct Node {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  ///< bounding box of its samples
    double min_size = 0;
    int begin = 0, end = 0;  ///< samples_[begin, end)
    int left = -1, right = -1;
  };
  int build(int begin, int end);
  void search(int node, const Eigen::Vector3d& x, double& best) const;

  std::vector<Sample> samples_;
  std::vector<Node> nodes_;
  double growth_, max_size_;
};

}  // namespace cg::mesh
