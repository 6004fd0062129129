#include "features/film/film_holes.hpp"

#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "features/drilling/drill_holes.hpp"
#include "features/film/hole_tool.hpp"
#include "src/algo/segment_distance.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

struct Box {
  Eigen::Vector3d lo, hi;
};

Box envelope_box(const HoleGeometry& g, double pad) {
  Box b{Eigen::Vector3d::Constant(HUGE_VAL), Eigen::Vector3d::Constant(-HUGE_VAL)};
  for (std::size_t k = 0; k < g.envelope_points.size(); ++k) {
    b.lo = b.lo.cwiseMin(g.envelope_points[k] - Eigen::Vector3d::Constant(g.envelope_radii[k] + pad));
    b.hi = b.hi.cwiseMax(g.envelope_points[k] + Eigen::Vector3d::Constant(g.envelope_radii[k] + pad));
  }
  return b;
}

}  // namespace

double hole_ligament(const HoleGeometry& a, const HoleGeometry& b) {
  double best = HUGE_VAL;
  const auto& pa = a.envelope_points;
  const auto& pb = b.envelope_points;
  for (std::size_t i = 0; i + 1 < pa.size(); ++i) {
    const double ra = std::max(a.envelope_radii[i], a.envelope_radii[i + 1]);
    for (std::size_t j = 0; j + 1 < pb.size(); ++j) {
      const double rb = std::max(b.envelope_radii[j], b.envelope_radii[j + 1]);
      best = std::min(best, segment_distance(pa[i], pa[i + 1], pb[j], pb[j + 1]) - ra - rb);
    }
  }
  return best;
}

FilmHoleTools analyse_film_holes(const HoleTarget& target, const std::vector<HoleSpec>& holes, const FilmLimits& limits,
                                 const HoleQuadrature& quadrature) {
  FilmHoleTools out;
  out.holes = holes;
  HoleAnalyser analyser(target, limits, quadrature);
  for (const HoleSpec& h : holes) out.geometry.push_back(analyser.analyse(h));

  // Ligaments: sweep over the envelopes' boxes along x.
  const std::size_t n = holes.size();
  out.ligament.assign(n, HUGE_VAL);
  out.ligament_to.assign(n, "");
  std::vector<Box> boxes;
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    boxes.push_back(envelope_box(out.geometry[i], 0.5 * limits.min_ligament + 0.5));
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  for (std::size_t oi = 0; oi < n; ++oi) {
    const std::size_t i = order[oi];
    for (std::size_t oj = oi + 1; oj < n && boxes[order[oj]].lo.x() <= boxes[i].hi.x(); ++oj) {
      const std::size_t j = order[oj];
      if ((boxes[i].lo.array() > boxes[j].hi.array()).any() || (boxes[j].lo.array() > boxes[i].hi.array()).any()) continue;
      const double lig = hole_ligament(out.geometry[i], out.geometry[j]);
      if (lig < out.ligament[i]) out.ligament[i] = lig, out.ligament_to[i] = holes[j].name;
      if (lig < out.ligament[j]) out.ligament[j] = lig, out.ligament_to[j] = holes[i].name;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (out.ligament[i] >= limits.min_ligament) continue;
    // Report the pair once, at the later hole (the later row for overlapping rows).
    const auto other = std::find_if(holes.begin(), holes.end(), [&](const HoleSpec& h) { return h.name == out.ligament_to[i]; });
    const HoleSpec& a = holes[i];
    const HoleSpec& b = *other;
    const HoleSpec& later = static_cast<std::size_t>(other - holes.begin()) > i ? b : a;
    const ValueLimitText t = format_value_limit(out.ligament[i], limits.min_ligament, Allowed::above);
    const std::string what = (out.ligament[i] < 0 ? a.name + " and " + b.name + " overlap by " + format_number(-out.ligament[i]) + " mm"
                                                  : "ligament between " + a.name + " and " + b.name + " is " + t.value +
                                                        " mm (least metal between the holes, a lower bound)") +
                             ", the ligament must be at least film_limits.min_ligament = " + t.limit + " mm";
    if (a.row == b.row) throw FilmInputError(later.field + later.spacing_field, "pitch too small: " + what);
    throw FilmInputError(later.field + later.position_field, "overlapping rows " + a.row + " and " + b.row + ": " + what);
  }
  return out;
}

FilmHoleTools make_film_hole_tools(const HoleTarget& target, const std::vector<HoleSpec>& holes, const FilmLimits& limits,
                                   const HoleQuadrature& quadrature) {
  FilmHoleTools out = analyse_film_holes(target, holes, limits, quadrature);
  add_hole_tools(out);
  return out;
}

void check_film_holes_against(FilmHoleTools& holes, const std::vector<TargetObstacle>& obstacles, const FilmLimits& limits) {
  for (std::size_t i = 0; i < holes.holes.size(); ++i)
    for (const TargetObstacle& ob : obstacles) check_hole_obstacle(holes.holes[i], holes.geometry[i], ob, limits);
}

void add_hole_tools(FilmHoleTools& out) {
  const std::vector<HoleSpec>& holes = out.holes;
  out.tools.clear();
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const HoleSpec& h = holes[i];
    const HoleGeometry& g = out.geometry[i];
    FeatureTool t;
    t.feature = h.name;
    t.shape = named_all_faces(make_hole_solid(h.frame, h.shape, g.extent), h.name);
    t.expected_volume = g.expected_volume;
    if (h.shape.kind == HoleKind::Cylindrical) {
      const Eigen::Vector3d p = h.frame.exit + g.extent.s_top * h.frame.axis;
      t.symmetry_axis = gp_Ax1(gp_Pnt(p.x(), p.y(), p.z()), gp_Dir(h.frame.axis.x(), h.frame.axis.y(), h.frame.axis.z()));
    }
    out.tools.push_back(std::move(t));
  }
}

