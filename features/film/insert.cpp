#include "features/film/insert.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "features/film/hole_analysis.hpp"
#include "features/film/hole_rays.hpp"
#include "features/film/hole_target.hpp"
#include "features/film/hole_tool.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/brep/occt_progress.hpp"
#include "src/brep/solid_integrals.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {




// The solid between the ends, split by the rib walls (grown by `grow`); the piece holding `reference` kept.
TopoDS_Shape chamber_solid(const BSplineSurface<3>& surface, const brep::EndTrim& hub, const brep::EndTrim& tip,
                           const InsertChamber& chamber, double grow, const std::string& what) {
  TopoDS_Shape s = brep::build_blade_solid(surface, hub, tip).solid;
  if (!chamber.rib_walls) return s;
  const std::vector<TopoDS_Shape> walls = chamber.rib_walls(grow);
  if (walls.empty()) return s;
  TopTools_ListOfShape args, tools;
  args.Append(s);
  for (const TopoDS_Shape& t : walls) tools.Append(t);
  BRepAlgoAPI_Splitter split;
  split.SetArguments(args);
  split.SetTools(tools);
  split.Build();
  if (!split.IsDone() || split.HasErrors()) throw FeatureFailure(what + ": splitting by the rib walls failed");
  for (TopExp_Explorer e(split.Shape(), TopAbs_SOLID); e.More(); e.Next()) {
    BRepClass3d_SolidClassifier in(e.Current(), occt::to_pnt(chamber.reference), 1e-7);
    if (in.State() == TopAbs_IN) return e.Current();
  }
  throw FeatureFailure(what + ": no piece between the ribs holds the chamber's reference point");
}

// Arc-length table of a curve given by points.
std::vector<double> arc_table(const std::vector<Eigen::Vector3d>& p) {
  std::vector<double> a{0};
  for (std::size_t i = 1; i < p.size(); ++i) a.push_back(a.back() + (p[i] - p[i - 1]).norm());
  return a;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - x.begin()), 1, x.size() - 1);
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

// Positions in [lo, hi] spaced `pitch` apart and centred, shifted by `shift` (dropped past the ends).
std::vector<double> spaced(double lo, double hi, double pitch, double shift) {
  std::vector<double> x;
  if (hi < lo) return x;
  const int n = 1 + static_cast<int>(std::floor((hi - lo) / pitch + 1e-9));
  const double x0 = lo + 0.5 * ((hi - lo) - (n - 1) * pitch) + shift;
  for (int k = 0; k < n; ++k)
    if (x0 + k * pitch <= hi + 1e-12) x.push_back(x0 + k * pitch);
  return x;
}

struct Jet {
  Eigen::Vector3d exit, axis;  // on the insert's outer surface; into the insert
  double span = 0, chord = 0;
};

}  // namespace

void check_insert_input(const InsertChamber& chamber, const InsertDefinition& def, int index, const std::string& field) {
  const std::string name = "insert_" + std::to_string(index);
  const double Z = def.gap, D = def.jet_diameter;
  if (!(chamber.wall_thickness > 0))
    throw FilmInputError(field + ".chamber", name + ": inserts need a constant wall thickness of the core over their chamber (" +
                                                 chamber.name + "'s wall varies)");
  if (!chamber.refusal.empty()) throw FilmInputError(field + ".chamber", name + ": " + chamber.refusal);
  if (!(Z > 0)) throw FilmInputError(field + ".gap", name + ": the gap must be > 0");
  if (Z < chamber.min_gap) {
    const ValueLimitText t = format_value_limit(Z, chamber.min_gap, Allowed::above);
    throw FilmInputError(field + ".gap", name + ": the gap " + t.value + " mm is below " + chamber.min_gap_reason + " (" + t.limit +
                                             " mm): the gap in the corners would fall below Z");
  }
  if (!(def.sheet_thickness > 0)) throw FilmInputError(field + ".sheet_thickness", name + ": the sheet thickness must be > 0");
  if (def.jet_spacing_x_d < 2) throw FilmInputError(field + ".jets.spacing_x_d", name + ": x/D must be >= 2");
  if (def.jet_spacing_y_d < 2) throw FilmInputError(field + ".jets.spacing_y_d", name + ": y/D must be >= 2");
  if (D >= Z * 4 || D <= 0) throw FilmInputError(field + ".jets.diameter", name + ": the jet diameter must be in (0, 4 Z)");
}

