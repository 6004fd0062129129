#pragma once
// The surface a span section of a blade lies on, for the section drawing, the passage table and the
// design checks' cross-sections alike (features/passages/span_sections.hpp):
//  - straight vane: the plane at the span height, z = hub_z + span (casing_z - hub_z);
//  - meridional blade (rotor): the surface of revolution of the meridional streamline at that span
//    about the x axis, over theta_centre +- 90 deg (theta_centre: the blade's mean angle atan2(z, y) at
//    that span). It follows the blade's span coordinate along the whole chord, so a section at span s
//    keeps the same distance from hub and casing (end walls) from LE to TE, and is normal to the mainly
//    radial coolant flow.
// The evaluator gives the surface as the zero set of g(p) = signed distance (mm; exact for the plane, in
// the meridional half-plane (x, r) to the streamline for the revolved surface, with its unit gradient),
// coordinates (a, b) in which the surface's area element is da db (plane: its frame; revolved:
// a = F(t) = the integral of r |C'| along the streamline from its start, b = theta), so that the area of
// a region is |loop integral of a db|, and the drawing coordinates (plane: its frame; revolved: the
// blade-to-blade view unrolled, (x, r (theta - theta_centre)) in mm).
#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/curve_evaluator.hpp"

namespace cg::features {

enum class SpanSurfaceKind { Plane, Revolved };

struct SpanSurface {
  double span = 0;  ///< span fraction (label and table key)
  SpanSurfaceKind kind = SpanSurfaceKind::Plane;
  // Plane: through origin with unit normal; frame (x_axis, normal x x_axis).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  // Revolved: the meridional curve (x, r), revolved about +x; theta_centre = atan2(z, y) of the blade.
  std::shared_ptr<const BSplineCurve<2>> meridional;
  double theta_centre = 0;  ///< rad
};

/// The section surfaces of a blade model at the given span fractions (each in [0, 1]; InvalidGeometry
/// otherwise).
std::vector<SpanSurface> span_surfaces(const blade::BladeModel& model, const std::vector<double>& spans);

/// Evaluation of one SpanSurface. Not thread-safe (curve span caches): one per thread.
class SpanSurfaceEvaluator {
 public:
  explicit SpanSurfaceEvaluator(const SpanSurface& surface);

  /// g(p) (mm) and its unit gradient; `t` (optional) receives the streamline parameter of p's foot point
  /// (revolved) for area_coordinates.
  double value(const Eigen::Vector3d& p, Eigen::Vector3d* gradient = nullptr, double* t = nullptr);
  /// (a, b) with area element da db, for a point on the surface (t from value()).
  Eigen::Vector2d area_coordinates(const Eigen::Vector3d& p, double t) const;
  /// Drawing coordinates, mm.
  Eigen::Vector2d drawing(const Eigen::Vector3d& p) const;
  /// Whether the surface can meet the box (conservative: a box it rejects holds no point of it).
  bool may_meet(const Bnd_Box& box) const;
  const SpanSurface& surface() const { return surface_; }

 private:
  double foot_parameter(const Eigen::Vector2d& q);
  double area_function(double t) const;

  SpanSurface surface_;
  Eigen::Vector3d y_axis_ = Eigen::Vector3d::UnitY();
  std::unique_ptr<CurveEvaluator<2>> curve_;
  std::vector<double> ts_;              ///< sample parameters of the streamline
  std::vector<Eigen::Vector2d> pts_;    ///< its points there
  std::vector<double> area_, darea_;    ///< F and F' = r |C'| at the samples (cubic Hermite between)
  bool monotone_x_ = false;             ///< the samples' x strictly increase (foot search by x)
  double pad_ = 0;                      ///< may_meet's padding of the sampled streamline, mm
};

/// The surface as an OCCT face (the plane bounded by +-size, the surface of revolution over
/// theta_centre +- 90 deg), for cross-checks against OCCT's section.
TopoDS_Face span_surface_face(const SpanSurface& surface, double size);

}  // namespace cg::features