BooleanOptions film_boolean_options(ProgressSink* progress) {
  BooleanOptions o;
  o.progress = progress;
  return o;
}

FilmCutResult cut_film_holes(const brep::NamedShape& blade, const HoleTarget& target, const FilmHoleTools& tools,
                             const BooleanOptions& options) {
  FilmCutResult out;
  // Straight cylinders with a square end are drilled directly (drill_holes.hpp: linear in the number of
  // holes, each verified locally); shaped holes and oblique-ended tools go through the boolean step.
  std::vector<CylindricalHole> cylinders;
  std::vector<std::size_t> boolean_tools;
  for (std::size_t i = 0; i < tools.holes.size(); ++i) {
    const HoleSpec& h = tools.holes[i];
    const HoleToolExtent& e = tools.geometry[i].extent;
    if (h.shape.kind == HoleKind::Cylindrical && e.end_normal.isZero()) {
      CylindricalHole c;
      c.name = h.name;
      c.origin = h.frame.exit + e.s_top * h.frame.axis;
      c.axis = h.frame.axis;
      c.diameter = h.shape.diameter;
      c.length = e.s_end - e.s_top;
      cylinders.push_back(std::move(c));
    } else {
      boolean_tools.push_back(i);
    }
  }
  FilmReport& rep = out.report;
  std::map<std::string, std::pair<double, bool>> measured;  // hole -> (removed volume, passed)
  out.blade = blade;
  // The boolean step first, on the undrilled part: OCCT's booleans meet the drilled walls' many inner
  // wires badly (wrong removed volumes on the built-in example), while drilling re-plans on any part.
  if (!boolean_tools.empty()) {
    BooleanStep step(BooleanOperation::Cut, options);
    for (std::size_t i : boolean_tools) step.add(tools.tools[i]);
    out.blade = step.apply(out.blade);
    const BooleanStepReport& br = step.report();
    out.check = br.check;
    out.checked = options.verification == Verification::EachStep;
    rep.tool_clusters = br.cluster_count;
    rep.boolean_runs += br.boolean_runs;
    for (const ToolReport& t : br.tools) measured[t.feature] = {t.cluster < 0 ? t.measured_volume : 0.0, t.passed};
    rep.seconds.emplace_back("boolean", br.seconds);
    append_perturbed_tools(br, rep.perturbed);
  }
  if (!cylinders.empty()) {
    DrillOptions d;
    d.fallback = options;
    const DrillResult dr = drill_holes(out.blade, cylinders, d);
    out.checked = false;  // the drilled part is checked locally; the verify stage checks it globally
    out.blade = dr.part;
    rep.drilled_holes = dr.drilled;
    rep.seconds.emplace_back("drill", dr.seconds);
    for (const DrilledHole& h : dr.holes) measured[h.name] = {h.volume, true};  // drill_holes throws on a failed check
    for (const ToolReport& t : dr.fallback.tools)
      if (t.cluster < 0) measured[t.feature] = {t.measured_volume, t.passed};
    rep.boolean_runs += dr.fallback.boolean_runs;
    append_perturbed_tools(dr.fallback, rep.perturbed);
  }
  std::vector<std::pair<std::string, double>> row_pitch;
  for (std::size_t i = 0; i < tools.holes.size(); ++i) {
    const HoleSpec& h = tools.holes[i];
    const HoleGeometry& g = tools.geometry[i];
    if (row_pitch.empty() || row_pitch.back().first != h.row) row_pitch.emplace_back(h.row, h.pitch);
    HoleMeasure m;
    m.name = h.name;
    m.row = h.row;
    m.chamber = target.chambers[g.chamber].name;
    m.shape = h.shape.kind == HoleKind::Cylindrical ? "cylindrical" : "fan_shaped";
    m.span = h.span;
    m.chord = h.chord;
    for (int k = 0; k < 3; ++k) m.exit[k] = h.frame.exit[k], m.axis[k] = h.frame.axis[k];
    m.diameter = h.shape.diameter;
    m.inclination_deg = g.inclination_deg;
    m.length = g.length;
    m.length_d = g.length / h.shape.diameter;
    m.metering_length = g.metering_length;
    m.metering_length_d = g.metering_length / h.shape.diameter;
    m.diffuser_length = g.diffuser_length;
    m.metering_area = g.metering_area;
    m.exit_area = g.exit_area;
    m.area_ratio = g.exit_area / g.metering_area;
    m.footprint_area = g.footprint_area;
    m.breakout_width = g.breakout_width;
    m.expected_volume = g.expected_volume;
    const auto it = measured.find(h.name);
    if (it != measured.end()) {
      m.measured_volume = it->second.first;  // 0 when measured with its cluster of overlapping tools
      m.volume_passed = it->second.second;
    }
    m.ligament = tools.ligament[i];
    m.ligament_to = tools.ligament_to[i];
    m.obstacle_ligament = g.obstacle_ligament;
    m.nearest_obstacle = g.nearest_obstacle;
    rep.holes.push_back(m);
  }
  summarise_film_report(rep, row_pitch);
  return out;
}

}  // namespace cg::features