namespace {

// The insert's sheet as two solids (outer minus inner is the sheet) and its outer ends.
struct InsertSolids {
  brep::EndTrim hub_o, tip_o;
  TopoDS_Shape outer, inner;
};

// Offsets of the wall: the insert's outer and inner sheet surfaces (into `out`), and the solids they bound.
InsertSolids insert_solids(const blade::BladeModel& model, const InsertChamber& chamber, const InsertDefinition& def,
                           const std::string& name, const std::string& field, InsertBuild& out) {
  const double tw = chamber.wall_thickness, Z = def.gap, ts = def.sheet_thickness;
  try {
    out.outer_surface = blade::build_inner_wall(model, blade::ThicknessField::constant(tw + Z));
    out.inner_surface = blade::build_inner_wall(model, blade::ThicknessField::constant(tw + Z + ts));
  } catch (const blade::InnerWallError& e) {
    throw FilmInputError(field + ".gap", name + " does not fit in " + chamber.name + ": its sheet lies " + format_number(tw + Z) +
                                             " to " + format_number(tw + Z + ts) + " mm inside the outer wall (" + e.what() + ")");
  }
  // Ends: the end walls moved into the chamber by the gap (outer); closed ends keep a cap of the sheet
  // thickness, open ends let the inner solid run out through the outer one's end.
  const double hub_gap = std::isnan(def.hub_gap) ? Z : def.hub_gap, tip_gap = std::isnan(def.tip_gap) ? Z : def.tip_gap;
  if (hub_gap < 0 || tip_gap < 0) throw FilmInputError(field + (hub_gap < 0 ? ".hub_gap" : ".tip_gap"), name + ": end gaps must be >= 0");
  const brep::EndTrim hub_o = chamber.hub_end(hub_gap), tip_o = chamber.tip_end(tip_gap);
  const brep::EndTrim hub_i = chamber.hub_end(def.hub_open ? hub_gap - ts : hub_gap + ts);
  const brep::EndTrim tip_i = chamber.tip_end(def.tip_open ? tip_gap - ts : tip_gap + ts);
  TopoDS_Shape outer, inner;
  try {
    outer = chamber_solid(out.outer_surface.surface, hub_o, tip_o, chamber, Z, name);
    inner = chamber_solid(out.inner_surface.surface, hub_i, tip_i, chamber, Z + ts, name);
  } catch (const AlgorithmFailure& e) {
    throw FilmInputError(field + ".gap", name + " does not fit in " + chamber.name + " (" + e.what() + ")");
  }
  return InsertSolids{hub_o, tip_o, outer, inner};
}

// Points on the insert's outer surface (the wall offset by `off`, jets into the insert) and their
// distances to the insert's ends.
struct SheetPoints {
  blade::BladeCoordinates coords;
  double off = 0;
  std::function<double(const Eigen::Vector3d&)> hub_dist, tip_dist;

