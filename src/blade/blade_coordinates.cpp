#include "src/blade/blade_coordinates.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "src/algo/project_point_surface.hpp"
#include "src/core/error.hpp"

namespace cg::blade {

BladeCoordinates::BladeCoordinates(const BladeModel& model) : model_(&model) {
  const BSplineSurface<3>& s = model.surface;
  require(s.is_periodic_u(), "blade coordinates: the blade surface must be periodic in u");
  // Outward orientation: S_u x S_v against the direction from the section centre, by majority over the
  // mid-span section so a locally concave pressure side cannot flip the decision.
  const int n = 256;
  const double vm = 0.5;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) centre += s.point(s.first_u() + (s.last_u() - s.first_u()) * i / n, vm);
  centre /= n;
  int votes = 0;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d d[4];
    s.derivatives(s.first_u() + (s.last_u() - s.first_u()) * i / n, vm, 1, d);
    votes += d[2].cross(d[1]).dot(d[0] - centre) > 0 ? 1 : -1;  // (S_u x S_v).(S - centre)
  }
  normal_sign_ = votes >= 0 ? 1.0 : -1.0;
  projector_ = std::make_unique<SurfaceProjector>(s);
}

BladeCoordinates::~BladeCoordinates() = default;

BladeFrame BladeCoordinates::frame(double span, double chord) const {
  const BSplineSurface<3>& s = model_->surface;
  double u = surface_u_at_chordwise(chord, model_->u_te), v = span;
  s.check_params(u, v);
  Eigen::Vector3d d[4];  // S, S_v, S_u, (S_uv unused) for order 1
  s.derivatives(u, v, 1, d);
  BladeFrame f;
  f.point = d[0];
  f.chord_tangent = d[2].normalized();
  f.span_tangent = d[1].normalized();
  f.normal = (normal_sign_ * d[2].cross(d[1])).normalized();
  return f;
}

Eigen::Vector3d BladeCoordinates::point(const BladeCoordinate& c) const {
  const BladeFrame f = frame(c.span, c.chord);
  return f.point - c.depth * f.normal;
}

BladeLocateResult BladeCoordinates::locate(const Eigen::Vector3d& p) const {
  const BSplineSurface<3>& s = model_->surface;
  BladeLocateResult r;
  const SurfaceProjection pr = projector_->project(p);
  if (!pr.found) return r;
  // A foot point on the over-build end rim is not an orthogonal projection (the point lies beyond the
  // surface's span range): report not found unless the point is on the surface itself.
  const double vtol = 1e-12 * (s.last_v() - s.first_v());
  if ((pr.v <= s.first_v() + vtol || pr.v >= s.last_v() - vtol) && pr.distance > projector_->tolerance()) return r;
  Eigen::Vector3d d[4];
  s.derivatives(pr.u, pr.v, 1, d);
  const Eigen::Vector3d n = (normal_sign_ * d[2].cross(d[1])).normalized();
  r.found = true;
  r.u = pr.u;
  r.v = pr.v;
  r.coordinate.span = pr.v;
  r.coordinate.chord = chordwise_at_surface_u(pr.u - s.first_u(), model_->u_te);
  r.coordinate.depth = (d[0] - p).dot(n);
  return r;
}

}  // namespace cg::blade
