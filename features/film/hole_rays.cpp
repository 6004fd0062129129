#include "features/film/hole_rays.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace cg::features {

RaySurfaceHit NearCaster::near(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const RaySurfaceHit& seed,
                               double sense, double s_lo, double s_hi, double s_max) {
  RaySurfaceHit h;
  double u = seed.u, v = seed.v, t = (seed.point - o).dot(d) / d.squaredNorm();
  Eigen::Vector3d der[4];
  for (int it = 0; it < 16; ++it) {
    if (!wrap(u, v)) break;
    s_->derivatives(u, v, 1, der);
    const Eigen::Vector3d f = o + t * d - der[0];
    Eigen::Matrix3d j;
    j << d, -der[2], -der[1];
    const Eigen::Vector3d step = j.partialPivLu().solve(-f);
    t += step[0];
    u += step[1];
    v += step[2];
    if (step.norm() < 1e-12 * (1 + std::abs(t))) {
      if (!wrap(u, v)) break;
      s_->derivatives(u, v, 1, der);
      const double cross = d.dot(der[2].cross(der[1]));
      if ((o + t * d - der[0]).norm() > 1e-9 || cross * sense <= 0 || t < s_lo || t > s_hi) break;
      h.found = true;
      h.ray_param = t;
      h.u = u;
      h.v = v;
      h.point = der[0];
      return h;
    }
  }
  ++fallbacks;
  const double from = std::max(0.0, s_lo);
  RaySurfaceHit g = global_.first_hit(o + from * d, d, s_max - from);
  g.ray_param += from;
  return g;
}

double NearCaster::sense(const Eigen::Vector3d& d, const RaySurfaceHit& h) const {
  Eigen::Vector3d der[4];
  s_->derivatives(h.u, h.v, 1, der);
  return d.dot(der[2].cross(der[1])) >= 0 ? 1.0 : -1.0;
}

bool NearCaster::wrap(double& u, double& v) const {
  if (!std::isfinite(u) || !std::isfinite(v)) return false;
  const double u0 = s_->first_u(), u1 = s_->last_u();
  if (s_->is_periodic_u()) {
    u = u0 + std::fmod(u - u0, u1 - u0);
    if (u < u0) u += u1 - u0;
  } else if (u < u0 || u > u1) {
    return false;
  }
  return v >= s_->first_v() && v <= s_->last_v();
}

// Foot point of p on a surface by Newton's method on the distance from (u, v) (the exit point's
// parameters: an inlet lies within the wall thickness of the exit, so its closest point is found from
// there). False when Newton does not settle inside the domain.
bool foot_near(const BSplineSurface<3>& s, const Eigen::Vector3d& p, double& u, double& v) {
  Eigen::Vector3d der[9];
  for (int it = 0; it < 30; ++it) {
    double uu = u, vv = v;
    if (s.is_periodic_u()) {
      const double u0 = s.first_u(), per = s.last_u() - u0;
      uu = u0 + std::fmod(uu - u0, per);
      if (uu < u0) uu += per;
    }
    if (!(uu >= s.first_u() && uu <= s.last_u() && vv >= s.first_v() && vv <= s.last_v())) return false;
    u = uu;
    s.derivatives(u, v, 2, der);  // der[k * 3 + l] = S^(k, l)
    const Eigen::Vector3d r = der[0] - p, su = der[3], sv = der[1];
    Eigen::Matrix2d h;
    h << su.dot(su) + r.dot(der[6]), su.dot(sv) + r.dot(der[4]), su.dot(sv) + r.dot(der[4]), sv.dot(sv) + r.dot(der[2]);
    const Eigen::Vector2d g(r.dot(su), r.dot(sv));
    const Eigen::Vector2d step = h.ldlt().solve(-g);
    if (!step.allFinite()) return false;
    u += step[0];
    v += step[1];
    if (step.norm() < 1e-13) return true;
  }
  return false;
}


}  // namespace cg::features
