#include "features/film/film_cavity.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <cmath>

#include "src/blade/blade_coordinates.hpp"

namespace cg::features {
namespace {

using Vec3 = Eigen::Vector3d;

// A rib's mid-surface M(a, s) = A(s) + a (B(s) - A(s)) sampled at `n` spans over the inner wall's span
// range and interpolated linearly between them (the rib lines are smooth along the span: on the
// examples the chord error of 129 samples is below 1e-3 mm), so a distance costs no blade evaluation.
class RibDistance {
 public:
  RibDistance(const blade::BladeModel& model, const blade::ThicknessField& wall, const RibDefinition& rib, double s0,
              double s1, int n = 129)
      : s0_(s0), h_((s1 - s0) / (n - 1)), half_(0.5 * rib.thickness) {
    const blade::BladeCoordinates coords(model);
    for (int k = 0; k < n; ++k) {
      const double s = s0 + h_ * k;
      a_.push_back(blade::inner_wall_point(coords, wall, s, rib.suction_chord));
      b_.push_back(blade::inner_wall_point(coords, wall, s, rib.pressure_chord));
    }
    // Fillet width on the wall: r / tan(theta / 2), theta the smaller corner angle between rib and wall.
    if (rib.fillet_radius > 0)
      for (double s : {0.1, 0.5, 0.9})
        for (double c : {rib.suction_chord, rib.pressure_chord}) {
          const Vec3 nw = coords.frame(s, c).normal;
          const Vec3 N = normal(c > 0 ? 0.0 : 1.0, s);
          const double theta = std::acos(std::min(1.0, std::abs(N.dot(nw))));
          fillet_ = std::max(fillet_, rib.fillet_radius / std::tan(0.5 * std::max(theta, 1e-3)));
        }
  }

  /// |w| - t / 2 - fillet width (see film_cavity.hpp).
  double operator()(const Vec3& p) const {
    double s = span_guess_, a = 0.5;
    Vec3 M;
    for (int it = 0; it < 12; ++it) {
      const auto [A, B, As, Bs] = at(s);
      const Vec3 AB = B - A;
      a = (p - A).dot(AB) / AB.squaredNorm();
      M = A + a * AB;
      const Vec3 Ms = As + a * (Bs - As);
      const double ds = (p - M).dot(Ms) / Ms.squaredNorm();
      s += ds;
      if (std::abs(ds) < 1e-10) break;
    }
    span_guess_ = s;
    const Vec3 N = normal(a, s);
    const auto [A, B, As, Bs] = at(s);
    M = A + a * (B - A);
    return std::abs((p - M).dot(N)) - half_ - fillet_;
  }

 private:
  struct Row {
    Vec3 a, b, as, bs;  // A, B and their span derivatives
  };
  Row at(double s) const {
    const int n = static_cast<int>(a_.size());
    const double x = (s - s0_) / h_;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, n - 2);
    const double t = x - i;
    return {a_[i] + t * (a_[i + 1] - a_[i]), b_[i] + t * (b_[i + 1] - b_[i]), (a_[i + 1] - a_[i]) / h_,
            (b_[i + 1] - b_[i]) / h_};
  }
  Vec3 normal(double a, double s) const {
    const Row r = at(s);
    return (r.as + a * (r.bs - r.as)).cross(r.b - r.a).normalized();
  }

  std::vector<Vec3> a_, b_;
  double s0_, h_, half_, fillet_ = 0;
  mutable double span_guess_ = 0.5;
};

brep::EndTrim end_trim(const blade::BladeModel& model, SpanEnd end, const EndWallDefinition& wall, double extra) {
  return EndWall(model, end, (wall.open ? 0.0 : wall.thickness) + extra).trim();
}

// Signed distance to a tool solid (a turbulator, a pin fin, a slot): exact (BRepExtrema, sign by the
// solid classifier) within `near` mm of the tool's box, the distance to the box beyond (a lower bound
// > 0, all a hole check needs there), so the many far pairs cost a box test each.
class ToolDistance {
 public:
  explicit ToolDistance(const TopoDS_Shape& solid, double near = 2.0) : solid_(solid), near_(near) {
    Bnd_Box box;
    BRepBndLib::Add(solid, box);
    box.Get(lo_.x(), lo_.y(), lo_.z(), hi_.x(), hi_.y(), hi_.z());
  }
  double operator()(const Vec3& p) const {
    const Vec3 outside = (lo_ - p).cwiseMax(p - hi_).cwiseMax(0.0);
    const double d_box = outside.norm();
    if (d_box > near_) return d_box;
    const gp_Pnt q(p.x(), p.y(), p.z());
    BRepClass3d_SolidClassifier inside(solid_, q, 1e-7);
    if (inside.State() == TopAbs_IN) return -1e-3;  // inside: any negative value (the check only asks <= 0)
    BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(q).Vertex(), solid_);
    return d.IsDone() ? d.Value() : d_box;
  }

 private:
  TopoDS_Shape solid_;
  double near_;
  Vec3 lo_, hi_;
};

}  // namespace

