#include "tests/support/boolean_sample_part.hpp"

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/brep/boolean/boolean_expected.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"
#include "src/fit/skin.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

using cg::kPi;

// Blade thickness |S_ss - S_ps| at chordwise fraction x and span v.
double blade_thickness(const blade::BladeCoordinates& bc, double v, double x) {
  return (bc.frame(v, x).point - bc.frame(v, -x).point).norm();
}

BSplineCurve<2> shifted_r(const BSplineCurve<2>& c, double dr) {
  std::vector<Eigen::Vector2d> poles = c.poles();
  for (Eigen::Vector2d& p : poles) p.y() += dr;
  return BSplineCurve<2>(c.degree(), c.knots(), poles, c.is_rational() ? c.weights() : std::vector<double>{});
}

brep::NamedShape named_solid(const TopoDS_Shape& s, const std::string& name) {
  brep::NamedShape n{s, {}};
  for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) n.faces.push_back({TopoDS::Face(e.Current()), name});
  return n;
}

}  // namespace

HollowBlade make_hollow_blade(const blade::BladeModel& model, const HollowBladeOptions& o) {
  require(o.wall > 0 && o.end_wall > 0 && o.min_cavity > 0, "hollow blade: wall, end_wall and min_cavity must be > 0");
  require(o.chord_start > 0 && o.chord_start < 0.5, "hollow blade: chord_start must be in (0, 0.5)");
  require(o.sections >= 4 && o.points_per_side >= 8, "hollow blade: at least 4 sections and 8 points per side");
  const blade::BladeCoordinates bc(model);
  const double ob = model.options.overbuild;
  std::vector<double> spans;
  for (int j = 0; j < o.sections; ++j) spans.push_back(-ob + (1 + 2 * ob) * j / (o.sections - 1));

  // x1: the largest chordwise fraction (step 0.01) up to which the blade is thick enough on every span.
  HollowBlade hb;
  hb.chord_start = o.chord_start;
  const double need = 2 * o.wall + o.min_cavity;
  double x1 = o.chord_start;
  for (double x = o.chord_start; x <= 0.95; x += 0.01) {
    bool ok = true;
    for (double v : spans) ok = ok && blade_thickness(bc, v, x) >= need;
    if (!ok) break;
    x1 = x;
  }
  require(x1 >= o.chord_start + 0.2, "hollow blade: the blade is thinner than 2 wall + min_cavity = " +
                                         format_number(need) + " mm over most of the chord");
  hb.chord_end = x1;

  std::vector<BSplineCurve<3>> sections;
  const int m = o.points_per_side;
  // The points are uniform in theta, a smooth parametrisation: the same parameters (and so the same
  // knots) on every section keep the skinned surface as small as one section.
  std::vector<double> params;
  for (int k = 0; k < 2 * m; ++k) params.push_back(static_cast<double>(k) / (2 * m));
  const std::vector<double> knots = periodic_interpolation_knots(params, 3);
  for (double v : spans) {
    PointList<3> pts;
    auto core_point = [&](double theta, double side) {
      const double x = o.chord_start + (x1 - o.chord_start) * 0.5 * (1 - std::cos(theta));
      const Eigen::Vector3d ss = bc.frame(v, x).point, ps = bc.frame(v, -x).point;
      const Eigen::Vector3d mid = 0.5 * (ss + ps);
      const double h = (ss - ps).norm();
      const Eigen::Vector3d s = side > 0 ? ss : ps;
      return Eigen::Vector3d(mid + (s - mid) * (1 - 2 * o.wall / h) * (1 - std::pow(1 - std::sin(theta), 3)));
    };
    for (int k = 0; k < m; ++k) pts.push_back(core_point(kPi * k / m, 1));   // LE end, then suction side
    for (int k = m; k > 0; --k) pts.push_back(core_point(kPi * k / m, -1));  // TE end, back on pressure side
    sections.push_back(interpolate_closed<3>(pts, 3, params, knots));
  }
  hb.core_surface = skin(sections).surface;

  brep::EndTrim hub = brep::hub_trim(model.trim), casing = brep::casing_trim(model.trim);
  if (auto* p = std::get_if<brep::PlaneTrim>(&hub)) p->point.z() += o.end_wall;
  if (auto* p = std::get_if<brep::PlaneTrim>(&casing)) p->point.z() -= o.end_wall;
  if (auto* r = std::get_if<brep::RevolvedTrim>(&hub)) r->meridional = shifted_r(r->meridional, o.end_wall);
  if (auto* r = std::get_if<brep::RevolvedTrim>(&casing)) r->meridional = shifted_r(r->meridional, -o.end_wall);

  const brep::BladeSolid outer = brep::build_blade_solid(model);
  const brep::BladeSolid core = brep::build_blade_solid(hb.core_surface, hub, casing);
  brep::NamedShape part{outer.solid, outer.faces};
  brep::NamedShape tool{core.solid, {}};
  for (const brep::NamedFace& f : core.faces) {
    const std::string name = f.name == brep::kWallFaceName ? "chamber_1_wall"
                             : f.name == brep::kHubFaceName ? "hub_floor"
                                                            : "tip_cap";
    tool.faces.push_back({f.face, name});
  }

  BooleanOptions bo;
  bo.parallel = true;
  bo.verification = o.verify ? Verification::EachStep : Verification::None;
  BooleanStep step(BooleanOperation::Cut, bo);
  FeatureTool core_tool;
  core_tool.feature = "chamber_1";
  core_tool.shape = tool;
  core_tool.expected_volume = occt_volume(core.solid);  // the core lies inside the blade
  step.add(core_tool);
  hb.part = step.apply(part);
  hb.volume = o.verify ? step.report().check.volume : occt_volume(hb.part.shape);
  return hb;
}

