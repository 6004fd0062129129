#pragma once
// Blade-relative coordinates, so that cooling features move with the blade:
//   span   = span fraction = surface v (0 hub, 1 casing; the over-build extends it slightly beyond);
//   chord  = chordwise coordinate in [-1, 1]: 0 at the LE, (0, 1] over the suction side to the TE,
//            [-1, 0) over the pressure side (c = +1 and c = -1 are both the TE). It is piecewise linear in
//            the surface u (see blade_surface.hpp) and equals the arc-length fraction of the side at the
//            sampled section points;
//   depth  = distance into the wall along the inward normal, mm (0 on the surface, > 0 inside).
// point = S(u, v) - depth * n(u, v), n the outward unit normal.
#include <Eigen/Core>
#include <memory>

#include "src/blade/blade_surface.hpp"

namespace cg {
class SurfaceProjector;
}

namespace cg::blade {

struct BladeCoordinate {
  double span = 0;
  double chord = 0;
  double depth = 0;
};

/// Local frame at a surface point.
struct BladeFrame {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();          // on the surface (depth 0)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();         // outward unit normal
  Eigen::Vector3d span_tangent = Eigen::Vector3d::Zero();   // unit dS/dv (hub -> casing)
  Eigen::Vector3d chord_tangent = Eigen::Vector3d::Zero();  // unit dS/du (LE -> TE on the suction side,
                                                            // TE -> LE on the pressure side)
};

struct BladeLocateResult {
  bool found = false;
  BladeCoordinate coordinate;
  double u = 0, v = 0;  // surface parameters of the foot point
};

/// One per thread (locate() reuses the projector's work buffers); the model must outlive it.
class BladeCoordinates {
 public:
  explicit BladeCoordinates(const BladeModel& model);
  ~BladeCoordinates();
  BladeCoordinates(const BladeCoordinates&) = delete;
  BladeCoordinates& operator=(const BladeCoordinates&) = delete;

  BladeFrame frame(double span, double chord) const;
  Eigen::Vector3d point(const BladeCoordinate& c) const;
  /// Inverse by global orthogonal projection onto the surface (src/algo/project_point_surface).
  /// found=false when the closest point lies on the over-build end (v at the domain boundary with the point
  /// beyond it). Exact inverse of point() while depth is below the local half-thickness and radius of
  /// curvature (the closest surface point is then the one the point was built from).
  BladeLocateResult locate(const Eigen::Vector3d& p) const;

  const BladeModel& model() const { return *model_; }

 private:
  const BladeModel* model_;
  double normal_sign_ = 1;  // +1 when S_u x S_v points outward
  std::unique_ptr<SurfaceProjector> projector_;
};

}  // namespace cg::blade
