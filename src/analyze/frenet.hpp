#pragma once
// Differential geometry of curves at a parameter: Frenet-Serret frame, curvature and torsion of 3D
// curves, signed curvature and the left normal of planar curves (do Carmo, Differential Geometry of
// Curves and Surfaces, 1.5; derivatives by The NURBS Book A3.2 + A4.2). From C', C'', C''':
//   T = C'/|C'|, B = C' x C'' / |C' x C''|, N = B x T,
//   curvature = |C' x C''| / |C'|^3, torsion = (C' x C'') . C''' / |C' x C''|^2;
//   planar: signed curvature = (C' x C'') / |C'|^3 (> 0 turning left), normal = T turned by +90 deg.
#include <Eigen/Core>
#include <string>

#include "src/core/bspline_curve.hpp"

namespace cg {

/// Which parts of a frame are defined at the point.
enum class FrameStatus {
  Regular,        ///< everything defined
  ZeroCurvature,  ///< C' x C'' ~ 0 (inflection or straight piece): tangent and curvature (= 0) only;
                  ///< normal, binormal and torsion are undefined (left zero)
  Singular        ///< C' ~ 0: no tangent; nothing but the point is defined
};

/// Frenet-Serret frame of a 3D curve at parameter u.
struct FrenetFrame {
  FrameStatus status = FrameStatus::Singular;
  double u = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d binormal = Eigen::Vector3d::Zero();
  double curvature = 0;
  double torsion = 0;
  /// Throws AlgorithmFailure naming u when the requested parts are undefined: tangent/curvature need
  /// status != Singular, normal/binormal/torsion need Regular.
  void require_tangent() const;
  void require_normal() const;
};

/// Frame of a planar curve at parameter u.
struct PlanarFrame {
  FrameStatus status = FrameStatus::Singular;
  double u = 0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< LEFT normal: tangent turned by +90 deg (always
                                                     ///< defined with the tangent, unlike the Frenet normal)
  double curvature = 0;                              ///< signed, > 0 where the curve turns left
  void require_tangent() const;
};

/// Thresholds, relative to the curve's size so they are scale-invariant: C' is "zero" when
/// |C'| <= 1e-12 * size / domain length, the curvature is "zero" when curvature * size <= 1e-12
/// (radius of curvature above 1e12 times the curve's size). size = diagonal of the poles' box.
FrenetFrame frenet_frame(const BSplineCurve<3>& curve, double u);
PlanarFrame frenet_frame(const BSplineCurve<2>& curve, double u);

/// Curvature (>= 0); throws AlgorithmFailure where C' vanishes.
double curvature(const BSplineCurve<3>& curve, double u);
/// Torsion; throws AlgorithmFailure where C' vanishes or the curvature is zero (torsion undefined).
double torsion(const BSplineCurve<3>& curve, double u);
/// Signed curvature of a planar curve; throws AlgorithmFailure where C' vanishes.
double signed_curvature(const BSplineCurve<2>& curve, double u);

}  // namespace cg
