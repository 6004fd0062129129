#include "features/passages/end_walls.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "src/algo/offset_exact.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/core/error.hpp"
#include "src/fit/approximate.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

// +1 when the flow path lies to the left of the contour's direction (the other contour is there).
double positive_side(const BSplineCurve<2>& contour, const BSplineCurve<2>& other) {
  const double um = 0.5 * (contour.first_param() + contour.last_param());
  const auto d = contour.derivatives(um, 1);
  const Eigen::Vector2d left(-d[1].y(), d[1].x());
  const Eigen::Vector2d to_other =
      other.point(0.5 * (other.first_param() + other.last_param())) - d[0];
  return left.dot(to_other) > 0 ? 1.0 : -1.0;
}

}  // namespace

EndWall::EndWall(const blade::BladeModel& model, SpanEnd end, double shift, double tolerance)
    : end_(end), shift_(shift), straight_(model.trim.straight) {
  require(std::isfinite(shift), "end wall: shift must be finite");
  const blade::FlowPathTrim& t = model.trim;
  if (straight_) {
    // Hub plane: positive side +z; casing plane: positive side -z.
    sense_ = end == SpanEnd::Hub ? 1.0 : -1.0;
    z_ = (end == SpanEnd::Hub ? t.hub_z : t.casing_z) + sense_ * shift;
    return;
  }
  const BSplineCurve<2>& base = end == SpanEnd::Hub ? t.hub : t.casing;
  const BSplineCurve<2>& other = end == SpanEnd::Hub ? t.casing : t.hub;
  sense_ = positive_side(base, other);
  if (shift == 0) {
    contour_ = base;
  } else {
    ExactOffset off(base, sense_ * shift);
    const int n = 400;
    PointList<2> pts;
    for (int k = 0; k <= n; ++k) {
      const double u = base.first_param() + (base.last_param() - base.first_param()) * k / n;
      if (off.speed_ratio(u) <= 0.05)
        throw InvalidGeometry(std::string(end == SpanEnd::Hub ? "hub" : "casing") + " contour: a shift of " +
                              format_number(shift) + " mm exceeds its radius of curvature");
      pts.push_back(off.point(u));
    }
    contour_ = approximate<2>(pts, 3, tolerance).curve;
  }
  projector_ = std::make_unique<CurveProjector<2>>(contour_);
}

EndWall::~EndWall() = default;

EndWall::EndWall(const EndWall& o)
    : end_(o.end_), shift_(o.shift_), straight_(o.straight_), z_(o.z_), sense_(o.sense_), contour_(o.contour_) {
  if (!straight_) projector_ = std::make_unique<CurveProjector<2>>(contour_);
}

EndWall& EndWall::operator=(const EndWall& o) {
  if (this != &o) {
    end_ = o.end_;
    shift_ = o.shift_;
    straight_ = o.straight_;
    z_ = o.z_;
    sense_ = o.sense_;
    contour_ = o.contour_;
    projector_ = straight_ ? nullptr : std::make_unique<CurveProjector<2>>(contour_);
  }
  return *this;
}

brep::EndTrim EndWall::trim() const {
  if (straight_) return brep::PlaneTrim{Eigen::Vector3d(0, 0, z_), Eigen::Vector3d::UnitZ()};
  return brep::RevolvedTrim{contour_};
}

double EndWall::signed_distance(const Eigen::Vector3d& p) const {
  if (straight_) return sense_ * (p.z() - z_);
  const Eigen::Vector2d q(p.x(), std::hypot(p.y(), p.z()));
  const CurveProjection<2> pr = projector_->project(q);
  const auto d = contour_.derivatives(pr.param, 1);
  const Eigen::Vector2d left = Eigen::Vector2d(-d[1].y(), d[1].x()).normalized();
  return (q - pr.point).dot(sense_ * left) >= 0 ? pr.distance : -pr.distance;
}

Eigen::Vector3d EndWall::normal_at(const Eigen::Vector3d& p) const {
  if (straight_) return Eigen::Vector3d(0, 0, sense_);
  const Eigen::Vector2d q(p.x(), std::hypot(p.y(), p.z()));
  const CurveProjection<2> pr = projector_->project(q);
  const auto d = contour_.derivatives(pr.param, 1);
  const Eigen::Vector2d n = sense_ * Eigen::Vector2d(-d[1].y(), d[1].x()).normalized();
  const double r = std::hypot(p.y(), p.z());
  const Eigen::Vector3d er = r > 0 ? Eigen::Vector3d(0, p.y() / r, p.z() / r) : Eigen::Vector3d::UnitY();
  return Eigen::Vector3d(n.x(), 0, 0) + n.y() * er;
}

}  // namespace cg::features
