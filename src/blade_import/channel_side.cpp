#include "src/blade_import/channel_side.hpp"

#include <cmath>

namespace cg::blade_import {

ChannelSide::ChannelSide(const blade::MeridionalNet& net) : net_(net) {
  const blade::Streamline& hub = net_->hub();
  const double u = 0.5 * (hub.first_param() + hub.last_param());
  const Eigen::Vector2d t = hub.curve().derivatives(u, 1)[1];
  const Eigen::Vector2d to_casing = net_->casing().point(0.5 * (net_->casing().first_param() + net_->casing().last_param())) - hub.point(u);
  sign_ = (-t.y() * to_casing.x() + t.x() * to_casing.y()) >= 0 ? 1 : -1;
}

ChannelSide::Line& ChannelSide::line(double s) {
  auto it = lines_.find(s);
  if (it == lines_.end()) {
    Line l{net_->streamline_at(s), nullptr};
    l.projector = std::make_unique<CurveProjector<2>>(l.line.curve());
    it = lines_.emplace(s, std::move(l)).first;
  }
  return it->second;
}

const blade::Streamline& ChannelSide::streamline(double s) { return line(s).line; }

double ChannelSide::offset(const Eigen::Vector3d& P, double s) {
  if (!net_) return P.z() - s * span_;
  Line& l = line(s);
  const Eigen::Vector2d q(P.x(), std::hypot(P.y(), P.z()));
  const CurveProjection<2> foot = l.projector->project(q);
  const Eigen::Vector2d t = l.line.curve().derivatives(foot.param, 1)[1].normalized();
  const Eigen::Vector2d n(-t.y(), t.x());
  return sign_ * n.dot(q - foot.point);
}

}  // namespace cg::blade_import
