#include "features/passages/passage_checks.hpp"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "src/brep/naming/face_names.hpp"
#include "features/passages/span_sections.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {
namespace {

using Vec3 = Eigen::Vector3d;

bool matches(const std::string& name, const std::vector<std::string>& patterns) {
  for (const std::string& p : patterns) {
    if (!p.empty() && p.back() == '*') {
      if (name.compare(0, p.size() - 1, p, 0, p.size() - 1) == 0) return true;
    } else if (name == p) {
      return true;
    }
  }
  return false;
}

TopoDS_Compound compound_of(const std::vector<TopoDS_Face>& faces) {
  BRep_Builder bb;
  TopoDS_Compound c;
  bb.MakeCompound(c);
  for (const auto& f : faces) bb.Add(c, f);
  return c;
}

std::vector<TopoDS_Face> faces_named(const brep::NamedShape& s, const std::vector<std::string>& patterns) {
  std::vector<TopoDS_Face> out;
  for (const auto& f : s.faces)
    if (matches(f.name, patterns)) out.push_back(f.face);
  return out;
}

double tolerance_for(double configured) { return std::max(0.01, 0.01 * configured); }

// Points on a face: a uv grid kept where inside the face's boundary.
std::vector<Vec3> face_samples(const TopoDS_Face& f, int n) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(f, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d cls(f, 1e-9);
  const Handle(Geom_Surface) s = BRep_Tool::Surface(f);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / n, v = v0 + (v1 - v0) * (j + 0.5) / n;
      if (cls.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      const gp_Pnt p = s->Value(u, v);
      out.emplace_back(p.X(), p.Y(), p.Z());
    }
  return out;
}

}  // namespace

ThicknessMeasure measure_between(const brep::NamedShape& shape, const std::string& feature,
                                 const std::vector<std::string>& side_a, const std::vector<std::string>& side_b,
                                 double configured) {
  ThicknessMeasure t;
  t.feature = feature;
  t.configured = configured;
  t.tolerance = tolerance_for(configured);
  t.method = "BRepExtrema_DistShapeShape";
  const auto a = faces_named(shape, side_a), b = faces_named(shape, side_b);
  if (a.empty() || b.empty()) throw FeatureFailure("thickness of " + feature + ": no faces on one side");
  BRepExtrema_DistShapeShape d;
  d.SetMultiThread(true);  // the face pairs on both cores; the same minimum
  d.LoadS1(compound_of(a));
  d.LoadS2(compound_of(b));
  d.Perform();
  if (!d.IsDone()) throw FeatureFailure("thickness of " + feature + ": BRepExtrema_DistShapeShape failed");
  t.min = d.Value();
  t.passed = t.min >= configured - t.tolerance;
  return t;
}

std::vector<PassageMeasure> passage_sections(const blade::BladeModel& model, const brep::NamedShape& cooled,
                                             const std::vector<double>& spans,
                                             const std::vector<std::string>& passages) {
  std::vector<PassageMeasure> out(passages.size());
  for (std::size_t k = 0; k < passages.size(); ++k) out[k].name = passages[k];
  if (passages.empty()) return out;
  // The sections of sections.svg and report.json "sections" (span_sections.hpp), on this solid. Their
  // spans lie between the turnaround gaps: every cavity has the walls of one passage.
  const std::vector<SpanSection> cuts = span_sections({{"blade", cooled}}, span_surfaces(model, spans));
  for (const SpanSection& cut : cuts)
    for (const SectionPassage& p : cut.passages) {
      const auto it = std::find(passages.begin(), passages.end(), p.name);
      if (it == passages.end() || !(p.area > 0)) continue;
      out[static_cast<std::size_t>(it - passages.begin())].sections.push_back({cut.span, p.area, p.wetted_perimeter, p.hydraulic_diameter});
    }
  return out;
}