  Jet on_insert(double s, double c) const {
    const blade::BladeFrame f = coords.frame(s, c);
    return Jet{f.point - off * f.normal, -f.normal, s, c};
  }
  // Span of a point where the distance to an end is `need` (bisection on the insert's line at chord c).
  double span_at(double c, bool hub, double need) const {
    double lo = -0.2, hi = 1.2;  // the distance to the hub end grows with span, to the tip end falls
    for (int it = 0; it < 36; ++it) {  // 1.4 / 2^36: far below a micrometre
      const double mid = 0.5 * (lo + hi);
      const Eigen::Vector3d p = on_insert(mid, c).exit;
      if (hub)
        (hub_dist(p) < need ? lo : hi) = mid;
      else
        (tip_dist(p) < need ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

// Jet lines around the chamber at mid-span of the insert (`body`: the insert's sheet).
std::vector<Jet> place_jets(const SheetPoints& sp, const InsertChamber& chamber, const InsertDefinition& def,
                            const InsertBuild& build, const TopoDS_Shape& body, const std::string& name, const std::string& field) {
  const double ts = def.sheet_thickness, D = def.jet_diameter, off = sp.off;
  const blade::BladeCoordinates& coords = sp.coords;
  const double c_lo = std::max(chamber.pressure_from, build.inner_surface.max_pressure_chord);
  const double c_hi = std::min(chamber.suction_to, build.inner_surface.min_suction_chord);
  const double margin = def.jet_margin + 0.5 * D;
  const double s_mid = 0.5 * (sp.span_at(0, true, 0) + sp.span_at(0, false, 0));
  // The chord range [c_lo, c_hi] runs between the ribs' centre lines; the sheet stops short of them by
  // half a rib and the gap (the rib walls grown by Z), more where a rib leans. So the ring runs where
  // the sheet is: the middle of the sheet inside the insert body, its ends found by bisection.
  const auto in_sheet = [&](double c) {
    const blade::BladeFrame f = coords.frame(s_mid, c);
    BRepClass3d_SolidClassifier cls(body, gp_Pnt(f.point.x() - (off + 0.5 * ts) * f.normal.x(), f.point.y() - (off + 0.5 * ts) * f.normal.y(),
                                                 f.point.z() - (off + 0.5 * ts) * f.normal.z()),
                                    1e-7);
    return cls.State() == TopAbs_IN;
  };
  const auto sheet_end = [&](double in, double out) {  // in_sheet(in), !in_sheet(out)
    for (int it = 0; it < 30; ++it) {  // |c_hi - c_lo| / 2^30 of chord: far below a micrometre
      const double mid = 0.5 * (in + out);
      (in_sheet(mid) ? in : out) = mid;
    }
    return in;
  };
  const double c_mid = 0.5 * (c_lo + c_hi);
  if (!in_sheet(c_mid)) throw FeatureFailure(name + ": the middle of its jet ring is not in the insert's sheet");
  const double r_lo = in_sheet(c_lo) ? c_lo : sheet_end(c_mid, c_lo), r_hi = in_sheet(c_hi) ? c_hi : sheet_end(c_mid, c_hi);
  std::vector<Eigen::Vector3d> ring;
  std::vector<double> chords;
  for (int k = 0; k <= 400; ++k) {
    const double c = r_lo + (r_hi - r_lo) * k / 400.0;
    ring.push_back(sp.on_insert(s_mid, c).exit);
    chords.push_back(c);
  }
  const std::vector<double> arc = arc_table(ring);
  const std::vector<double> lines = spaced(margin, arc.back() - margin, def.jet_spacing_x_d * D, 0);
  if (lines.empty())
    throw FilmInputError(field + ".jets.spacing_x_d", name + ": no room for a line of jets around " + chamber.name);
  std::vector<Jet> jets;
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const double c = interpolate(arc, chords, lines[li]);
    const double s0 = sp.span_at(c, true, margin + (def.hub_open ? 0 : ts)), s1 = sp.span_at(c, false, margin + (def.tip_open ? 0 : ts));
    if (s1 <= s0) throw FilmInputError(field + ".jets.margin", name + ": no room for jets between the insert's ends");
    std::vector<Eigen::Vector3d> line;
    std::vector<double> spans;
    // Each span is a new section (an iso-curve with its arc-length map): 32 chords of the line.
    for (int k = 0; k <= 32; ++k) {
      spans.push_back(s0 + (s1 - s0) * k / 32.0);
      line.push_back(sp.on_insert(spans.back(), c).exit);
    }
    const std::vector<double> la = arc_table(line);
    const double pitch = def.jet_spacing_y_d * D;
    for (double a : spaced(0, la.back(), pitch, def.staggered && li % 2 == 1 ? 0.5 * pitch : 0))
      jets.push_back(sp.on_insert(interpolate(la, spans, a), c));
  }
  return jets;
}

// Jet tool `jn`: from the middle of the gap through the sheet, `clear` past its inner surface; expected
// removal by ray quadrature (gx, gw: Gauss-Legendre on [0, 1]) between the two offset surfaces.
FeatureTool jet_tool(const Jet& jet, const char* jn, NearCaster& entry, NearCaster& exit, const std::vector<double>& gx,
                     const std::vector<double>& gw, const InsertDefinition& def, const std::string& field) {
  constexpr int kAngles = 16;
  const double Z = def.gap, ts = def.sheet_thickness, D = def.jet_diameter;
  const double r = 0.5 * D, clear = std::min(0.2, 0.5 * Z);
  const Eigen::Vector3d d = jet.axis, e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  const double back = 0.5 * Z;  // the tool starts in the middle of the gap
  const Eigen::Vector3d base = jet.exit - back * d;
  const RaySurfaceHit ao = entry.first(base, d, 4 * (back + ts) + 1), ai = exit.first(base, d, 4 * (back + ts) + 1);
  if (!ao.found || !ai.found || ai.ray_param <= ao.ray_param)
    throw FilmInputError(field + ".jets.diameter", std::string(jn) + ": does not cross the insert's sheet");
  const RaySurfaceHit far = exit.first(ai.point + 1e-6 * d, d, 4 * (back + ts) + 1);
  if (far.found && far.ray_param < 2 * clear)
    throw FilmInputError(field + ".jets.margin", std::string(jn) + ": the insert is only " + format_number(far.ray_param) +
                                                   " mm wide behind the jet; keep the jets further from its narrow end");
  const double so = entry.sense(d, ao), si = exit.sense(d, ai);
  double volume = 0, s_max = 0, s_min = HUGE_VAL;
  for (int k = 0; k <= 6; ++k)
    for (int a = 0; a < kAngles; ++a) {
      const double rho = k == 6 ? r : r * gx[k], th = 2 * kPi * a / kAngles;
      const Eigen::Vector3d o = base + rho * (std::cos(th) * e1 + std::sin(th) * e2);
      const RaySurfaceHit ho = entry.near(o, d, ao, so, 0, 4 * (back + ts) + 1, 4 * (back + ts) + 1);
      const RaySurfaceHit hi = exit.near(o, d, ai, si, 0, 4 * (back + ts) + 1, 4 * (back + ts) + 1);
      if (!ho.found || !hi.found || hi.ray_param <= ho.ray_param || ho.ray_param < 0.25 * Z)
        throw FilmInputError(field + ".jets.diameter", std::string(jn) + ": does not cross the insert's sheet cleanly");
      s_min = std::min(s_min, ho.ray_param);
      s_max = std::max(s_max, hi.ray_param);
      if (k < 6) volume += r * r * gx[k] * gw[k] * 2 * kPi / kAngles * (hi.ray_param - ho.ray_param);
    }
  HoleFrame hf;
  hf.exit = base;
  hf.axis = d;
  hf.forward = e2;
  HoleShape cyl;
  cyl.diameter = D;
  HoleToolExtent ext;
  ext.s_top = 0;
  ext.s_end = s_max + clear;
  FeatureTool t;
  t.feature = jn;
  t.shape = named_all_faces(make_hole_solid(hf, cyl, ext), jn);
  t.expected_volume = volume;
  t.symmetry_axis = gp_Ax1(occt::to_pnt(base), gp_Dir(d.x(), d.y(), d.z()));
  return t;
}

}  // namespace

InsertBuild build_insert(const blade::BladeModel& model, const InsertChamber& chamber, const InsertDefinition& def,
                         int index, const std::string& field, ProgressSink* progress, PerturbedRetries retries) {
  check_insert_input(chamber, def, index, field);
  const std::string name = "insert_" + std::to_string(index);
  const double tw = chamber.wall_thickness, Z = def.gap, ts = def.sheet_thickness, D = def.jet_diameter;
  InsertBuild out;
  auto t0 = std::chrono::steady_clock::now();
  const auto lap = [&](const char* stage) {
    const auto t = std::chrono::steady_clock::now();
    out.seconds.emplace_back(stage, std::chrono::duration<double>(t - t0).count());
    t0 = t;
  };
  const InsertSolids solids = insert_solids(model, chamber, def, name, field, out);
  const TopoDS_Shape& outer = solids.outer;
  const TopoDS_Shape& inner = solids.inner;
  lap("offsets");
  BooleanOptions bo;
  bo.progress = progress;
  bo.perturbed_retries = retries;
  BooleanStep shell(BooleanOperation::Cut, bo);
  FeatureTool core;
  core.feature = name;
  core.shape = named_all_faces(inner, name);
  if (!def.hub_open && !def.tip_open) core.expected_volume = brep::volume_of(inner);  // inside the outer solid
  shell.add(core);
  brep::NamedShape body = shell.apply(named_all_faces(outer, name));
  lap("shell");

  const Eigen::Vector3d inside = chamber.reference;
  const SheetPoints sp{blade::BladeCoordinates(model), tw + Z, end_wall_distance(solids.hub_o, inside),
                       end_wall_distance(solids.tip_o, inside)};
  const std::vector<Jet> jets = place_jets(sp, chamber, def, out, body.shape, name, field);

  // Jet tools: from the middle of the gap through the sheet, `clear` past its inner surface; expected
  // removal by ray quadrature between the two offset surfaces.
  NearCaster entry(out.outer_surface.surface), exit(out.inner_surface.surface);
  std::vector<double> gx, gw;
  gauss_legendre_01(6, gx, gw);
  const double r = 0.5 * D;
  BooleanStep holes(BooleanOperation::Cut, bo);
  double jet_area = 0;
  for (std::size_t j = 0; j < jets.size(); ++j) {
    char jn[64];
    std::snprintf(jn, sizeof jn, "%s_jet_%03d", name.c_str(), static_cast<int>(j) + 1);
    holes.add(jet_tool(jets[j], jn, entry, exit, gx, gw, def, field));
    jet_area += kPi * r * r;
  }
  lap("jet_tools");
  body = holes.apply(body);
  lap("jets");

  out.body = {name, body};
  out.check = holes.report().check;
  append_perturbed_tools(shell.report(), out.perturbed);
  append_perturbed_tools(holes.report(), out.perturbed);
  InsertMeasure& m = out.measure;
  m.name = name;
  m.chamber = chamber.name;
  m.gap = Z;
  m.sheet_thickness = ts;
  m.hub_open = def.hub_open;
  m.tip_open = def.tip_open;
  m.jet_holes = static_cast<int>(jets.size());
  m.jet_area = jet_area;
  m.volume = holes.report().check.volume;
  double removed = 0;
  for (const ToolReport& t : holes.report().tools) removed += t.expected_volume;
  m.expected_volume = brep::volume_of(outer) - shell.report().tools.front().expected_volume - removed;
  return out;
}

void measure_insert(const blade::BladeModel& model, const brep::NamedShape& blade, InsertBuild& insert,
                    const InsertChamber& chamber, const InsertDefinition& def, ProgressSink* progress) {
  InsertMeasure& m = insert.measure;
  const Handle(brep::OcctProgress) bridge = new brep::OcctProgress(progress, insert.body.name + " gap measurement");
  BRepExtrema_DistShapeShape dist(insert.body.geometry.shape, blade.shape, Extrema_ExtFlag_MIN, Extrema_ExtAlgo_Grad,
                                  bridge->Start());
  bridge->throw_if_stopped();
  if (!dist.IsDone()) throw FeatureFailure(insert.body.name + ": cannot measure the gap to the blade");
  m.measured_gap = dist.Value();
  // Along the wall normal at sample points between the jet lines: the gap to the blade and the sheet.
  const blade::BladeCoordinates coords(model);
  const double off = chamber.wall_thickness + def.gap;
  IntCurvesFace_ShapeIntersector on_blade, on_insert;
  on_blade.Load(blade.shape, 1e-9);
  on_insert.Load(insert.body.geometry.shape, 1e-9);
  m.measured_sheet_min = HUGE_VAL;
  m.measured_sheet_max = 0;
  double gap_normal_min = HUGE_VAL;
  const double c_lo = std::max(chamber.pressure_from, insert.inner_surface.max_pressure_chord);
  const double c_hi = std::min(chamber.suction_to, insert.inner_surface.min_suction_chord);
  for (int i = 1; i <= 7; ++i)
    for (double s : {0.45, 0.55}) {
      const double c = c_lo + (c_hi - c_lo) * (i - 0.5 + 0.37) / 8.0;  // off the jet lines' even spacing
      const blade::BladeFrame f = coords.frame(s, c);
      const Eigen::Vector3d p = f.point - off * f.normal, n = f.normal;
      const gp_Lin out_line(occt::to_pnt(p), gp_Dir(n.x(), n.y(), n.z()));
      on_blade.Perform(out_line, 0, 10 * def.gap + 1);
      double g = HUGE_VAL;
      for (int k = 1; k <= on_blade.NbPnt(); ++k) g = std::min(g, on_blade.WParameter(k));
      gap_normal_min = std::min(gap_normal_min, g);
      const Eigen::Vector3d q = p + 1e-3 * n;
      const gp_Lin in_line(occt::to_pnt(q), gp_Dir(-n.x(), -n.y(), -n.z()));
      on_insert.Perform(in_line, 0, 10 * def.sheet_thickness + 1);
      // The sheet is measured where the line enters and leaves it through its two sides (their normals
      // both within 25 deg of the line and parallel to each other: the line's length in the sheet times
      // their cosine); a line leaving through the insert's chordwise end (seen: the first sample of a
      // C3X variant, 1.625 mm along a 0.533 mm sheet) or through a jet hole measures nothing.
      std::vector<std::pair<double, double>> w;  // (parameter, |cos|) of every crossing
      for (int k = 1; k <= on_insert.NbPnt(); ++k) {
        gp_Pnt pt;
        gp_Vec du, dv;
        BRepAdaptor_Surface(on_insert.Face(k)).D1(on_insert.UParameter(k), on_insert.VParameter(k), pt, du, dv);
        const gp_Vec normal = du.Crossed(dv);
        if (normal.Magnitude() <= 0) continue;
        w.emplace_back(on_insert.WParameter(k), std::abs(normal.Normalized().Dot(gp_Vec(n.x(), n.y(), n.z()))));
      }
      std::sort(w.begin(), w.end());
      if (w.size() < 2 || std::min(w[0].second, w[1].second) < 0.9 || std::abs(w[0].second - w[1].second) > 0.01) continue;
      const double sheet = (w[1].first - w[0].first) * 0.5 * (w[0].second + w[1].second);
      m.measured_sheet_min = std::min(m.measured_sheet_min, sheet);
      m.measured_sheet_max = std::max(m.measured_sheet_max, sheet);
    }
  m.measured_gap = std::min(m.measured_gap, gap_normal_min);
}

}  // namespace cg::features
