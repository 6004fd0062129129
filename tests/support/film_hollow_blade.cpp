#include "tests/support/film_hollow_blade.hpp"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {
namespace {

HoleTarget one_chamber_target(const blade::BladeModel& model, const BSplineSurface<3>& wall, const brep::EndTrim& hub,
                              const brep::EndTrim& tip) {
  HoleTarget t;
  t.model = &model;
  t.cavity_wall = wall;
  t.chambers.push_back(TargetChamber{});
  const Eigen::Vector3d mid = blade::BladeCoordinates(model).frame(0.5, 0.3).point;
  t.obstacles.push_back({"hub_floor", end_wall_distance(hub, mid), true, ".span_start"});
  t.obstacles.push_back({"tip_cap", end_wall_distance(tip, mid), true, ".span_end"});
  return t;
}

}  // namespace

brep::EndTrim shifted_end_trim(const blade::BladeModel& model, bool hub, double shift) {
  brep::EndTrim t = hub ? brep::hub_trim(model.trim) : brep::casing_trim(model.trim);
  const double sign = hub ? 1 : -1;
  if (auto* p = std::get_if<brep::PlaneTrim>(&t)) p->point.z() += sign * shift;
  if (auto* r = std::get_if<brep::RevolvedTrim>(&t)) {
    std::vector<Eigen::Vector2d> poles = r->meridional.poles();
    for (Eigen::Vector2d& p : poles) p.y() += sign * shift;
    const BSplineCurve<2>& c = r->meridional;
    r->meridional = BSplineCurve<2>(c.degree(), c.knots(), poles, c.is_rational() ? c.weights() : std::vector<double>{});
  }
  return t;
}

FilmHollowBlade make_film_hollow_blade(const blade::BladeModel& model, double wall, double end_wall, bool build_solid) {
  require(wall > 0 && end_wall > 0, "film hollow blade: wall and end_wall must be > 0");
  FilmHollowBlade h;
  h.inner = blade::build_inner_wall(model, blade::ThicknessField::constant(wall));
  h.hub_floor = shifted_end_trim(model, true, end_wall);
  h.tip_cap = shifted_end_trim(model, false, end_wall);
  h.wall = wall;
  h.end_wall = end_wall;
  if (!build_solid) return h;
  const brep::BladeSolid outer = brep::build_blade_solid(model);
  const brep::BladeSolid core = brep::build_blade_solid(h.inner.surface, h.hub_floor, h.tip_cap);
  FeatureTool tool;
  tool.feature = "chamber_1";
  tool.shape.shape = core.solid;
  for (const brep::NamedFace& f : core.faces)
    tool.shape.faces.push_back({f.face, f.name == brep::kWallFaceName ? "chamber_1_wall"
                                        : f.name == brep::kHubFaceName ? "hub_floor"
                                                                       : "tip_cap"});
  GProp_GProps props;
  BRepGProp::VolumeProperties(core.solid, props, 1e-9, true);
  tool.expected_volume = props.Mass();  // the core lies inside the blade
  BooleanStep step(BooleanOperation::Cut);
  step.add(tool);
  h.part = step.apply(brep::NamedShape{outer.solid, outer.faces});
  h.volume = step.report().check.volume;
  return h;
}

HoleTarget film_hollow_target(const blade::BladeModel& model, const FilmHollowBlade& hollow) {
  return one_chamber_target(model, hollow.inner.surface, hollow.hub_floor, hollow.tip_cap);
}

InsertChamber film_hollow_insert_chamber(const blade::BladeModel& model, const FilmHollowBlade& hollow) {
  InsertChamber c;
  c.wall_thickness = hollow.wall;
  const double end_wall = hollow.end_wall;
  const blade::BladeModel* m = &model;
  c.hub_end = [m, end_wall](double extra) { return shifted_end_trim(*m, true, end_wall + extra); };
  c.tip_end = [m, end_wall](double extra) { return shifted_end_trim(*m, false, end_wall + extra); };
  const blade::BladeCoordinates bc(model);
  c.reference = 0.5 * (bc.frame(0.5, 0.3).point + bc.frame(0.5, -0.3).point);
  return c;
}

HoleTarget sample_hole_target(const blade::BladeModel& model, const HollowBlade& part, const HollowBladeOptions& options) {
  return one_chamber_target(model, part.core_surface, shifted_end_trim(model, true, options.end_wall),
                            shifted_end_trim(model, false, options.end_wall));
}

}  // namespace cg::features