namespace {

// Outer wall: minimum by BRepExtrema between the outer wall and every face of the chambers;
// maximum and the local value against a varying thickness from points on the chamber walls,
// projected onto the outer wall (global projection, src/algo/project_point_surface).
ThicknessMeasure outer_wall_thickness(const blade::BladeCoordinates& coords, const brep::NamedShape& cooled,
                                      const CoreDefinition& cd, const PassageReport& report) {
  ThicknessMeasure wall;
  if (std::isnan(report.wall_clearance)) {
    wall = measure_between(cooled, "outer_wall", {"blade_wall"}, {"chamber_*", "rib_*", "turnaround_*"},
                           cd.wall_thickness.min_value());
  } else {  // measured between the same faces when the chambers were inserted (passage_boolean.hpp)
    wall.feature = "outer_wall";
    wall.configured = cd.wall_thickness.min_value();
    wall.tolerance = tolerance_for(wall.configured);
    wall.min = report.wall_clearance;
    wall.passed = wall.min >= wall.configured - wall.tolerance;
    wall.method = "BRepExtrema_DistShapeShape";
  }
  double max_d = 0, worst = 0;
  for (const auto& f : faces_named(cooled, {"chamber_*"}))
    for (const Vec3& p : face_samples(f, 10)) {
      const blade::BladeLocateResult r = coords.locate(p);
      if (!r.found) continue;
      max_d = std::max(max_d, r.coordinate.depth);
      worst = std::max(worst, cd.wall_thickness.at(r.coordinate.span, r.coordinate.chord) - r.coordinate.depth);
    }
  wall.max = max_d;
  wall.method += " (min); sampled projection onto the outer wall (max, local value)";
  wall.passed = wall.passed && worst <= wall.tolerance;
  return wall;
}

// Rib i: its two sides (faces named rib_<i>, told apart by the side of the mid-surface they lie on).
ThicknessMeasure rib_thickness(const blade::BladeCoordinates& coords, const brep::NamedShape& cooled, const CoreDefinition& cd,
                               std::size_t i) {
  const std::string name = "rib_" + std::to_string(i + 1);
  const RibMidSurface mid(coords, cd.wall_thickness, cd.ribs[i]);
  std::vector<TopoDS_Face> le_side, te_side;
  for (const auto& f : faces_named(cooled, {name})) {
    const auto pts = face_samples(f, 5);
    if (pts.empty()) continue;
    const blade::BladeLocateResult r = coords.locate(pts.front());
    Vec3 n, t;
    mid.frame(0.5, r.coordinate.span, n, t);
    ((pts.front() - mid.point(0.5, r.coordinate.span)).dot(n) > 0 ? te_side : le_side).push_back(f);
  }
  ThicknessMeasure m;
  m.feature = name;
  m.configured = cd.ribs[i].thickness;
  m.tolerance = tolerance_for(m.configured);
  m.method = "BRepExtrema_DistShapeShape between its two sides";
  if (le_side.empty() || te_side.empty()) throw FeatureFailure(name + ": cannot find both of its sides on the blade");
  BRepExtrema_DistShapeShape d(compound_of(le_side), compound_of(te_side));
  m.min = d.IsDone() ? d.Value() : 0;
  double mx = 0;
  for (const auto& f : le_side)
    for (const Vec3& p : face_samples(f, 4)) {
      BRepExtrema_DistShapeShape dp(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex(), compound_of(te_side));
      if (dp.IsDone()) mx = std::max(mx, dp.Value());
    }
  m.max = mx;
  m.passed = m.min >= m.configured - m.tolerance;
  return m;
}

// The core's measurements: its report fields, wall, end wall and rib thicknesses, volumes; the spans of
// its cross-sections and its passages (chambers) appended to `spans` and `passages`.
void measure_core(const blade::BladeModel& model, const brep::NamedShape& cooled, const CoreDefinition& cd,
                  const CoreBuild& core, PassageReport& report, std::vector<double>& spans, std::vector<std::string>& passages) {
  report.inner_wall_poles_u = core.inner_wall.poles_u();
  report.inner_wall_poles_v = core.inner_wall.poles_v();
  report.inner_wall_fit_error = core.inner_wall.max_fit_error;
  const blade::BladeCoordinates coords(model);
  report.thickness.push_back(outer_wall_thickness(coords, cooled, cd, report));
  if (!cd.tip_cap.open)
    report.thickness.push_back(measure_between(cooled, "tip_cap", {"casing"}, {"tip_cap"}, cd.tip_cap.thickness));
  if (!cd.hub_floor.open)
    report.thickness.push_back(measure_between(cooled, "hub_floor", {"hub"}, {"hub_floor"}, cd.hub_floor.thickness));
  for (std::size_t i = 0; i < cd.ribs.size(); ++i) report.thickness.push_back(rib_thickness(coords, cooled, cd, i));
  // Volumes.
  report.volumes.push_back({"core", core.core_volume, "coolant + rib material before the ribs"});
  for (const auto& c : core.chambers) report.volumes.push_back({"chamber_" + std::to_string(c.number), c.volume, "coolant"});
  for (std::size_t i = 0; i < core.rib_volumes.size(); ++i) {
    report.volumes.push_back({"rib_" + std::to_string(i + 1), core.rib_volumes[i], "material"});
    report.volumes.push_back({"rib_" + std::to_string(i + 1) + "_fillets", core.fillet_volumes[i], "material"});
  }
  for (std::size_t m = 0; m < core.inlet_volumes.size(); ++m)
    report.volumes.push_back({"inlet_" + std::to_string(m + 1), core.inlet_volumes[m], "removed"});
  // Cross-sections on 10 spans where every rib is present (between the turnaround gaps).
  double lo = 0.05, hi = 0.95;
  for (const auto& r : core.ribs) {
    const std::size_t mid = r.stations.size() / 2;
    if (r.hub_junction[mid] > 0) lo = std::max(lo, r.hub_junction[mid] + 0.02);
    if (r.tip_junction[mid] < 1) hi = std::min(hi, r.tip_junction[mid] - 0.02);
  }
  for (int k = 0; k < 10; ++k) spans.push_back(lo + (hi - lo) * k / 9);
  for (const auto& c : core.chambers) {
    passages.push_back("chamber_" + std::to_string(c.number));
  }
}

// What feeds chamber `number` (its inlets, open ends, or the turnarounds of its system).
std::string chamber_fed_by(int number, const CoreDefinition& cd, const CoreBuild& core) {
  const ChamberInfo& c = core.chambers[static_cast<std::size_t>(number - 1)];
  std::string fed;
  for (std::size_t in = 0; in < cd.inlets.size(); ++in)
    if (cd.inlets[in].chamber == number) fed += (fed.empty() ? "" : ", ") + std::string("inlet_") + std::to_string(in + 1);
  if (cd.hub_floor.open) fed += std::string(fed.empty() ? "" : ", ") + "open hub";
  if (cd.tip_cap.open) fed += std::string(fed.empty() ? "" : ", ") + "open tip";
  if (fed.empty() && c.fed) fed = "through turnarounds (" + core.systems[static_cast<std::size_t>(c.system)].feature + ")";
  return fed.empty() ? "none" : fed;
}

}  // namespace

