#pragma once
// Geometry of one drilled hole, with our own kernel: where the hole's cylinder meets a wall surface
// (the loop), fitted as curves an edge can carry, and the volume the hole removes from a wall.
//
// A hole is the cylinder C(theta, t) = o + r (cos theta e1 + sin theta e2) + t d (d = unit axis,
// e2 = d x e1, the frame of OCCT's gp_Ax3(o, d, e1), so theta and t are the parameters of
// Geom_CylindricalSurface). Its ruling line at angle theta meets a thin wall's surface once, at t(theta)
// and S(u(theta), v(theta)); that is the loop. Newton on line(t) - S(u, v) = 0 (src/core/newton.hpp),
// started at the axis hit found by ray casting (src/algo/ray_surface.hpp) and continued outwards and
// around the circle, follows it (the marching of Barnhill & Kersey's surface/surface intersection with
// the cylinder's angle as the marching parameter, which needs no step control: every ruling is
// solved exactly).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

#include "src/algo/ray_surface.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/surface_evaluator.hpp"

namespace cg::features {

/// The cylinder of a hole: origin o (tool start), unit axis d, frame e1, e2 = d x e1, radius, length.
struct HoleCylinder {
  Eigen::Vector3d o, d, e1, e2;
  double radius = 0, length = 0;
  Eigen::Vector3d ruling(double theta, double rho) const {
    return o + rho * (std::cos(theta) * e1 + std::sin(theta) * e2);
  }
  /// A frame for an axis (e1 perpendicular to d, fixed rule so results are reproducible).
  static HoleCylinder from_axis(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double radius,
                                double length);
};

/// A B-spline wall surface prepared for line queries. Not thread-safe (work buffers): one per thread.
class WallSurface {
 public:
  explicit WallSurface(std::shared_ptr<const BSplineSurface<3>> surface);
  const BSplineSurface<3>& surface() const { return *surface_; }
  /// Newton on p + t d = S(u, v) from (t, u, v); the parameters stay clamped to the domain (no wrap:
  /// a loop crossing a periodic seam is not followed). True when settled with |residual| <= 1e-10 mm.
  bool solve(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double& t, double& u, double& v);
  /// First hit of the ray p + t d, t in [0, t_max] (global search).
  RaySurfaceHit first_hit(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double t_max);
  Eigen::Vector3d point(double u, double v) { return ev_.point(u, v); }
  Eigen::Vector3d unit_normal(double u, double v);

 private:
  std::shared_ptr<const BSplineSurface<3>> surface_;
  SurfaceEvaluator<3> ev_;
  RaySurfaceCaster caster_;
};

/// A hit of the hole axis with a wall (start of every march).
struct AxisHit {
  double t = 0, u = 0, v = 0;
};

/// The loop of a hole on one wall, as the three curves of its edge, all periodic in s in [0, 1]
/// (theta = 2 pi s), interpolating the exact loop at s_k = k / nodes.
struct HoleLoop {
  bool ok = false;
  std::string failure;         ///< why not (Newton lost the loop, grazing incidence, ...)
  int nodes = 0;
  BSplineCurve<3> curve;       ///< 3D
  BSplineCurve<2> pcurve;      ///< (u, v) on the wall surface
  /// (theta, t) on the cylinder, for s in [0, 1]: periodic interpolant of t(s) in y; x is replaced by
  /// 2 pi s exactly when it becomes an OCCT curve (drill_hole_topology.cpp).
  BSplineCurve<2> cylinder_pcurve;
  double deviation = 0;        ///< mm, max distance of the three curves from the exact loop (between nodes)
  double min_sin_incidence = 1;  ///< min over the nodes of |d . n|
  double t_min = 0, t_max = 0;   ///< range of t(theta) at the nodes
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< the loop point at theta = 0
};

/// Follows and fits the loop of `hole` on `wall` from the axis hit; doubles the nodes from 32 up to
/// 512 until `deviation` <= fit_tolerance. ok = false with a reason when the loop cannot be followed.
HoleLoop hole_loop(WallSurface& wall, const HoleCylinder& hole, const AxisHit& axis_hit, double fit_tolerance);

/// Points of the ring of radius `rho` (> radius: a margin ring) on `wall`, as (u, v) at `count`
/// angles; false when Newton fails.
bool ring_parameters(WallSurface& wall, const HoleCylinder& hole, const AxisHit& axis_hit, double rho, int count,
                     std::vector<Eigen::Vector2d>& uv);

/// The volume between two walls inside the hole: integral over the hole's cross-section disk of
/// t_exit - t_entry of the axis-parallel line, Gauss-Legendre (8 nodes, weight rho) in the radius x
/// trapezoid (`angles`, exponentially convergent for the smooth periodic integrand) in the angle.
/// NaN when a line cannot be solved.
double quadrature_volume(WallSurface& entry, const AxisHit& entry_hit, WallSurface& exit, const AxisHit& exit_hit,
                         const HoleCylinder& hole, int angles = 48);

}  // namespace cg::features
