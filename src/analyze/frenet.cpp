#include "src/analyze/frenet.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

namespace {

template <int Dim>
double size_of(const BSplineCurve<Dim>& c) {
  const auto& H = c.homogeneous_poles();
  Eigen::Matrix<double, Dim, 1> lo, hi;
  lo.setConstant(HUGE_VAL);
  hi.setConstant(-HUGE_VAL);
  for (Eigen::Index i = 0; i < H.cols(); ++i) {
    const Eigen::Matrix<double, Dim, 1> P = H.col(i).template head<Dim>() / H(Dim, i);
    lo = lo.cwiseMin(P);
    hi = hi.cwiseMax(P);
  }
  return (hi - lo).norm();
}

// |C'| below this counts as zero: a relative 1e-12 of the mean speed size / domain length.
template <int Dim>
double speed_threshold(const BSplineCurve<Dim>& c, double size) {
  return 1e-12 * size / (c.last_param() - c.first_param());
}

[[noreturn]] void fail(const char* what, double u, const char* why) {
  throw AlgorithmFailure(std::string(what) + " undefined at u = " + format_number(u) + ": " + why);
}

}  // namespace

void FrenetFrame::require_tangent() const {
  if (status == FrameStatus::Singular) fail("tangent", u, "the first derivative vanishes");
}
void FrenetFrame::require_normal() const {
  require_tangent();
  if (status == FrameStatus::ZeroCurvature) fail("normal", u, "the curvature is zero");
}
void PlanarFrame::require_tangent() const {
  if (status == FrameStatus::Singular) fail("tangent", u, "the first derivative vanishes");
}

FrenetFrame frenet_frame(const BSplineCurve<3>& c, double u) {
  Eigen::Vector3d d[4];
  c.derivatives(u, 3, d);
  FrenetFrame f;
  f.u = u;
  f.point = d[0];
  const double size = size_of(c);
  const double speed = d[1].norm();
  if (!(speed > speed_threshold(c, size))) return f;
  f.tangent = d[1] / speed;
  const Eigen::Vector3d cross = d[1].cross(d[2]);
  const double cn = cross.norm();
  f.curvature = cn / (speed * speed * speed);
  if (!(f.curvature * size > 1e-12)) {
    f.status = FrameStatus::ZeroCurvature;
    f.curvature = 0;
    return f;
  }
  f.status = FrameStatus::Regular;
  f.binormal = cross / cn;
  f.normal = f.binormal.cross(f.tangent);
  f.torsion = cross.dot(d[3]) / (cn * cn);
  return f;
}

PlanarFrame frenet_frame(const BSplineCurve<2>& c, double u) {
  Eigen::Vector2d d[3];
  c.derivatives(u, 2, d);
  PlanarFrame f;
  f.u = u;
  f.point = d[0];
  const double speed = d[1].norm();
  if (!(speed > speed_threshold(c, size_of(c)))) return f;
  f.status = FrameStatus::Regular;
  f.tangent = d[1] / speed;
  f.normal = Eigen::Vector2d(-f.tangent.y(), f.tangent.x());
  f.curvature = (d[1].x() * d[2].y() - d[1].y() * d[2].x()) / (speed * speed * speed);
  return f;
}

double curvature(const BSplineCurve<3>& c, double u) {
  const FrenetFrame f = frenet_frame(c, u);
  f.require_tangent();
  return f.curvature;
}

double torsion(const BSplineCurve<3>& c, double u) {
  const FrenetFrame f = frenet_frame(c, u);
  f.require_normal();
  return f.torsion;
}

double signed_curvature(const BSplineCurve<2>& c, double u) {
  const PlanarFrame f = frenet_frame(c, u);
  f.require_tangent();
  return f.curvature;
}

}  // namespace cg
