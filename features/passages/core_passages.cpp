#include "features/passages/core_passages.hpp"

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Message_Alert.hxx>
#include <Message_Report.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>

#include "adaptors/occt_convert.hpp"
#include "src/brep/naming/face_names.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/core/newton.hpp"
#include "src/core/parallel.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/analyze/cell_quadrature.hpp"

namespace cg::features {
namespace {


using Vec3 = Eigen::Vector3d;


std::string rib_field(std::size_t i, const char* member) {
  return "core.ribs[" + std::to_string(i) + "]." + member;
}

class Stopwatch {
 public:
  double lap() {
    const auto t = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(t - t0_).count();
    t0_ = t;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};


// Point-in-solid tests against one solid (the classifier's face explorer is built once).
class Inside {
 public:
  explicit Inside(const TopoDS_Shape& solid) { c_.Load(solid); }
  bool operator()(const Vec3& p) {
    c_.Perform(occt::to_pnt(p), 1e-7);
    return c_.State() == TopAbs_IN;
  }

 private:
  BRepClass3d_SolidClassifier c_;
};

std::string alerts(const Message_Report& r, Message_Gravity g) {
  std::string s;
  for (const Handle(Message_Alert)& a : r.GetAlerts(g)) s += (s.empty() ? "" : ", ") + std::string(a->GetMessageKey());
  return s;
}

// Parameter t along x0 + t dir (|t| <= 50 mm) where the end wall's signed distance reaches `target`
// (the distance grows along dir, which points into the flow path; Illinois regula falsi to 1e-12 mm).
// Without a crossing in [-50, 50] the end on the side of the target.
double along_line(const EndWall& w, const Vec3& x0, const Vec3& dir, double target) {
  auto f = [&](double t) { return w.signed_distance(x0 + t * dir) - target; };
  const double lo = -50, hi = 50, f_lo = f(lo), f_hi = f(hi);
  if (f_lo >= 0) return lo;
  if (f_hi < 0) return hi;
  return newton::solve_bracketed_secant(f, lo, hi, f_lo, f_hi, 1e-12);
}

// ---------------------------------------------------------------------------------------------------
// Input checks that need no geometry

void check_definition(const CoreDefinition& def) {
  const std::size_t n = def.ribs.size();
  for (std::size_t i = 0; i < n; ++i) {
    const RibDefinition& r = def.ribs[i];
    if (i > 0 && !(r.suction_chord > def.ribs[i - 1].suction_chord)) {
      const ValueLimitText t = format_value_limit(r.suction_chord, def.ribs[i - 1].suction_chord, Allowed::above);
      throw PassageInputError(rib_field(i, "suction_chord"), "ribs must be listed from the LE to the TE: must be > " + t.limit +
                                                                 " (ribs[" + std::to_string(i - 1) + "]), got " + t.value);
    }
    if (i > 0 && !(r.pressure_chord < def.ribs[i - 1].pressure_chord)) {
      const ValueLimitText t = format_value_limit(r.pressure_chord, def.ribs[i - 1].pressure_chord, Allowed::below);
      throw PassageInputError(rib_field(i, "pressure_chord"), "ribs must be listed from the LE to the TE: must be < " + t.limit +
                                                                  " (ribs[" + std::to_string(i - 1) +
                                                                  "], pressure-side chords are negative), got " + t.value);
    }
    if (r.turnaround) {
      const TurnaroundDefinition& t = *r.turnaround;
      const bool open = t.end == SpanEnd::Tip ? def.tip_cap.open : def.hub_floor.open;
      if (open)
        throw PassageInputError(rib_field(i, "turnaround.end"),
                                std::string("a turnaround needs an end wall, but the ") +
                                    (t.end == SpanEnd::Tip ? "tip (core.tip_cap.open)" : "hub (core.hub_floor.open)") +
                                    " is open");
      if (t.tip_radius > 0.5 * r.thickness * (1 + 1e-12)) {
        const ValueLimitText v = format_value_limit(t.tip_radius, 0.5 * r.thickness, Allowed::below);
        throw PassageInputError(rib_field(i, "turnaround.tip_radius"), "must be in (0, thickness / 2 = " + v.limit + "] mm, got " + v.value);
      }
    }
  }
  const int chambers = static_cast<int>(n) + 1;
  for (std::size_t m = 0; m < def.inlets.size(); ++m) {
    const InletDefinition& in = def.inlets[m];
    const std::string f = "core.inlets[" + std::to_string(m) + "]";
    if (in.chamber < 1 || in.chamber > chambers)
      throw PassageInputError(f + ".chamber", "must be in [1, " + std::to_string(chambers) + "] (" +
                                                  std::to_string(chambers) + " chambers), got " +
                                                  std::to_string(in.chamber));
    const bool open = in.end == SpanEnd::Tip ? def.tip_cap.open : def.hub_floor.open;
    if (open)
      throw PassageInputError(f + ".end", "the inlet's end is open already (no end wall to pass through)");
  }
  // Every chamber must receive coolant: from an open end, or an inlet reached through turnarounds.
  std::vector<int> comp(static_cast<std::size_t>(chambers));
  for (int k = 0; k < chambers; ++k) comp[static_cast<std::size_t>(k)] = k;
  for (std::size_t i = 0; i < n; ++i)
    if (def.ribs[i].turnaround) comp[i + 1] = comp[i];
  std::set<int> fed;
  if (def.hub_floor.open || def.tip_cap.open)
    for (int c : comp) fed.insert(c);
  for (const auto& in : def.inlets) fed.insert(comp[static_cast<std::size_t>(in.chamber - 1)]);
  std::string unfed;
  for (int k = 0; k < chambers; ++k)
    if (!fed.count(comp[static_cast<std::size_t>(k)])) unfed += (unfed.empty() ? "" : ", ") + std::to_string(k + 1);
  if (!unfed.empty())
    throw PassageInputError("core.inlets", "chamber(s) " + unfed +
                                               " receive no coolant: add an inlet into them, a turnaround to a fed "
                                               "chamber, or open an end");
}

// ---------------------------------------------------------------------------------------------------

double side_length(const blade::BladeCoordinates& coords, double span, bool suction) {
  double len = 0;
  Vec3 prev = coords.frame(span, 0.0).point;
  for (int k = 1; k <= 200; ++k) {
    const Vec3 p = coords.frame(span, (suction ? 1.0 : -1.0) * k / 200.0).point;
    len += (p - prev).norm();
    prev = p;
  }
  return len;
}

// Ribs inside the core and apart from each other, on a few spans.
// A fillet of radius r where a rib side meets a wall at angle a runs r cot(a / 2) along that side (r at
// a right angle, 11 r at 5 deg); both ends' fillets on one side must fit in the rib's length between
// the walls (the rib from wall point to wall point at its chords, the walls' chordwise tangents there).
void check_rib_fillet_run(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall, const RibDefinition& r,
                          std::size_t i, double s) {
  auto at = [&](double c) { return blade::inner_wall_point(coords, wall, s, c); };
  auto tangent = [&](double c) {
    const double h = 1e-5;
    return Vec3((at(c + h) - at(c - h)).normalized());
  };
  const Vec3 a = at(r.suction_chord), b = at(r.pressure_chord);
  const double length = (b - a).norm();
  const Vec3 d = (b - a) / length, ta = tangent(r.suction_chord), tb0 = tangent(r.pressure_chord);
  const Vec3 e = (ta - ta.dot(d) * d).normalized();  // the side of the rib the suction wall's tangent leans to
  const Vec3 tb = tb0.dot(e) >= 0 ? tb0 : Vec3(-tb0);
  auto angle = [](const Vec3& u, const Vec3& v) { return std::acos(std::clamp(u.dot(v), -1.0, 1.0)); };
  const double as = angle(d, ta), ap = angle(-d, tb);  // on side +e; 180 deg minus these on side -e
  const double run = std::max(1 / std::tan(0.5 * as) + 1 / std::tan(0.5 * ap), std::tan(0.5 * as) + std::tan(0.5 * ap));
  if (std::isfinite(run) && r.fillet_radius * run < length) return;
  const ValueLimitText t = format_value_limit(r.fillet_radius, std::isfinite(run) ? length / run : 0.0, Allowed::below);
  throw PassageInputError(rib_field(i, "fillet_radius"),
                          "rib " + std::to_string(i + 1) + " meets the walls at " + format_number(std::min(as, kPi - as) * 180 / kPi) +
                              " and " + format_number(std::min(ap, kPi - ap) * 180 / kPi) + " deg at span " + format_number(s) +
                              ": fillets of radius " + t.value + " mm at both ends would run " +
                              format_number(r.fillet_radius * run) + " mm along a side " + format_number(length) +
                              " mm long; must be < " + t.limit + " mm here (or move the rib to meet the walls more squarely)");
}

void check_rib_placement(const blade::BladeCoordinates& coords, const CoreDefinition& def) {
  const double spans[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  for (double s : spans) {
    const blade::InnerWallSection cr = blade::inner_wall_crease(coords, def.wall_thickness, s);
    const double ls = side_length(coords, s, true), lp = side_length(coords, s, false);
    for (std::size_t i = 0; i < def.ribs.size(); ++i) {
      const RibDefinition& r = def.ribs[i];
      const double reach = 0.5 * r.thickness + r.fillet_radius + 0.1;  // mm the rib needs beyond its chord
      if (r.suction_chord + reach / ls >= cr.suction_chord)
        throw PassageInputError(rib_field(i, "suction_chord"),
                                "rib " + std::to_string(i + 1) + " lies outside the core at span " + format_number(s) +
                                    ": with its thickness and fillets it reaches chord " + format_number(r.suction_chord + reach / ls) +
                                    ", the inner wall ends at suction chord " + format_number(cr.suction_chord) + " there");
      if (r.pressure_chord - reach / lp <= cr.pressure_chord)
        throw PassageInputError(rib_field(i, "pressure_chord"),
                                "rib " + std::to_string(i + 1) + " lies outside the core at span " + format_number(s) +
                                    ": with its thickness and fillets it reaches chord " + format_number(r.pressure_chord - reach / lp) +
                                    ", the inner wall ends at pressure chord " + format_number(cr.pressure_chord) + " there");
      if (r.suction_chord - reach / ls <= 0 || r.pressure_chord + reach / lp >= 0)
        throw PassageInputError(rib_field(i, r.suction_chord - reach / ls <= 0 ? "suction_chord" : "pressure_chord"),
                                "rib " + std::to_string(i + 1) + " with its thickness and fillets reaches over the "
                                "leading edge at span " + format_number(s));
      if (r.fillet_radius > 0) check_rib_fillet_run(coords, def.wall_thickness, r, i, s);
      if (i == 0) continue;
      const RibDefinition& q = def.ribs[i - 1];
      const double need = std::max(r.thickness, q.thickness);
      const double clear_s = (blade::inner_wall_point(coords, def.wall_thickness, s, r.suction_chord) -
                              blade::inner_wall_point(coords, def.wall_thickness, s, q.suction_chord)).norm() -
                             0.5 * (r.thickness + q.thickness);
      const double clear_p = (blade::inner_wall_point(coords, def.wall_thickness, s, r.pressure_chord) -
                              blade::inner_wall_point(coords, def.wall_thickness, s, q.pressure_chord)).norm() -
                             0.5 * (r.thickness + q.thickness);
      const bool ss = clear_s < need;
      if (ss || clear_p < need) {
        const double clear = ss ? clear_s : clear_p;
        const ValueLimitText t = format_value_limit(clear, need, Allowed::above);
        throw PassageInputError(rib_field(i, ss ? "suction_chord" : "pressure_chord"),
                                "ribs " + std::to_string(i) + " and " + std::to_string(i + 1) + " overlap or are closer "
                                "than their thickness on the " + (ss ? "suction" : "pressure") + " side at span " + format_number(s) +
                                    (clear < 0 ? ": they overlap by " + format_number(-clear) + " mm" : ": clear width " + t.value + " mm") +
                                    ", at least " + t.limit + " mm needed");
      }
      // The fillets of both ribs on one wall take about their radii of the clear width (at least half).
      const double fillets = 0.5 * (r.fillet_radius + q.fillet_radius), clear = std::min(clear_s, clear_p);
      if (fillets > 0 && clear < fillets) {
        const std::size_t k = r.fillet_radius >= q.fillet_radius ? i : i - 1;
        throw PassageInputError(rib_field(k, "fillet_radius"),
                                "the fillets of ribs " + std::to_string(i) + " and " + std::to_string(i + 1) + " (radii " +
                                    format_number(q.fillet_radius) + " and " + format_number(r.fillet_radius) + " mm) do not fit in the " +
                                    format_number(clear) + " mm of wall between them at span " + format_number(s));
      }
    }
  }
}

std::vector<ChamberInfo> chambers_of(const blade::BladeCoordinates& coords, const CoreDefinition& def) {
  const blade::InnerWallSection mid = blade::inner_wall_crease(coords, def.wall_thickness, 0.5);
  const std::size_t n = def.ribs.size();
  std::vector<ChamberInfo> out(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    ChamberInfo& c = out[k];
    c.number = static_cast<int>(k) + 1;
    c.suction_from = k == 0 ? 0.0 : def.ribs[k - 1].suction_chord;
    c.pressure_from = k == 0 ? 0.0 : def.ribs[k - 1].pressure_chord;
    c.suction_to = k == n ? mid.suction_chord : def.ribs[k].suction_chord;
    c.pressure_to = k == n ? mid.pressure_chord : def.ribs[k].pressure_chord;
    c.reference = chamber_point(coords, def.wall_thickness, c, 0.5);
  }
  return out;
}

// Rib index (0-based) of a face name "rib_<i>" / "turnaround_<j>", -1 for other names.
int rib_of(const std::string& name, const std::vector<RibTube>& ribs) {
  auto number_after = [&](const std::string& prefix) {
    if (name.rfind(prefix, 0) != 0) return -1;
    std::size_t end = prefix.size();
    while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
    if (end == prefix.size() || end != name.size()) return -1;  // exact "<prefix><number>"
    return std::stoi(name.substr(prefix.size()));
  };
  if (const int i = number_after("rib_"); i > 0) return i - 1;
  if (const int j = number_after("turnaround_"); j > 0)
    for (std::size_t r = 0; r < ribs.size(); ++r)
      if (ribs[r].turnaround == j) return static_cast<int>(r);
  return -1;
}

}  // namespace

namespace {

// The least width of a chamber's cross-section at `span` (its inner-wall points between the centre lines
// of its ribs, in their best-fit plane) over 180 directions: sampled directions overestimate the least
// width, and a circle inside the chamber is no wider than that, so an inlet wider than this cannot fit.
double chamber_width(const blade::BladeCoordinates& coords, const CoreDefinition& def, const ChamberInfo& c, double span) {
  std::vector<Vec3> pts;
  constexpr int kSamples = 16;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    pts.push_back(blade::inner_wall_point(coords, def.wall_thickness, span, c.suction_from + t * (c.suction_to - c.suction_from)));
    pts.push_back(blade::inner_wall_point(coords, def.wall_thickness, span, c.pressure_from + t * (c.pressure_to - c.pressure_from)));
  }
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : pts) mean += p / static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : pts) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // ascending: column 0 is the normal
  const Vec3 e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  double least = HUGE_VAL;
  for (int a = 0; a < 180; ++a) {
    const double phi = a * kPi / 180;
    const Vec3 dir = std::cos(phi) * e1 + std::sin(phi) * e2;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Vec3& p : pts) lo = std::min(lo, dir.dot(p - mean)), hi = std::max(hi, dir.dot(p - mean));
    least = std::min(least, hi - lo);
  }
  return least;
}

