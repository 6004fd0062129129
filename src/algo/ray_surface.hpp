#pragma once
// First intersection of a 3D ray with a B-spline / NURBS surface.
//
// Method: the surface's Bézier patches whose pole boxes the ray enters (slab test) and whose poles
// straddle each of four planes through the line (convex hull: otherwise the patch cannot meet it) are
// kept in a queue ordered by the ray parameter at which the ray enters the box. The nearest one is
// taken: a patch that is not yet nearly planar (poles within 2% of the patch size from the plane of its
// corners, weights within 2%) is split by de Casteljau along its longer direction (Nishita et al.
// 1990 use the same convex hull argument with Bézier clipping); a nearly planar one is solved by
// Newton's method on the 3x3 system o + s d - S(u, v) = 0 (J = [d, -S_u, -S_v]) from its centre, and
// a root inside the patch is a hit. A patch is done with its hit only when it provably meets the line
// at most once: its homogeneous projection along d onto a plane is injective, shown by determinants of
// one strict sign for every pair of control point differences along u and v (see meets_line_once in
// the .cpp). Any other patch - Newton did not settle inside it, or it may be met twice - is split
// further while the ray runs inside its box before the best hit, down to 2^-30 of a knot patch. The
// search stops when the next box is entered beyond the best hit, so the hit returned is the first
// along the ray. A ray grazing the surface within that resolution can be reported as a miss. The knot
// patches the ray may enter are found through a tree of their boxes (median splits along the longest
// axis, up to 4 patches a leaf): a parent's box holds its children's, so the patches queued are exactly
// those whose own box the ray enters, while the boxes tested are those along the ray rather than all of
// the surface's patches (thousands on a blade's inner wall).
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <vector>

#include "src/algo/bounding_spans.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

struct RaySurfaceHit {
  bool found = false;
  double ray_param = 0.0;  // s: the hit is origin + s * direction
  double u = 0.0, v = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // S(u, v)
  double gap = 0.0;                                 // |origin + s d - S(u, v)| (rounding)
};

/// Precomputed ray casting against one surface (patches and their boxes). It shares ownership of a
/// copy of the surface (never dangles); a query mutates work buffers, so one caster per thread.
class RaySurfaceCaster {
 public:
  /// tolerance <= 0: 1e-12 * (1 + diagonal of the surface's box) (Newton residual for a hit).
  explicit RaySurfaceCaster(const BSplineSurface<3>& surface, double tolerance = 0.0);

  /// First hit of origin + s * direction, s in [0, s_max]. Throws InvalidGeometry for a zero or
  /// non-finite direction.
  RaySurfaceHit first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                          double s_max = std::numeric_limits<double>::infinity());

 private:
  struct Item {
    double entry;
    double u0, u1, v0, v1;
    int depth;
    std::size_t block;  // index of the poles in pool_
    bool operator>(const Item& o) const { return entry > o.entry; }
  };
  struct Node {
    BoundingBox<3> box;
    int begin = 0, end = 0;     // patches order_[begin, end)
    int left = -1, right = -1;  // children (a leaf has none)
  };
  bool newton(const Item& it, const Eigen::Vector3d& o, const Eigen::Vector3d& d, RaySurfaceHit& hit);
  std::size_t new_block();
  int build_tree(int begin, int end);

  std::shared_ptr<const BSplineSurface<3>> s_;
  int pu_ = 0, pv_ = 0;
  double tol_ = 0, scale_ = 0;
  std::vector<SurfaceBezierPatch<3>> patches_;
  std::vector<Node> nodes_;  // nodes_[0] is the root (when there are patches)
  std::vector<int> order_;   // patch indices, each node's a contiguous range
  std::vector<int> stack_;   // work buffer of the tree walk
  std::vector<double> pool_;
  std::vector<std::size_t> free_;
  std::vector<Item> heap_;
  std::vector<double> left_, right_, hp_, cu_;  // work buffers, reused across calls
};

/// First hit (builds a RaySurfaceCaster).
RaySurfaceHit ray_surface_first_hit(const BSplineSurface<3>& surface, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& direction,
                                    double s_max = std::numeric_limits<double>::infinity());

/// Sorted parameters t in [0, 1] where the segment a -> b crosses the caster's surface: first hits, each
/// search restarted 1e-9 mm past the last hit (far below any feature, far above a hit's rounding); more
/// than 64 (a segment grazing the surface) end the search. Empty for a zero-length segment.
std::vector<double> segment_crossings(RaySurfaceCaster& caster, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace cg