std::vector<TargetObstacle> wall_feature_obstacles(const WallFeatureBuild& walls) {
  std::vector<TargetObstacle> out;
  const auto add = [&](const std::vector<FeatureTool>& tools) {
    for (const FeatureTool& t : tools) {
      auto d = std::make_shared<ToolDistance>(t.shape.shape);
      out.push_back({t.feature, [d](const Vec3& p) { return (*d)(p); }, true, ""});
    }
  };
  add(walls.turbulators.tools);
  add(walls.trailing_edge.pin_tools);
  add(walls.trailing_edge.slot_tools);
  return out;
}

HoleTarget hole_target_of_core(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core) {
  HoleTarget t;
  t.model = &model;
  t.cavity_wall = core.inner_wall.surface;
  const double s0 = core.inner_wall.surface.first_v(), s1 = core.inner_wall.surface.last_v();
  for (const ChamberInfo& c : core.chambers) {
    TargetChamber tc;
    tc.number = c.number;
    tc.name = "chamber_" + std::to_string(c.number);
    tc.suction_from = c.suction_from;
    tc.suction_to = c.suction_to;
    // ChamberInfo runs LE -> TE on both sides (pressure_from >= pressure_to); ours runs up the chord coordinate.
    tc.pressure_from = c.pressure_to;
    tc.pressure_to = c.pressure_from;
    t.chambers.push_back(tc);
  }
  for (std::size_t i = 0; i < def.ribs.size(); ++i) {
    auto rib = std::make_shared<RibDistance>(model, def.wall_thickness, def.ribs[i], s0, s1);
    t.obstacles.push_back({"rib_" + std::to_string(i + 1), [rib](const Vec3& p) { return (*rib)(p); }, true, ""});
  }
  if (core.hub_floor) {
    auto w = std::make_shared<EndWall>(*core.hub_floor);
    t.obstacles.push_back({"hub_floor", [w](const Vec3& p) { return w->signed_distance(p); }, true, ".span_start"});
  }
  if (core.tip_cap) {
    auto w = std::make_shared<EndWall>(*core.tip_cap);
    t.obstacles.push_back({"tip_cap", [w](const Vec3& p) { return w->signed_distance(p); }, true, ".span_end"});
  }
  return t;
}

FilmCavity film_cavity_of_core(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core) {
  FilmCavity cav;
  cav.target = hole_target_of_core(model, def, core);
  const double s0 = core.inner_wall.surface.first_v(), s1 = core.inner_wall.surface.last_v();

  // Insert chambers.
  const blade::BladeModel* m = &model;
  const auto shared_def = std::make_shared<CoreDefinition>(def);
  for (const ChamberInfo& c : core.chambers) {
    InsertChamber ic;
    ic.number = c.number;
    ic.name = "chamber_" + std::to_string(c.number);
    // The chamber's wall where it is one thickness over the chamber (a constant wall, or a table flat
    // there, as upstream of a cutback's TE land: cutback_wall.hpp); else 0, which inserts refuse.
    const double ts = def.wall_thickness.constant_over(std::min(c.suction_from, c.suction_to), std::max(c.suction_from, c.suction_to));
    const double tp = def.wall_thickness.constant_over(std::min(c.pressure_from, c.pressure_to), std::max(c.pressure_from, c.pressure_to));
    ic.wall_thickness = ts == tp ? ts : 0.0;  // NaN never equal
    ic.suction_from = c.suction_from;
    ic.suction_to = c.suction_to;
    ic.pressure_from = c.pressure_to;
    ic.pressure_to = c.pressure_from;
    ic.reference = c.reference;
    ic.hub_open = def.hub_floor.open;
    ic.tip_open = def.tip_cap.open;
    ic.hub_end = [m, shared_def](double extra) { return end_trim(*m, SpanEnd::Hub, shared_def->hub_floor, extra); };
    ic.tip_end = [m, shared_def](double extra) { return end_trim(*m, SpanEnd::Tip, shared_def->tip_cap, extra); };
    std::vector<int> bounding;  // 0-based rib indices
    if (c.number >= 2) bounding.push_back(c.number - 2);
    if (c.number <= static_cast<int>(def.ribs.size())) bounding.push_back(c.number - 1);
    for (int i : bounding) {
      const RibDefinition& r = def.ribs[static_cast<std::size_t>(i)];
      if (r.turnaround)
        ic.refusal = ic.name + " is joined to its neighbour by turnaround at rib_" + std::to_string(i + 1) +
                     "; an insert needs a chamber closed by ribs from the hub floor to the tip cap";
      if (r.fillet_radius > ic.min_gap) {
        ic.min_gap = r.fillet_radius;
        ic.min_gap_reason = "rib_" + std::to_string(i + 1) + "'s fillet radius";
      }
    }
    ic.rib_walls = [m, shared_def, bounding, s0, s1](double grow) {
      const blade::BladeCoordinates coords(*m);
      RibEnds ends;
      ends.hub_through_span = s0;
      ends.tip_through_span = s1;
      std::vector<TopoDS_Shape> walls;
      for (int i : bounding) {
        RibDefinition r = shared_def->ribs[static_cast<std::size_t>(i)];
        r.thickness += 2 * grow;
        r.fillet_radius = 0;
        r.turnaround.reset();
        walls.push_back(build_rib_tube(coords, shared_def->wall_thickness, r, i + 1, 0, ends, shared_def->tolerance).shell);
      }
      return walls;
    };
    cav.chambers.push_back(std::move(ic));
  }
  return cav;
}

}  // namespace cg::features