// An inlet wider than its chamber at its end wall (the exact rim test, check_inlet_rims, needs the
// built core: this refuses the gross cases before it).
void check_inlet_sizes(const blade::BladeCoordinates& coords, const CoreDefinition& def) {
  const std::vector<ChamberInfo> chambers = chambers_of(coords, def);
  for (std::size_t m = 0; m < def.inlets.size(); ++m) {
    const InletDefinition& in = def.inlets[m];
    const ChamberInfo& c = chambers[static_cast<std::size_t>(in.chamber - 1)];
    const double span = in.end == SpanEnd::Hub ? 0.0 : 1.0;
    const double width = std::max(chamber_width(coords, def, c, span), chamber_width(coords, def, c, in.end == SpanEnd::Hub ? 0.1 : 0.9));
    if (in.diameter > width) {
      const ValueLimitText t = format_value_limit(in.diameter, width, Allowed::below);
      throw PassageInputError("core.inlets[" + std::to_string(m) + "].diameter",
                              "inlet_" + std::to_string(m + 1) + " of " + t.value + " mm is wider than chamber_" +
                                  std::to_string(in.chamber) + " at its " + (in.end == SpanEnd::Hub ? "hub" : "tip") +
                                  " end (at most " + t.limit + " mm across between its ribs' centre lines): must be < " + t.limit + " mm");
    }
  }
}

}  // namespace

