#include "features/film/hole_target.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "src/algo/project_point_curve.hpp"

namespace cg::features {

bool TargetChamber::contains(double chord) const {
  return chord >= 0 ? chord >= suction_from && chord <= suction_to : chord >= pressure_from && chord <= pressure_to;
}

int HoleTarget::chamber_at(double chord) const {
  for (std::size_t i = 0; i < chambers.size(); ++i)
    if (chambers[i].contains(chord)) return static_cast<int>(i);
  return -1;
}

double insert_reach(double gap) { return gap - std::max(0.05, 0.25 * gap); }

void limit_reach_by_inserts(HoleTarget& target, const std::vector<InsertDefinition>& inserts) {
  for (const InsertDefinition& d : inserts)
    for (TargetChamber& c : target.chambers)
      if (c.number == d.chamber) c.reach = insert_reach(d.gap);
}

std::function<double(const Eigen::Vector3d&)> end_wall_distance(const brep::EndTrim& trim, const Eigen::Vector3d& inside) {
  if (const auto* plane = std::get_if<brep::PlaneTrim>(&trim)) {
    Eigen::Vector3d n = plane->normal.normalized();
    if ((inside - plane->point).dot(n) < 0) n = -n;
    const Eigen::Vector3d p0 = plane->point;
    return [p0, n](const Eigen::Vector3d& p) { return (p - p0).dot(n); };
  }
  const auto& rev = std::get<brep::RevolvedTrim>(trim);
  auto curve = std::make_shared<BSplineCurve<2>>(rev.meridional);
  auto projector = std::make_shared<CurveProjector<2>>(*curve);
  auto side_of = [curve, projector](const Eigen::Vector2d& q, double& distance) {
    const CurveProjection<2> f = projector->project(q);
    Eigen::Vector2d d[2];
    curve->derivatives(f.param, 1, d);
    distance = f.distance;
    return (q - f.point).dot(Eigen::Vector2d(-d[1].y(), d[1].x())) >= 0 ? 1.0 : -1.0;
  };
  double unused;
  const double side = side_of(Eigen::Vector2d(inside.x(), std::hypot(inside.y(), inside.z())), unused);
  return [side_of, side](const Eigen::Vector3d& p) {
    double distance;
    const double s = side_of(Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z())), distance);
    return s * side * distance;
  };
}

}  // namespace cg::features
