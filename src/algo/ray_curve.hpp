#pragma once
// Ray-curve intersection.
//
// RayCurveCaster::first_hit (2D and 3D): sphere tracing (Hart 1996) with the exact distance to the
// curve from CurveProjector: no curve point lies closer to the ray point X(s) than dist(X(s), C), so
// the step s += dist / |d| cannot pass the curve, and the first hit along the ray is the one reached.
// Close to the curve (dist below 1e-3 of the curve's size) the hit is refined by Newton's method on
// the closest approach of ray and curve, min |o + s d - C(u)|^2 / 2 (exact Hessian, damped), to a
// residual of 1e-12 of the curve size; in 3D a hit is a closest approach within hit_tol. A march that
// stalls (a ray grazing the curve: the distance decreases only quadratically) is checked by the same
// closest-approach solve: a tangent hit when its gap is within hit_tol. A near miss by a gap g costs
// ~sqrt(curvature radius / g) plain sphere steps: no step is ever larger than the certified distance,
// so no crossing can be skipped.
//
// line_curve_intersections (2D, exact): every root of n.(C(u) - o) = 0, n normal to the ray. Per
// Bézier piece in homogeneous form g(t) = n.(A(t) - w(t) o) is a polynomial of degree p with Bernstein
// coefficients n.(A_j - w_j o); roots are isolated by the variation diminishing property and de
// Casteljau subdivision (Lane & Riesenfeld 1981), and each isolated root is refined by bracketed
// Newton. All hits, sorted along the ray.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "src/algo/project_point_curve.hpp"

namespace cg {

template <int Dim>
struct RayCurveHit {
  using Point = Eigen::Matrix<double, Dim, 1>;
  bool found = false;
  double ray_param = 0.0;    // s: the ray point is origin + s * direction
  double curve_param = 0.0;  // u
  Point point = Point::Zero();  // C(u)
  /// |origin + s d - C(u)|: rounding in 2D and for crossings, the closest-approach gap in 3D.
  double gap = 0.0;
  bool tangent = false;  // the ray touches the curve (or grazes it within hit_tol) without crossing
};

template <int Dim>
class RayCurveCaster {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  /// hit_tol <= 0: 1e-9 * (1 + diagonal of the curve's box).
  explicit RayCurveCaster(const BSplineCurve<Dim>& curve, double hit_tol = 0.0);

  /// First hit of the ray origin + s * direction, s in [0, s_max]. Throws InvalidGeometry for a zero
  /// or non-finite direction.
  RayCurveHit<Dim> first_hit(const Point& origin, const Point& direction,
                             double s_max = std::numeric_limits<double>::infinity());
  double hit_tolerance() const { return hit_tol_; }
  /// The caster's own copy of the curve (it never dangles; one caster per thread).
  const BSplineCurve<Dim>& curve() const { return proj_.curve(); }

 private:
  bool closest_approach(const Point& o, const Point& d, double& s, double& u, double& gap);
  CurveProjector<Dim> proj_;
  BoundingBox<Dim> box_;
  double scale_ = 0, hit_tol_ = 0;
};

/// First hit by sphere tracing (builds a RayCurveCaster).
template <int Dim>
RayCurveHit<Dim> ray_curve_first_hit(const BSplineCurve<Dim>& curve, const Eigen::Matrix<double, Dim, 1>& origin,
                                     const Eigen::Matrix<double, Dim, 1>& direction,
                                     double s_max = std::numeric_limits<double>::infinity());

/// Every intersection of the line origin + s * direction, s in [s_min, s_max] (s_min = 0: a ray;
/// -inf: a full line), with a 2D curve, sorted by s. Tangent contacts are reported once with
/// tangent = true.
std::vector<RayCurveHit<2>> line_curve_intersections(const BSplineCurve<2>& curve, const Eigen::Vector2d& origin,
                                                     const Eigen::Vector2d& direction, double s_min = 0.0,
                                                     double s_max = std::numeric_limits<double>::infinity());

extern template class RayCurveCaster<2>;
extern template class RayCurveCaster<3>;

}  // namespace cg