namespace {

// Where the core's ribs end: through ends beyond the inner wall's span range, turnarounds against the
// closed end walls `hub` / `tip` (null when open).
RibEnds rib_ends(const CoreBuild& core, const EndWall* hub, const EndWall* tip) {
  RibEnds ends;
  ends.hub_through_span = core.inner_wall.surface.first_v();
  ends.tip_through_span = core.inner_wall.surface.last_v();
  ends.hub_wall = hub;
  ends.tip_wall = tip;
  return ends;
}

PassageInputError rib_error(const CoreDefinition& def, std::size_t i, const InvalidGeometry& e) {
  return PassageInputError("core.ribs[" + std::to_string(i) + "]" + (def.ribs[i].turnaround ? ".turnaround" : ""), e.what());
}

blade::InnerWallOptions inner_wall_options(const CoreDefinition& def) {
  blade::InnerWallOptions o;
  o.tolerance = def.tolerance;
  return o;
}

// The turnaround ends placed by their gaps as the rib tubes will place them (check_rib_ends, between the
// inner wall's span range and the closed end walls): a gap the span cannot take is refused before any
// fit or solid.
void check_turnarounds(const blade::BladeModel& model, const blade::BladeCoordinates& coords, const CoreDefinition& def) {
  if (std::none_of(def.ribs.begin(), def.ribs.end(), [](const RibDefinition& r) { return r.turnaround.has_value(); })) return;
  std::optional<EndWall> hub, tip;
  if (!def.hub_floor.open) hub.emplace(model, SpanEnd::Hub, def.hub_floor.thickness);
  if (!def.tip_cap.open) tip.emplace(model, SpanEnd::Tip, def.tip_cap.thickness);
  RibEnds ends;
  std::tie(ends.hub_through_span, ends.tip_through_span) = blade::inner_wall_span_range(model, inner_wall_options(def));
  ends.hub_wall = hub ? &*hub : nullptr;
  ends.tip_wall = tip ? &*tip : nullptr;
  for (std::size_t i = 0; i < def.ribs.size(); ++i) {
    if (!def.ribs[i].turnaround) continue;
    try {
      check_rib_ends(coords, def.wall_thickness, def.ribs[i], static_cast<int>(i) + 1, ends);
    } catch (const InvalidGeometry& e) {
      throw rib_error(def, i, e);
    }
  }
}

// Cutting ends just outside the blade lie this far out (mm): the open ends' cutting surfaces at -delta,
// the inlets' outer ends at -delta / 2.
double end_margin(const blade::BladeModel& model) { return 0.4 * model.options.overbuild * model.span_length; }

// The end wall inlet `in` passes through (its end is closed: check_definition).
const EndWall& end_wall_of(const InletDefinition& in, const CoreBuild& core) {
  return in.end == SpanEnd::Hub ? *core.hub_floor : *core.tip_cap;
}

// Inlet m (InletPlacement): along the line from its chamber's point on the flow path's end to the
// chamber's point at 0.1 of the span from it, from just outside the blade to `reach` past the end wall,
// its rim (12 points on its circle) half way between the end wall and that end.
InletPlacement place_inlet(std::size_t m, const blade::BladeModel& model, const blade::BladeCoordinates& coords,
                           const CoreDefinition& def, const CoreBuild& out) {
  const InletDefinition& in = def.inlets[m];
  InletPlacement p;
  p.name = "inlet_" + std::to_string(m + 1);
  ChamberInfo at = out.chambers[static_cast<std::size_t>(in.chamber - 1)];
  if (!std::isnan(in.suction_chord)) at.suction_from = at.suction_to = in.suction_chord;
  if (!std::isnan(in.pressure_chord)) at.pressure_from = at.pressure_to = in.pressure_chord;
  const bool hub = in.end == SpanEnd::Hub;
  p.origin = chamber_point(coords, def.wall_thickness, at, hub ? 0.0 : 1.0);
  p.axis = (chamber_point(coords, def.wall_thickness, at, hub ? 0.1 : 0.9) - p.origin).normalized();
  const EndWall& wall = end_wall_of(in, out);
  const EndWall outside(model, in.end, -0.5 * end_margin(model));
  const double reach = std::max(0.5, 0.25 * in.diameter);
  p.from = along_line(outside, p.origin, p.axis, 0.0);
  p.to = along_line(wall, p.origin, p.axis, reach);
  p.radius = 0.5 * in.diameter;
  InletRim& rim = p.rim;
  rim.field = "core.inlets[" + std::to_string(m) + "].diameter";
  rim.message = p.name + " (diameter " + format_number(in.diameter) + " mm) does not fit into chamber " +
                std::to_string(in.chamber) + " where it passes the " + (hub ? "hub floor" : "tip cap") +
                ": its rim leaves the chamber; use a smaller diameter or move it";
  rim.centre = p.origin + along_line(wall, p.origin, p.axis, 0.5 * reach) * p.axis;
  const Vec3 e1 = p.axis.unitOrthogonal(), e2 = p.axis.cross(e1);
  for (int k = 0; k < 12; ++k) {
    const double a = 2 * kPi * k / 12;
    rim.points.push_back(rim.centre + p.radius * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  return p;
}

// The walls' part of the rim test (check_inlet_rims classifies against the chamber solid, which the
// ribs and fillets bound too): every rim point on the chamber's side of its end wall and inside the
// inner wall, i.e. an even number of inner-wall crossings from the rim's centre on the axis (inside
// the core: the chamber point's line) to it.
void check_inlet_rims_in_walls(const CoreDefinition& def, const CoreBuild& out) {
  if (out.inlets.empty()) return;
  RaySurfaceCaster inner(out.inner_wall.surface);
  for (std::size_t m = 0; m < out.inlets.size(); ++m) {
    const InletRim& rim = out.inlets[m].rim;
    const EndWall& wall = end_wall_of(def.inlets[m], out);
    for (const Vec3& q : rim.points)
      if (segment_crossings(inner, rim.centre, q).size() % 2 == 1 || !(wall.signed_distance(q) > 0))
        throw PassageInputError(rim.field, rim.message);
  }
}

}  // namespace

void check_core_definition(const blade::BladeModel& model, const CoreDefinition& def) {
  check_definition(def);
  const blade::BladeCoordinates coords(model);
  try {
    check_rib_placement(coords, def);  // computes the crossing on five spans
    check_turnarounds(model, coords, def);
    check_inlet_sizes(coords, def);
  } catch (const blade::InnerWallError& e) {
    throw PassageInputError("core.wall_thickness", e.what());
  }
}

Vec3 chamber_point(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall, const ChamberInfo& c,
                   double span) {
  const Vec3 s = blade::inner_wall_point(coords, wall, span, 0.5 * (c.suction_from + c.suction_to));
  const Vec3 p = blade::inner_wall_point(coords, wall, span, 0.5 * (c.pressure_from + c.pressure_to));
  return 0.5 * (s + p);
}

CoreBuild build_core_walls(const blade::BladeModel& model, const CoreDefinition& def) {
  Stopwatch sw;
  CoreBuild out;
  const blade::BladeCoordinates coords(model);

  // 1. Inner wall and core solid (the definition checked by check_core_definition).
  try {
    out.inner_wall = blade::build_inner_wall(model, def.wall_thickness, inner_wall_options(def));
  } catch (const blade::InnerWallError& e) {
    throw PassageInputError("core.wall_thickness", e.what());
  }
  if (!def.hub_floor.open) out.hub_floor.emplace(model, SpanEnd::Hub, def.hub_floor.thickness);
  if (!def.tip_cap.open) out.tip_cap.emplace(model, SpanEnd::Tip, def.tip_cap.thickness);
  out.chambers = chambers_of(coords, def);
  for (std::size_t m = 0; m < def.inlets.size(); ++m) out.inlets.push_back(place_inlet(m, model, coords, def, out));
  check_inlet_rims_in_walls(def, out);
  out.seconds.emplace_back("inner_wall", sw.lap());
  return out;
}

namespace {

// The core solid: the inner wall trimmed by the end walls (or, at an open end, by a cutting end just
// outside the blade), its faces named.
brep::BladeSolid build_core_solid(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& out,
                                  double delta, FaceNames& names) {
  const EndWall bottom = def.hub_floor.open ? EndWall(model, SpanEnd::Hub, -delta) : *out.hub_floor;
  const EndWall top = def.tip_cap.open ? EndWall(model, SpanEnd::Tip, -delta) : *out.tip_cap;
  brep::BladeSolid core = brep::build_blade_solid(out.inner_wall.surface, bottom.trim(), top.trim());
  if (!core.warnings.empty()) throw FeatureFailure("core solid: BOPAlgo warnings while trimming the inner wall");
  for (const auto& f : core.faces) {
    const std::string n = f.name == brep::kWallFaceName ? "chamber_wall"
                          : f.name == brep::kHubFaceName ? (def.hub_floor.open ? "open_hub" : "hub_floor")
                                                         : (def.tip_cap.open ? "open_tip" : "tip_cap");
    names.set(f.face, n);
  }
  return core;
}

// 2. Ribs and chambers.
// The ribs are independent: built in parallel, each worker with its own coordinates and end walls
// (both cache evaluation state); the error of the first failing rib is reported.
void build_rib_tubes(const blade::BladeModel& model, const CoreDefinition& def, CoreBuild& out, FaceNames& names) {
  std::vector<int> turnaround_of(def.ribs.size(), 0);
  for (std::size_t i = 0, j = 0; i < def.ribs.size(); ++i)
    if (def.ribs[i].turnaround) turnaround_of[i] = static_cast<int>(++j);
  struct RibWorker {
    std::unique_ptr<blade::BladeCoordinates> coords;
    std::optional<EndWall> hub, tip;
    RibEnds ends;
  };
  const int rib_workers = std::min(parallel_workers(), std::max(1, static_cast<int>(def.ribs.size())));
  std::vector<RibWorker> rib_worker(static_cast<std::size_t>(rib_workers));
  for (RibWorker& w : rib_worker) {
    w.coords = std::make_unique<blade::BladeCoordinates>(model);
    if (out.hub_floor) w.hub.emplace(*out.hub_floor);
    if (out.tip_cap) w.tip.emplace(*out.tip_cap);
    w.ends = rib_ends(out, w.hub ? &*w.hub : nullptr, w.tip ? &*w.tip : nullptr);
  }
  std::vector<std::optional<RibTube>> tubes(def.ribs.size());
  parallel_for(static_cast<int>(def.ribs.size()), rib_workers, [&](int k, int wk) {
    const std::size_t i = static_cast<std::size_t>(k);
    const RibWorker& w = rib_worker[static_cast<std::size_t>(wk)];
    try {
      tubes[i] = build_rib_tube(*w.coords, def.wall_thickness, def.ribs[i], k + 1, turnaround_of[i], w.ends,
                                def.tolerance);
    } catch (const InvalidGeometry& e) {
      throw rib_error(def, i, e);
    }
  });
  for (auto& t : tubes) {
    out.ribs.push_back(std::move(*t));
    names.add(out.ribs.back().faces);
  }
}

// The core split by the rib tubes into cells (the core itself without ribs).
std::vector<TopoDS_Shape> split_core_by_ribs(const TopoDS_Shape& core, const std::vector<RibTube>& ribs, FaceNames& names) {
  if (ribs.empty()) return {core};
  BRepAlgoAPI_Splitter split;
  TopTools_ListOfShape args, tools;
  args.Append(core);
  for (const auto& r : ribs) tools.Append(r.shell);
  split.SetArguments(args);
  split.SetTools(tools);
  split.SetRunParallel(true);
  split.Build();
  // Seen when a rib meets the inner wall where the core is thinner than the rib with its fillets, or
  // at a very acute angle (e.g. a rib near the trailing-edge crease): name the input that moves it.
  const std::string hint =
      " (cooling.core.ribs: a rib probably meets the inner wall where the core is thinner than the rib "
      "with its fillets, or at a very acute angle; move it away from the trailing edge or make it thinner)";
  if (!split.IsDone() || split.HasErrors())
    throw FeatureFailure("splitting the core by the ribs failed: " + alerts(*split.GetReport(), Message_Fail) + hint);
  if (split.HasWarnings())
    throw FeatureFailure("splitting the core by the ribs raised BOPAlgo warnings: " +
                         alerts(*split.GetReport(), Message_Warning) + hint);
  names = names.carried(split, split.Shape());
  return solids_of(split.Shape());
}

// Coolant cells: those holding chamber reference points (the cells are disjoint: the first cell that
// holds a point is its only one; a cell's bounding box rules most cells out without classifying).
std::vector<int> chamber_cells(const std::vector<TopoDS_Shape>& cells, const std::vector<ChamberInfo>& chambers) {
  std::vector<int> cell_of(chambers.size(), -1);
  std::vector<std::unique_ptr<Inside>> in_cell(cells.size());
  std::vector<Bnd_Box> cell_box(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) BRepBndLib::Add(cells[c], cell_box[c]);
  for (std::size_t k = 0; k < chambers.size(); ++k) {
    for (std::size_t c = 0; c < cells.size() && cell_of[k] < 0; ++c) {
      if (cell_box[c].IsOut(occt::to_pnt(chambers[k].reference))) continue;
      if (!in_cell[c]) in_cell[c] = std::make_unique<Inside>(cells[c]);
      if ((*in_cell[c])(chambers[k].reference)) cell_of[k] = static_cast<int>(c);
    }
    if (cell_of[k] < 0)
      throw FeatureFailure("chamber " + std::to_string(k + 1) + ": its reference point lies in no cell of the core");
  }
  return cell_of;
}

// The other cells are the ribs': their volumes per rib (found by the names of their faces).
void measure_rib_cells(const std::vector<TopoDS_Shape>& cells, const std::vector<double>& cell_volume,
                       const std::vector<int>& cell_of, const FaceNames& names, const CoreDefinition& def,
                       CoreBuild& out) {
  out.rib_volumes.assign(def.ribs.size(), 0.0);
  out.fillet_volumes.assign(def.ribs.size(), 0.0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (std::find(cell_of.begin(), cell_of.end(), static_cast<int>(c)) != cell_of.end()) continue;
    int rib = -1;
    for (const TopoDS_Shape& f : faces_of(cells[c]))
      if (const int r = rib_of(names.get(f), out.ribs); r >= 0) rib = r;
    if (rib < 0) throw FeatureFailure("a cell of the core belongs to no chamber and no rib");
    out.rib_volumes[static_cast<std::size_t>(rib)] += cell_volume[c];
  }
}

// 3. Fillets on every edge between a rib face and the inner wall of a coolant cell (`cell` becomes the
// filleted cell); the filleted edges with their ribs (0-based).
std::vector<std::pair<TopoDS_Edge, int>> fillet_rib_edges(TopoDS_Shape& cell, const CoreDefinition& def,
                                                          const std::vector<RibTube>& ribs, FaceNames& names) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(cell, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  BRepFilletAPI_MakeFillet fillet(cell);
  std::vector<std::pair<TopoDS_Edge, int>> filleted;
  for (int e = 1; e <= edge_faces.Extent(); ++e) {
    int rib = -1;
    bool wall = false;
    for (const TopoDS_Shape& f : edge_faces(e)) {
      const std::string n = names.get(f);
      wall |= n == "chamber_wall";
      if (const int r = rib_of(n, ribs); r >= 0) rib = r;
    }
    if (!wall || rib < 0 || def.ribs[static_cast<std::size_t>(rib)].fillet_radius <= 0) continue;
    const TopoDS_Edge edge = TopoDS::Edge(edge_faces.FindKey(e));
    if (fillet.Contour(edge) == 0) fillet.Add(def.ribs[static_cast<std::size_t>(rib)].fillet_radius, edge);
    filleted.emplace_back(edge, rib);
  }
  if (filleted.empty()) return filleted;
  fillet.Build();
  if (!fillet.IsDone()) {
    std::set<int> failed;
    for (const auto& [e, r] : filleted) failed.insert(r + 1);
    std::string list;
    for (int r : failed) list += (list.empty() ? "" : ", ") + std::to_string(r);
    // OCCT cannot make these fillets: the user's remedy is the radius (a refusal naming it).
    throw PassageInputError(rib_field(static_cast<std::size_t>(*failed.begin() - 1), "fillet_radius"),
                            "fillets of rib(s) " + list + " failed (BRepFilletAPI_MakeFillet, " +
                                std::to_string(fillet.NbFaultyContours()) + " faulty contours); try another fillet radius");
  }
  const TopoDS_Shape result = fillet.Shape();
  FaceNames next = names.carried(fillet, result);
  for (const auto& [edge, rib] : filleted) {
    std::string base;
    for (const TopoDS_Shape& f : edge_faces.FindFromKey(edge))
      if (rib_of(names.get(f), ribs) >= 0) base = names.get(f);
    for (const TopoDS_Shape& g : fillet.Generated(edge))
      if (g.ShapeType() == TopAbs_FACE) next.set(g, base + "_fillet");
  }
  names.merge(next);
  cell = result;
  return filleted;
}

// 4. Naming split by the turnaround sheets of this system's ribs: the cell's pieces, one per chamber.
std::vector<TopoDS_Shape> split_at_turnarounds(const TopoDS_Shape& cell, const std::vector<int>& members,
                                               const std::vector<RibTube>& ribs, FaceNames& names) {
  TopTools_ListOfShape sheets;
  for (std::size_t r = 0; r < ribs.size(); ++r) {
    const bool joins = std::find(members.begin(), members.end(), static_cast<int>(r)) != members.end() &&
                       std::find(members.begin(), members.end(), static_cast<int>(r) + 1) != members.end();
    if (joins && !ribs[r].turnaround_sheet.IsNull()) sheets.Append(ribs[r].turnaround_sheet);
  }
  if (sheets.IsEmpty()) return {cell};
  BRepAlgoAPI_Splitter split;
  TopTools_ListOfShape args;
  args.Append(cell);
  split.SetArguments(args);
  split.SetTools(sheets);
  split.Build();
  if (!split.IsDone() || split.HasErrors() || split.HasWarnings())
    throw FeatureFailure("splitting the turnaround faces for naming failed: " +
                         alerts(*split.GetReport(), Message_Fail) + " " + alerts(*split.GetReport(), Message_Warning));
  names.merge(names.carried(split, split.Shape()));
  return solids_of(split.Shape());
}

// Each piece to the chamber whose reference point it holds: the chambers' and the system's volumes, and
// the chamber wall named per chamber.
void assign_pieces(const std::vector<TopoDS_Shape>& pieces, const std::vector<int>& members, ChamberSystem& sys,
                   FaceNames& names, CoreBuild& out) {
  const std::vector<double> piece_volume = volumes_of(pieces);
  for (std::size_t pc = 0; pc < pieces.size(); ++pc) {
    const TopoDS_Shape& piece = pieces[pc];
    int owner = -1;
    Bnd_Box box;
    BRepBndLib::Add(piece, box);
    std::optional<Inside> in_piece;
    for (int k : members) {
      const Vec3& ref = out.chambers[static_cast<std::size_t>(k)].reference;
      if (box.IsOut(occt::to_pnt(ref))) continue;
      if (!in_piece) in_piece.emplace(piece);
      if ((*in_piece)(ref)) owner = k;
    }
    if (owner < 0) throw FeatureFailure("a piece of a chamber system holds no chamber reference point");
    const double v = piece_volume[pc];
    out.chambers[static_cast<std::size_t>(owner)].volume += v;
    sys.volume += v;  // the pieces' shared faces cancel: the merged solid's volume is their sum
    for (const TopoDS_Shape& f : faces_of(piece))
      if (names.get(f) == "chamber_wall") names.set(f, "chamber_" + std::to_string(owner + 1) + "_wall");
  }
}

// 3. + 4. One coolant cell (holding the chambers `members`, 0-based): fillets, naming split, merge; its
// chamber system and its tool.
void build_chamber_system(TopoDS_Shape cell, double v_before, const std::vector<int>& members,
                          const CoreDefinition& def, FaceNames& names, CoreBuild& out) {
  const std::vector<std::pair<TopoDS_Edge, int>> filleted = fillet_rib_edges(cell, def, out.ribs, names);
  const std::vector<TopoDS_Shape> pieces = split_at_turnarounds(cell, members, out.ribs, names);
  ChamberSystem sys;
  assign_pieces(pieces, members, sys, names, out);
  const TopoDS_Shape merged = merge_cells(pieces);
  for (int k : members) {
    sys.chambers.push_back(k + 1);
    out.chambers[static_cast<std::size_t>(k)].system = static_cast<int>(out.systems.size());
  }
  sys.feature = members.size() == 1 ? "chamber_" + std::to_string(members.front() + 1)
                                    : "chambers_" + std::to_string(members.front() + 1) + "_" +
                                          std::to_string(members.back() + 1);
  // Fillet material per rib, shared in proportion to the rib's edge count (one system rarely has ribs
  // of different radii; the per-system total is exact).
  if (!filleted.empty()) {
    std::map<int, int> per_rib;
    for (const auto& [e, r] : filleted) ++per_rib[r];
    for (const auto& [r, count] : per_rib)
      out.fillet_volumes[static_cast<std::size_t>(r)] += (v_before - sys.volume) * count / filleted.size();
  }
  FeatureTool tool;
  tool.feature = sys.feature;
  tool.shape.shape = merged;
  tool.shape.faces = names.list(merged, sys.feature);
  // Closed ends: the tool lies inside the blade (inside the inner wall, between the end walls), so it
  // removes its own volume. Open ends: the verified path computes the overlap.
  sys.shape = merged;
  if (def.hub_floor.open || def.tip_cap.open) {
    tool.expected_volume = std::numeric_limits<double>::quiet_NaN();
    out.cut_tools.push_back(tool);
  } else {
    tool.expected_volume = sys.volume;
    out.interior_tools.push_back(tool);
  }
  out.systems.push_back(sys);
}

// Which chambers receive coolant (for the report; the definition check already refused unfed ones).
void mark_fed_chambers(const CoreDefinition& def, CoreBuild& out) {
  for (auto& c : out.chambers) c.fed = def.hub_floor.open || def.tip_cap.open;
  for (const auto& in : def.inlets) {
    const int sys = out.chambers[static_cast<std::size_t>(in.chamber - 1)].system;
    for (auto& c : out.chambers)
      if (c.system == sys) c.fed = true;
  }
}

// Inlet m from its placement (build_core_walls): its cylinder, its rim's chamber system, and its tool
// with the volume it removes.
void build_inlet(std::size_t m, const blade::BladeModel& model, const CoreDefinition& def, CoreBuild& out) {
  InletPlacement& p = out.inlets[m];
  const InletDefinition& in = def.inlets[m];
  p.rim.system = out.chambers[static_cast<std::size_t>(in.chamber - 1)].system;
  const gp_Ax2 ax(occt::to_pnt(p.origin + p.from * p.axis), gp_Dir(p.axis.x(), p.axis.y(), p.axis.z()));
  BRepPrimAPI_MakeCylinder cyl(ax, p.radius, p.to - p.from);
  cyl.Build();
  if (!cyl.IsDone()) throw FeatureFailure(p.name + ": cannot make its cylinder");
  const TopoDS_Shape s = cyl.Shape();
  FeatureTool tool;
  tool.feature = p.name;
  tool.shape.shape = s;
  for (const TopoDS_Shape& f : faces_of(s)) tool.shape.faces.push_back({TopoDS::Face(f), p.name});
  // It removes the material between the flow-path surface and the end wall (beyond the end wall it
  // opens into the chamber): the integral over its disc of the axial distance between the two surfaces
  // (Gauss-Legendre in the radius, the trapezoidal rule in the angle, exact for periodic integrands).
  const EndWall& wall = end_wall_of(in, out);
  const EndWall flow_path(model, in.end, 0.0);
  const Vec3 e1 = p.axis.unitOrthogonal(), e2 = p.axis.cross(e1);
  tool.expected_volume = disc_integral(p.radius, [&](double rho, double phi) {
    const Vec3 base = p.origin + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    return along_line(wall, base, p.axis, 0.0) - along_line(flow_path, base, p.axis, 0.0);
  });
  out.inlet_volumes.push_back(tool.expected_volume);
  out.cut_tools.push_back(tool);
}

}  // namespace

void build_core_cells(const blade::BladeModel& model, const CoreDefinition& def, CoreBuild& out) {
  Stopwatch sw;
  const blade::BladeCoordinates coords(model);
  const double delta = end_margin(model);
  FaceNames names;
  const brep::BladeSolid core = build_core_solid(model, def, out, delta, names);
  out.seconds.emplace_back("core_solid", sw.lap());

  // 2. Ribs (the chambers are build_core_walls').
  build_rib_tubes(model, def, out, names);
  out.seconds.emplace_back("ribs", sw.lap());

  const std::vector<TopoDS_Shape> cells = split_core_by_ribs(core.solid, out.ribs, names);
  // The cells partition the core: their volumes give the core's, the ribs' and (before the fillets)
  // the chambers'.
  const std::vector<double> cell_volume = volumes_of(cells);
  for (double v : cell_volume) out.core_volume += v;
  const std::vector<int> cell_of = chamber_cells(cells, out.chambers);
  measure_rib_cells(cells, cell_volume, cell_of, names, def, out);
  out.seconds.emplace_back("split", sw.lap());

  // 3. + 4. Per coolant cell: fillets, naming split, merge.
  std::map<int, std::vector<int>> systems;  // cell -> chambers (0-based)
  for (std::size_t k = 0; k < cell_of.size(); ++k) systems[cell_of[k]].push_back(static_cast<int>(k));
  for (const auto& [cell_index, members] : systems)
    build_chamber_system(cells[static_cast<std::size_t>(cell_index)], cell_volume[static_cast<std::size_t>(cell_index)],
                         members, def, names, out);
  out.seconds.emplace_back("fillets_and_names", sw.lap());

  mark_fed_chambers(def, out);
  for (std::size_t m = 0; m < def.inlets.size(); ++m) build_inlet(m, model, def, out);
  out.seconds.emplace_back("inlets", sw.lap());
}

void check_inlet_rims(const CoreBuild& core) {
  // ~20 ms per point on a serpentine's solid (rays against its B-spline faces): each inlet on its own core.
  parallel_for(static_cast<int>(core.inlets.size()), parallel_workers(), [&](int m, int) {
    const InletRim& rim = core.inlets[static_cast<std::size_t>(m)].rim;
    Inside in_target(core.systems[static_cast<std::size_t>(rim.system)].shape);
    for (const Vec3& p : rim.points)
      if (!in_target(p)) throw PassageInputError(rim.field, rim.message);
  });
}

CoreBuild build_core_tools(const blade::BladeModel& model, const CoreDefinition& def) {
  check_core_definition(model, def);
  CoreBuild out = build_core_walls(model, def);
  build_core_cells(model, def, out);
  check_inlet_rims(out);
  return out;
}

}  // namespace cg::features