void measure_passages(const blade::BladeModel& model, const brep::NamedShape& cooled, const PassagesDefinition& def,
                      const CoreBuild* core, const RadialPassageBuild* radial, PassageReport& report) {
  // Cavities: a chamber system without an opening is a closed inner shell of the solid.
  int shells = 0;
  for (TopExp_Explorer e(cooled.shape, TopAbs_SHELL); e.More(); e.Next()) ++shells;
  report.closed_cavities = shells - 1;
  report.all_chambers_fed = report.closed_cavities == 0;

  std::vector<std::string> passages;
  std::vector<double> spans;
  if (core) measure_core(model, cooled, *def.core, *core, report, spans, passages);
  if (radial) {
    for (std::size_t k = 0; k < radial->tools.size(); ++k) {
      const std::string name = radial->tools[k].feature;
      report.thickness.push_back(measure_between(cooled, name + "_wall", {"blade_wall"}, {name}, std::numeric_limits<double>::quiet_NaN()));
      ThicknessMeasure& t = report.thickness.back();
      t.passed = t.min > 0;
      t.tolerance = 0;
      report.volumes.push_back({name, radial->tools[k].expected_volume, "removed"});
      passages.push_back(name);
    }
    if (spans.empty())
      for (int k = 0; k < 10; ++k) spans.push_back(0.05 + 0.9 * k / 9);
  }
  std::vector<PassageMeasure> measured = passage_sections(model, cooled, spans, passages);
  for (auto& m : measured) {
    for (const auto& v : report.volumes)
      if (v.feature == m.name) m.volume = v.volume;
    if (core && m.name.rfind("chamber_", 0) == 0)
      m.fed_by = chamber_fed_by(std::stoi(m.name.substr(8)), *def.core, *core);
    else
      m.fed_by = "both ends open";
  }
  report.passages = std::move(measured);
}

}  // namespace cg::features
