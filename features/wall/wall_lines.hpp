#pragma once
// Straight lines through the hollow blade: where a segment crosses the outer wall (the blade surface)
// and the core's inner wall, from the exact NURBS surfaces the B-rep faces carry (ray casting,
// src/algo/ray_surface.hpp). The turbulators, pin fins and trailing-edge slots use it to place their
// tools and for the independent expectation of the volume each tool adds or removes: that volume is
// the integral, over the tool's cross-section, of the length of each line inside the material (or inside
// the chamber), by Gauss-Legendre quadrature; it shares nothing with OCCT's boolean.
#include <Eigen/Core>
#include <map>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "src/algo/bounding_spans.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

/// Where a point lies in the hollow blade.
enum class Region { Outside, Material, Chamber, Any /* only as an expected end region: no check */ };

/// Intervals [t0, t1] of a segment's parameter t in [0, 1].
using Intervals = std::vector<std::pair<double, double>>;

/// Ray casting against the part of a surface near a segment. A ray caster visits every Bézier patch of
/// its surface per ray (the blade walls have hundreds), while a feature's lines meet a few: each query
/// goes to a caster of the rectangle of patches whose pole boxes the segment passes through (grown by one
/// patch all round), cached by rectangle, so the lines of one tool share one small caster. The patches
/// are the surface's own Bézier patches (the sub-surface is their Bézier form, same geometry), and a
/// crossing lies in the convex hull of the poles of its patch, so no crossing is lost. A rectangle may
/// run over a periodic seam (a line across the trailing edge meets both sides of the seam): its
/// patches past the seam carry parameters one period on, so a hit's u (v) may exceed the surface's
/// last_u (last_v) by less than a period (evaluation wraps it). Queries whose patches cover most of the
/// surface use the whole surface.
class LocalCaster {
 public:
  explicit LocalCaster(const BSplineSurface<3>& surface);
  /// The caster for the segment a -> b (valid until the next call).
  RaySurfaceCaster& for_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  /// Queries answered by a local caster / by the whole surface (for the tests and the bench).
  int local_queries = 0, full_queries = 0;

 private:
  int pu_, pv_, cols_ = 0, rows_ = 0;
  bool periodic_u_, periodic_v_;
  double tol_;
  double period_u_, period_v_;  // used where the direction is periodic
  std::vector<SurfaceBezierPatch<3>> patches_;  // u-major: column iu, row iv at iu * rows_ + iv
  RaySurfaceCaster full_;
  std::map<std::tuple<int, int, int, int>, std::unique_ptr<RaySurfaceCaster>> cache_;
  std::vector<char> col_hit_, row_hit_;
};

/// Segment queries against the outer and the inner wall. One per thread (ray casters keep work buffers);
/// the inner surface must outlive it.
class WallLines {
 public:
  WallLines(const BSplineSurface<3>& outer, const BSplineSurface<3>& inner);

  /// Sorted parameters t in [0, 1] where a + t (b - a) crosses the outer / the inner wall.
  std::vector<double> outer_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  std::vector<double> inner_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

  /// The parts of the segment a -> b in `wanted`, given the region of a (each crossing of the outer wall
  /// toggles outside / inside the blade, each crossing of the inner wall material / chamber). `end`
  /// receives the region reached at b, so a caller can check its assumption about both ends.
  /// chamber = false: the segment cannot reach the chamber, the inner wall is not searched.
  Intervals intervals(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Region start, Region wanted, Region* end = nullptr,
                      bool chamber = true);

  /// Unit normal of the inner wall where the segment a -> b first crosses it (zero when it does not).
  Eigen::Vector3d inner_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

 private:
  std::vector<double> crossings(LocalCaster& caster, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  LocalCaster outer_, inner_;
  const BSplineSurface<3>* inner_surface_;
};

/// Total length fraction of intervals (sum of t1 - t0).
double total(const Intervals& iv);

}  // namespace cg::features
