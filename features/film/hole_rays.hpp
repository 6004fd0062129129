#pragma once
// Ray casting for the bundles of parallel or nearly parallel lines of one hole (hole_analysis.cpp,
// insert jets): near a crossing already found, Newton's method on o + s d - S(u, v) = 0
// (J = [d, -S_u, -S_v]) from the seed crossing's (u, v) takes a few surface evaluations instead of a
// global search (src/algo/ray_surface.hpp). A Newton root is accepted only if it crosses the surface in
// the same sense as the seed (sign of d . (S_u x S_v)), so it is the crossing near the seed and not the
// surface's other side, and lies in the window [s_lo, s_hi] of the ray; otherwise the global caster
// (first hit beyond s_lo) decides.
#include <Eigen/Core>

#include "src/algo/ray_surface.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

class NearCaster {
 public:
  explicit NearCaster(const BSplineSurface<3>& s) : s_(&s), global_(s) {}
  /// Global first hit (src/algo/ray_surface.hpp).
  RaySurfaceHit first(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double s_max) { return global_.first_hit(o, d, s_max); }
  /// The crossing near `seed` (see above); falls back to the global first hit beyond s_lo.
  RaySurfaceHit near(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const RaySurfaceHit& seed, double sense,
                     double s_lo, double s_hi, double s_max);
  /// Unit normal at a hit.
  Eigen::Vector3d normal(const RaySurfaceHit& h) const { return s_->normal(h.u, h.v); }
  /// The sense of a crossing: sign of d . (S_u x S_v) at the hit.
  double sense(const Eigen::Vector3d& d, const RaySurfaceHit& h) const;
  int fallbacks = 0;  ///< calls that needed the global search

 private:
  bool wrap(double& u, double& v) const;
  const BSplineSurface<3>* s_;
  RaySurfaceCaster global_;
};

/// Foot point of p on a surface by Newton's method on the distance, from (u, v); false when Newton does
/// not settle inside the domain. A local minimum: callers check it is the closest point where that matters.
bool foot_near(const BSplineSurface<3>& s, const Eigen::Vector3d& p, double& u, double& v);

}  // namespace cg::features
