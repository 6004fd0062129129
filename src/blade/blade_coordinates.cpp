#include "src/blade/blade_coordinates.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "src/algo/project_point_surface.hpp"
#include "src/blade/surface_iso.hpp"
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
  iso_nodes_ = std::make_shared<const IsoArcLengthNodes>(detail::iso_curve_v(s, vm));
}

BladeCoordinates::~BladeCoordinates() = default;

const SpanSection& BladeCoordinates::section(double span) const {
  ++clock_;
  if (last_hit_ < cache_.size() && cache_[last_hit_].span == span) {
    cache_[last_hit_].last_used = clock_;
    return *cache_[last_hit_].section;
  }
  for (std::size_t i = 0; i < cache_.size(); ++i)
    if (cache_[i].span == span) {
      cache_[i].last_used = clock_;
      last_hit_ = i;
      return *cache_[i].section;
    }
  // Built before the cache changes, so a throwing span (outside the domain) leaves it as it was.
  auto made = std::make_unique<const SpanSection>(*model_, span, iso_nodes_);
  if (cache_.size() < kSectionCacheSize) {
    cache_.push_back({span, clock_, std::move(made)});
    last_hit_ = cache_.size() - 1;
  } else {
    last_hit_ = static_cast<std::size_t>(
        std::min_element(cache_.begin(), cache_.end(),
                         [](const CachedSection& a, const CachedSection& b) { return a.last_used < b.last_used; }) -
        cache_.begin());
    cache_[last_hit_] = {span, clock_, std::move(made)};
  }
  return *cache_[last_hit_].section;
}

BladeFrame BladeCoordinates::frame_at(double u, double v) const {
  const BSplineSurface<3>& s = model_->surface;
  s.check_params(u, v);
  Eigen::Vector3d d[4];  // S, S_v, S_u, (S_uv unused) for order 1
  s.derivatives(u, v, 1, d);
  BladeFrame f;
  f.point = d[0];
  f.chord_tangent = d[2].normalized();
  f.span_tangent = d[1].normalized();
  f.normal = (normal_sign_ * d[2].cross(d[1])).normalized();
  f.u = u;
  f.v = v;
  return f;
}

BladeFrame BladeCoordinates::frame(double span, double chord, ChordAccuracy accuracy) const {
  double u = 0, v = span;
  model_->surface.check_params(u, v);  // span inside the surface's domain, or InvalidGeometry
  return frame_at(section(span).u_at_chordwise(chord, accuracy), span);
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
  // The projector stops at its tolerance; a few Newton steps on grad |S - p|^2 / 2 = 0 with exact second
  // derivatives take the foot point to rounding, so coordinates round-trip to ~1e-12.
  double u = pr.u, v = pr.v, dist = pr.distance;
  for (int it = 0; it < 4; ++it) {
    Eigen::Vector3d e[9];  // e[k * 3 + l] = d^(k+l) S / du^k dv^l
    s.derivatives(u, v, 2, e);
    const Eigen::Vector3d g = e[0] - p;
    Eigen::Matrix2d H;
    H << e[3].dot(e[3]) + g.dot(e[6]), e[3].dot(e[1]) + g.dot(e[4]), e[3].dot(e[1]) + g.dot(e[4]),
        e[1].dot(e[1]) + g.dot(e[2]);
    const Eigen::Vector2d step = H.fullPivLu().solve(-Eigen::Vector2d(g.dot(e[3]), g.dot(e[1])));
    if (!step.allFinite()) break;
    double un = u + step.x(), vn = std::clamp(v + step.y(), s.first_v(), s.last_v());
    if (s.is_periodic_u()) {
      double dummy = vn;
      s.check_params(un, dummy);
    } else {
      un = std::clamp(un, s.first_u(), s.last_u());
    }
    const double dn = (s.point(un, vn) - p).norm();
    if (!(dn <= dist * (1 + 1e-12) + 1e-300)) break;
    const bool converged = step.norm() <= 1e-15 * (1 + std::abs(u) + std::abs(v));
    u = un;
    v = vn;
    dist = dn;
    if (converged) break;
  }
  Eigen::Vector3d d[4];
  s.derivatives(u, v, 1, d);
  const Eigen::Vector3d n = (normal_sign_ * d[2].cross(d[1])).normalized();
  r.found = true;
  r.u = u;
  r.v = v;
  r.coordinate.span = v;
  r.coordinate.chord = section(v).chordwise_at_u(u);
  r.coordinate.depth = (d[0] - p).dot(n);
  return r;
}

}  // namespace cg::blade