std::vector<FeatureTool> make_hole_tools(const blade::BladeModel& model, const HollowBlade& part,
                                         const HoleFieldOptions& o) {
  require(o.count >= 1, "holes: count must be >= 1");
  require(o.diameter > 0 && o.inclination_deg >= 10 && o.inclination_deg <= 90,
          "holes: diameter > 0 and inclination in [10, 90] degrees required");
  require(o.span_min < o.span_max && o.band_min < o.band_max, "holes: empty field");
  const blade::BladeCoordinates bc(model);
  RaySurfaceCaster outer(model.surface), inner(part.core_surface);
  const double r = 0.5 * o.diameter, a = o.inclination_deg * kPi / 180;
  const double x0 = part.chord_start + (part.chord_end - part.chord_start) * o.band_min;
  const double x1 = part.chord_start + (part.chord_end - part.chord_start) * o.band_max;

  // Grid: rows chordwise (split between the two sides), holes spanwise, about square cells.
  const double span_len = (bc.frame(o.span_max, 0.5 * (x0 + x1)).point - bc.frame(o.span_min, 0.5 * (x0 + x1)).point).norm();
  double side_len = 0;
  for (int k = 0; k < 20; ++k) side_len += (bc.frame(0.5, x0 + (x1 - x0) * (k + 1) / 20).point - bc.frame(0.5, x0 + (x1 - x0) * k / 20).point).norm();
  int rows = std::max(2, 2 * static_cast<int>(std::lround(0.5 * std::sqrt(o.count * 2 * side_len / span_len))));
  const int per_row = (o.count + rows - 1) / rows;

  // Quadrature of the removed volume: Gauss-Legendre in rho (weight rho), trapezoid in phi.
  static const double gx[6] = {0.033765242898424, 0.169395306766868, 0.380690406958402,
                               0.619309593041598, 0.830604693233132, 0.966234757101576};
  static const double gw[6] = {0.085662246189585, 0.180380786524069, 0.233956967286346,
                               0.233956967286346, 0.180380786524069, 0.085662246189585};
  constexpr int kPhi = 16;

  std::vector<FeatureTool> tools;
  for (int row = 0; row < rows && static_cast<int>(tools.size()) < o.count; ++row) {
    const bool suction = row % 2 == 0;
    const int k = row / 2, side_rows = rows / 2;
    const double x = x0 + (x1 - x0) * (k + 0.5) / side_rows;
    const double stagger = (k % 2) * 0.5;
    for (int j = 0; j < per_row && static_cast<int>(tools.size()) < o.count; ++j) {
      const double span = o.span_min + (o.span_max - o.span_min) * (j + 0.25 + stagger) / per_row;
      const blade::BladeFrame f = bc.frame(span, suction ? x : -x);
      const Eigen::Vector3d down = suction ? f.chord_tangent : Eigen::Vector3d(-f.chord_tangent);
      const Eigen::Vector3d d = (-std::sin(a) * f.normal - std::cos(a) * down).normalized();
      Eigen::Vector3d e1 = d.cross(f.span_tangent).normalized();
      const Eigen::Vector3d e2 = d.cross(e1);
      const double s_out = (o.clearance + r * std::cos(a)) / std::sin(a) + 0.1;  // axis length outside
      const Eigen::Vector3d start = f.point - s_out * d;
      // Every quadrature line enters the wall (outer surface) and leaves it (core surface); the tool
      // ends `clearance` (measured along the surface normal) past the last exit.
      const double along = o.clearance / std::sin(a);
      double volume = 0, s_min = HUGE_VAL, s_max = 0;
      for (int q = 0; q < 6; ++q)
        for (int p = 0; p < kPhi; ++p) {
          const double rho = r * gx[q], phi = 2 * kPi * p / kPhi;
          const Eigen::Vector3d origin = start + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
          const RaySurfaceHit ho = outer.first_hit(origin, d, 30), hi = inner.first_hit(origin, d, 30);
          require(ho.found && hi.found && ho.ray_param < hi.ray_param,
                  "holes: a hole does not cross the wall into the core (span " + format_number(span) + ")");
          s_min = std::min(s_min, ho.ray_param);
          s_max = std::max(s_max, hi.ray_param);
          volume += gw[q] * rho * r * (hi.ray_param - ho.ray_param) * (2 * kPi / kPhi);
        }
      const double length = s_max + along + r * std::cos(a) / std::sin(a);
      require(s_min > 0.5 * along, "holes: a hole tool starts too close to the outer surface");
      // The far side of the cavity must stay clear of the tool's end.
      const RaySurfaceHit far = inner.first_hit(start + (s_max + 1e-6) * d, d, 30);
      require(!far.found || far.ray_param > length - s_max + 0.5 * along,
              "holes: the cavity is too thin for a hole at span " + format_number(span));
      char name[64];
      std::snprintf(name, sizeof name, "%s%d_hole_%03d", o.name_prefix.c_str(), row + 1, j + 1);
      const gp_Ax2 ax(gp_Pnt(start.x(), start.y(), start.z()), gp_Dir(d.x(), d.y(), d.z()),
                      gp_Dir(e1.x(), e1.y(), e1.z()));
      FeatureTool t;
      t.feature = name;
      t.shape = named_solid(BRepPrimAPI_MakeCylinder(ax, r, length).Shape(), name);
      t.expected_volume = volume;
      t.symmetry_axis = gp_Ax1(ax.Location(), ax.Direction());
      tools.push_back(std::move(t));
    }
  }
  return tools;
}

}  // namespace cg::features
