#pragma once
// End walls of the hollow core: the flow path's hub and casing surfaces shifted along their normals.
//
// A straight vane ends at the planes z = hub_z and z = casing_z; a shifted plane is a plane. A meridional
// blade ends at surfaces of revolution of the hub and casing contours (x, r); the offset of a surface of
// revolution by d (true mm, normal to it) is the surface of revolution of the contour's 2D offset by d in
// the (x, r) plane, so it is built from the exact 2D offset (src/algo/offset_exact.hpp) approximated by a
// cubic B-spline within the tolerance (src/fit/approximate.hpp).
//
// Used for the tip cap (casing shifted into the flow path by the cap thickness), the hub floor (hub
// shifted by the floor thickness), the cutting ends of tools that must pass through an end (shifted
// out of the flow path) and distances to them (turnaround gaps).
#include <Eigen/Core>
#include <memory>

#include "features/passages/passage_definition.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg {
template <int Dim>
class CurveProjector;
}

namespace cg::features {

class EndWall {
 public:
  /// The hub (end = Hub) or casing (end = Tip) surface of `model`'s flow path, shifted by `shift` mm
  /// along its normal into the flow path (shift > 0) or out of it (shift < 0). Throws InvalidGeometry
  /// when the shifted contour degenerates (shift beyond the contour's radius of curvature).
  EndWall(const blade::BladeModel& model, SpanEnd end, double shift, double tolerance = 1e-4);
  ~EndWall();
  EndWall(const EndWall& other);
  EndWall& operator=(const EndWall& other);

  /// The surface as a trim for the solid builders (src/brep/blade_solid.hpp).
  brep::EndTrim trim() const;
  /// Signed distance from the surface, mm: > 0 on the side of the other end wall (inside the flow
  /// path for an unshifted wall). For a surface of revolution: the distance in the (x, r) plane.
  double signed_distance(const Eigen::Vector3d& p) const;
  /// Unit normal at the foot point of p, pointing to the positive side.
  Eigen::Vector3d normal_at(const Eigen::Vector3d& p) const;

  SpanEnd end() const { return end_; }
  double shift() const { return shift_; }
  bool straight() const { return straight_; }

 private:
  SpanEnd end_;
  double shift_;
  bool straight_;
  double z_ = 0, sense_ = 1;  // straight: plane z = z_, positive side sense_ * (z - z_) > 0
  BSplineCurve<2> contour_;   // meridional: the shifted contour (x, r)
  std::unique_ptr<CurveProjector<2>> projector_;
};

}  // namespace cg::features
