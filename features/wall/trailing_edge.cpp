#include "features/wall/trailing_edge.hpp"

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <OSD_Parallel.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "src/brep/naming/face_names.hpp"
#include "features/wall/ruled_block.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/algo/segment_distance.hpp"
#include "src/analyze/cell_quadrature.hpp"
#include "src/core/newton.hpp"

namespace cg::features {
namespace {

using Vec3 = Eigen::Vector3d;
// Gauss cells per direction and span between breaks: the integrands are smooth between the breaks
// (measured against OCCT's Common of the tool with the part: 1e-7 .. 3e-7 relative on the example).
constexpr int kCellsChannel = 2, kCellsCutback = 4;

std::string field(const std::string& m) { return "core.trailing_edge." + m; }

std::string numbered(int n, int digits) {
  char b[16];
  std::snprintf(b, sizeof b, "%0*d", digits, n);
  return b;
}

struct TeFrame {
  double span = 0;
  Vec3 o, x, y, z;
  double te_x = 0;      // x of the TE point
  double crease_x = 0;  // x of the crease (the chamber's TE end)
  double crease_y = 0;  // y of the crease
  Vec3 at(double a, double b, double c) const { return o + a * x + b * y + c * z; }
};

TeFrame te_frame(const blade::BladeCoordinates& coords, const CoreDefinition& def, double s) {
  const TrailingEdgeDefinition& te = *def.trailing_edge;
  const blade::InnerWallSection cr = blade::inner_wall_crease(coords, def.wall_thickness, s);
  if (!cr.trimmed)
    throw PassageInputError(field("type"), "the inner wall rounds the trailing edge at span " + format_number(s) +
                                               " (TE radius >= wall thickness): the last chamber has no TE end to "
                                               "eject from");
  TeFrame f;
  f.span = s;
  const blade::BladeFrame te_point = coords.frame(s, 1.0);
  const Vec3 P = te_point.point;
  if (te.type == TrailingEdgeType::Centreline) {
    f.o = cr.crease;
    f.x = (P - f.o).normalized();
  } else {
    const blade::BladeFrame a = coords.frame(s, cr.suction_chord);
    f.o = a.point;
    f.x = a.chord_tangent;  // LE -> TE on the suction side
  }
  // z: the span direction; for a centreline slot the crease's own tangent, so the crease lies on the
  // slot's mid-plane y = 0 across the slot's width (up to its curvature) and the kink it puts in the
  // removed-volume integrand stays on one quadrature break.
  Vec3 t = te_point.span_tangent;
  if (te.type == TrailingEdgeType::Centreline) {
    const double ds = 1e-4;
    const Vec3 t_crease = blade::inner_wall_crease(coords, def.wall_thickness, std::min(s + ds, 1.0)).crease -
                          blade::inner_wall_crease(coords, def.wall_thickness, std::max(s - ds, 0.0)).crease;
    t = t_crease.dot(t) > 0 ? t_crease : Vec3(-t_crease);
  }
  f.z = (t - t.dot(f.x) * f.x).normalized();
  f.y = f.z.cross(f.x);
  if ((coords.frame(s, cr.pressure_chord).point - f.o).dot(f.y) < 0) {
    f.y = -f.y;
    f.z = f.x.cross(f.y);
  }
  f.te_x = (P - f.o).dot(f.x);
  f.crease_x = (cr.crease - f.o).dot(f.x);
  f.crease_y = (cr.crease - f.o).dot(f.y);
  return f;
}

// Blade surface (outer) and chamber (inner) extents along y at (x, z): [first, last] crossing.
struct Across {
  bool ok = false;
  double lo = 0, hi = 0;
};
Across across(WallLines& lines, const TeFrame& f, double x, double z, bool outer) {
  const double r = 20.0;  // mm: far upstream the frame's y-lines meet the convex suction side at y > 0
  const Vec3 a = f.at(x, -r, z), b = f.at(x, r, z);
  const std::vector<double> t = outer ? lines.outer_crossings(a, b) : lines.inner_crossings(a, b);
  Across out;
  if (t.size() != 2) return out;
  out.ok = true;
  out.lo = -r + 2 * r * t[0];
  out.hi = -r + 2 * r * t[1];
  return out;
}

// Spans with positions at equal arc length along the crease line, between the end walls.
struct SpanLine {
  std::vector<double> s, len;
  double length() const { return len.back(); }
  double span_at(double y) const {
    std::size_t j = 0;
    while (j + 2 < s.size() && len[j + 1] < y) ++j;
    return s[j] + (s[j + 1] - s[j]) * (y - len[j]) / (len[j + 1] - len[j]);
  }
};

// `hub`, `tip`: the end walls (EndWall(model, end, 0) where an end is open), as the core builds them.
SpanLine crease_line(const blade::BladeCoordinates& coords, const CoreDefinition& def, const EndWall& hub, const EndWall& tip,
                     double margin) {
  auto crease = [&](double s) { return blade::inner_wall_crease(coords, def.wall_thickness, s).crease; };
  // Each value costs an exact section of the inner wall (~5 ms): Illinois regula falsi on [0, 1] needs
  // ~8 of them where bisection to the same 6e-8 in span needed 24. Without a sign change the end
  // where |f| is smaller (for these monotone f: the end bisection converged to).
  auto root = [&](auto f) {
    const double f0 = f(0.0), f1 = f(1.0);
    if ((f0 < 0) == (f1 < 0)) return std::abs(f0) < std::abs(f1) ? 0.0 : 1.0;
    return newton::solve_bracketed_secant(f, 0.0, 1.0, f0, f1, 6e-8);
  };
  const double s0 = root([&](double s) { return hub.signed_distance(crease(s)) - margin; });
  const double s1 = root([&](double s) { return tip.signed_distance(crease(s)) - margin; });
  SpanLine out;
  const int n = 24;
  Vec3 prev;
  for (int j = 0; j <= n; ++j) {
    out.s.push_back(s0 + (s1 - s0) * j / n);
    const Vec3 p = crease(out.s.back());
    out.len.push_back(j == 0 ? 0.0 : out.len.back() + (p - prev).norm());
    prev = p;
  }
  return out;
}


// Centred positions: `count` items at `pitch` on [lo, hi].
std::vector<double> centred(double lo, double hi, double pitch, int count) {
  std::vector<double> out;
  const double first = 0.5 * (lo + hi) - 0.5 * (count - 1) * pitch;
  for (int j = 0; j < count; ++j) out.push_back(first + j * pitch);
  return out;
}

// The slot's inlet: the first station x upstream of x_from where the chamber holds the inlet face
// (height H, width w - 2 x taper at station x, 0.05 mm clear all round). centred: the face is centred in
// the chamber at z = 0 (the channel then tilts to the slot under the lip); otherwise it spans [y0, y0 + H].
struct Inlet {
  double x = std::nan(""), y = 0;
};
Inlet inlet_station(WallLines& lines, const TeFrame& f, double x_from, double y0, double h, double w, double taper,
                    bool centred) {
  for (double x = x_from - 0.2; x > x_from - 30; x -= 0.1) {
    const double wx = w - 2 * x * taper;
    const Across mid = across(lines, f, x, 0.0, false);
    if (!mid.ok) continue;
    const double y = centred ? 0.5 * (mid.lo + mid.hi) - 0.5 * h : y0;
    auto holds = [&](const Across& c) { return c.ok && c.lo < y - 0.05 && c.hi > y + h + 0.05; };
    // The middle line first: most stations upstream of the crease are too narrow there already.
    if (holds(mid) && holds(across(lines, f, x, -0.5 * wx, false)) && holds(across(lines, f, x, 0.5 * wx, false)))
      return {x, y};
  }
  return {};
}

// The width of a slot that the lands' taper closed, without a negative width: "the lands overlap by 0.2 mm".
std::string closed_width(double w) { return w < 0 ? "the lands overlap by " + format_number(-w) + " mm" : "width 0 mm"; }

// A tapered centreline slot: still open where it leaves the blade (w_out > 0 at the tool's end, 1 mm past
// the TE) and apart from its neighbours at the inlet, where it is widest (w_in < pitch).
void check_centreline_widths(const TrailingEdgeDefinition& te, const std::string& name, double s, double pitch,
                             int count, double x_in, double x_out, double w_in, double w_out) {
  const double w = te.slot_width;
  if (!(w_out > 0))
    throw PassageInputError(field("land_taper_deg"), name + ": the lands' taper closes the slot before it leaves the "
                                                             "blade at span " + format_number(s) + " (" + closed_width(w_out) +
                                                             " there); must be < " +
                                                             format_limit(std::atan(w / (2 * x_out)) * 180 / kPi, Allowed::below) + " deg here");
  if (count > 1 && !(w_in < pitch - 0.05))
    throw PassageInputError(field("land_taper_deg"),
                            name + ": with the taper the slots' inlets in the chamber (" + format_number(-x_in) +
                                " mm upstream of the crease, " + format_number(w_in) + " mm wide) touch their neighbours at span " +
                                format_number(s) + "; must be < " +
                                format_limit(std::atan((pitch - 0.05 - w) / (2 * -x_in)) * 180 / kPi, Allowed::below) + " deg here");
}

}  // namespace

void check_trailing_edge_definition(const CoreDefinition& def) {
  if (!def.trailing_edge) return;
  const TrailingEdgeDefinition& te = *def.trailing_edge;
  auto in_range = [](double v, double lo, double hi, const std::string& name, const char* unit) {
    if (!(v > lo && v <= hi))
      throw PassageInputError(field(name), "must be in (" + format_limit(lo, Allowed::above) + ", " + format_limit(hi, Allowed::below) + "] " +
                                               unit + ", got " + format_value_range(v, lo, hi).value);
  };
  in_range(te.slot_height, 0, 10, "slot_height", "mm");
  in_range(te.slot_width, 0, 50, "slot_width", "mm");
  if (te.pitch > 0) {
    if (!(te.pitch > te.slot_width)) {
      const ValueLimitText t = format_value_limit(te.pitch, te.slot_width, Allowed::above);
      throw PassageInputError(field("pitch"), "slot pitch must be > slot_width = " + t.limit +
                                                  " mm (the lands between the slots need width), got " + t.value);
    }
  } else if (te.count < 1) {
    throw PassageInputError(field("count"), "give the slot pitch or a count >= 1");
  }
  if (!(te.span_margin >= 0 && te.span_margin <= 50))
    throw PassageInputError(field("span_margin"), "must be in [0, 50] mm, got " + format_value_range(te.span_margin, 0, 50).value);
  if (!(te.land_taper_deg >= 0 && te.land_taper_deg < 45))
    throw PassageInputError(field("land_taper_deg"), "must be in [0, 45) deg, got " + format_value_range(te.land_taper_deg, 0, 45).value);
  if (te.type == TrailingEdgeType::PressureSideCutback) {
    in_range(te.lip_thickness, 0, 10, "lip_thickness", "mm");
    in_range(te.cutback_length, 0, 50, "cutback_length", "mm");
    const double w_te = te.slot_width - 2 * (te.cutback_length + 1.0) * std::tan(te.land_taper_deg * kPi / 180);
    if (!(w_te > 0))
      throw PassageInputError(field("land_taper_deg"),
                              "the lands' taper closes the slots before the TE (" + closed_width(w_te) + " there): must be < " +
                                  format_limit(std::atan(te.slot_width / (2 * (te.cutback_length + 1.0))) * 180 / kPi, Allowed::below) +
                                  " deg");
  }
  if (te.pin_fins) {
    const PinFinDefinition& p = *te.pin_fins;
    in_range(p.diameter, 0, 10, "pin_fins.diameter", "mm");
    if (!(p.spanwise_pitch > p.diameter)) {
      const ValueLimitText t = format_value_limit(p.spanwise_pitch, p.diameter, Allowed::above);
      throw PassageInputError(field("pin_fins.spanwise_pitch"), "must be > diameter = " + t.limit + " mm, got " + t.value);
    }
    if (!(p.streamwise_pitch > p.diameter)) {
      const ValueLimitText t = format_value_limit(p.streamwise_pitch, p.diameter, Allowed::above);
      throw PassageInputError(field("pin_fins.streamwise_pitch"), "must be > diameter = " + t.limit + " mm, got " + t.value);
    }
    if (p.rows < 1 || p.rows > 20)
      throw PassageInputError(field("pin_fins.rows"), "must be in [1, 20], got " + std::to_string(p.rows));
    if (!(p.slot_gap >= 0 && p.slot_gap <= 20))
      throw PassageInputError(field("pin_fins.slot_gap"), "must be in [0, 20] mm, got " + format_value_range(p.slot_gap, 0, 20).value);
  }
}

namespace {

// The slots' spans along the chamber's TE end (between the end walls, span_margin clear of them), their
// pitch, and the pitch/count errors. `hub`, `tip`: the core's end walls (null: that end is open).
struct SlotLayout {
  SpanLine line;  ///< the chamber's TE end between the end walls
  std::vector<double> spans;
  double pitch = 0;
};

SlotLayout slot_layout(const blade::BladeModel& model, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                       const EndWall* hub, const EndWall* tip) {
  const TrailingEdgeDefinition& te = *def.trailing_edge;
  SlotLayout out;
  out.line = crease_line(coords, def, hub ? *hub : EndWall(model, SpanEnd::Hub, 0.0),
                         tip ? *tip : EndWall(model, SpanEnd::Tip, 0.0), te.span_margin);
  const SpanLine& line = out.line;
  const double lo = 0.5 * te.slot_width, hi = line.length() - 0.5 * te.slot_width;
  if (hi < lo)
    throw PassageInputError(field("span_margin"), "no slot fits between the end walls (" + format_number(line.length()) +
                                                      " mm along the chamber's TE end)");
  out.pitch = te.pitch;
  int count = te.count;
  if (out.pitch > 0) {
    count = static_cast<int>(std::floor((hi - lo) / out.pitch + 1e-9)) + 1;
  } else {
    out.pitch = count > 1 ? (hi - lo) / (count - 1) : 0.0;
    if (count > 1 && !(out.pitch > te.slot_width)) {
      const ValueLimitText t = format_value_limit(out.pitch, te.slot_width, Allowed::above);
      throw PassageInputError(field("count"), std::to_string(count) + " slots give a pitch of " + t.value +
                                                  " mm, not more than slot_width " + t.limit + " mm: at most " +
                                                  std::to_string(static_cast<int>(std::floor((hi - lo) / te.slot_width))) +
                                                  " slots fit");
    }
  }
  for (double yc : centred(lo, hi, out.pitch, count)) out.spans.push_back(line.span_at(yc));
  return out;
}

// A cutback's lip must lie downstream of the last chamber's end (kLipClear).
void check_lip(const TrailingEdgeDefinition& te, const TeFrame& f, double s) {
  if (!(f.te_x - te.cutback_length > f.crease_x + kLipClear)) {
    const ValueLimitText t = format_value_limit(te.cutback_length, f.te_x - f.crease_x - kLipClear, Allowed::below);
    throw LipOverChamber(field("cutback_length"), "must be < " + t.limit + " mm at span " + format_number(s) +
                                                      " (the lip must lie downstream of the last chamber's end), got " + t.value);
  }
}

}  // namespace

namespace {

// The cutback's floor leaves the blade through one side of the TE's rounding, at least kFloorTipGap from
// its tip (the last point of the blade along the slot at the slot's middle and sides: section_tip, else
// bisection on the frame's y-lines; on the rotor's 54 tips Newton's lies 6e-4 mm further along x than
// the bisection's last line through the blade and 4.4e-4 mm from that line's chord midpoint, at a
// twentieth of the line queries). A floor through the tip ends on a knife edge at the blade surface's seam:
// OCCT's boolean then fails (BOPAlgo_AlertFaceBuilderUnusedEdges, data/repro/te_cutback_short.json:
// floors 0.06-0.07 mm from the tip failed, 0.16-0.17 mm built; bench/random_designs.py seed 11 light,
// 2026-12-06: floors 0.105 and 0.185 mm from the tip failed (slot 5 of variants 88 and 72), every
// cutback whose floors kept 0.25 mm or more built (the nearest 0.251 and 0.261 mm)).
constexpr double kFloorTipGap = 0.2;  // mm

// The blade's tip in the frame's plane z = z0 (the point of the wall's section there furthest along x),
// as frame (x, y): Newton on the wall's (u, v) for g1 = (S - o).z - z0 = 0 (on the plane) and g2 =
// det[S_u.x, S_v.x; S_u.z, S_v.z] = 0 (the section's tangent normal to x), from the TE point (u0, v0).
// Checked by the lines themselves: the y-line 0.01 mm before it meets the blade, 0.01 mm past it not.
// Empty when Newton does not settle or the lines disagree (the caller bisects instead).
std::optional<Eigen::Vector2d> section_tip(const BSplineSurface<3>& S, WallLines& lines, const TeFrame& f, double z0,
                                           double u0, double v0) {
  double u = u0, v = v0;
  for (int it = 0; it < 30; ++it) {
    S.check_params(u, v);
    const auto d = S.derivatives<2>(u, v);
    const Vec3 &Su = d.S_u(), &Sv = d.S_v(), &Suu = d.S_uu(), &Suv = d.S_uv(), &Svv = d.S_vv();
    const double ux = Su.dot(f.x), vx = Sv.dot(f.x), uz = Su.dot(f.z), vz = Sv.dot(f.z);
    const Eigen::Vector2d g((d.S() - f.o).dot(f.z) - z0, ux * vz - vx * uz);
    if (std::abs(g[0]) < 1e-11 && std::abs(g[1]) < 1e-10 * Su.norm() * Sv.norm()) {
      const Vec3 p = d.S() - f.o;
      const double x = p.dot(f.x);
      if (!(std::abs(x - f.te_x) < 1.0) || !across(lines, f, x - 0.01, z0, true).ok || across(lines, f, x + 0.01, z0, true).ok)
        return std::nullopt;
      return Eigen::Vector2d(x, p.dot(f.y));
    }
    Eigen::Matrix2d J;
    J << uz, vz,
        Suu.dot(f.x) * vz + ux * Suv.dot(f.z) - Suv.dot(f.x) * uz - vx * Suu.dot(f.z),
        Suv.dot(f.x) * vz + ux * Svv.dot(f.z) - Svv.dot(f.x) * uz - vx * Suv.dot(f.z);
    Eigen::Vector2d step = J.fullPivLu().solve(-g);
    if (!step.allFinite()) return std::nullopt;
    const double limit = 0.01;  // parameter units per step: stay on the TE's rounding
    if (step.cwiseAbs().maxCoeff() > limit) step *= limit / step.cwiseAbs().maxCoeff();
    u += step[0];
    v = std::clamp(v + step[1], S.first_v(), S.last_v());
  }
  return std::nullopt;
}

void check_floor_off_the_tip(const TrailingEdgeDefinition& te, WallLines& lines, const blade::BladeCoordinates& coords,
                             const TeFrame& f, double s, const SlotInfo& info) {
  const blade::BladeFrame te_point = coords.frame(s, 1.0);
  for (const double z : {-0.5 * te.slot_width, 0.0, 0.5 * te.slot_width}) {
    double tip_y = 0;
    if (const auto tip = section_tip(coords.model().surface, lines, f, z, te_point.u, te_point.v)) {
      tip_y = tip->y();
    } else {
      double in = info.x_lip, out = f.te_x + 1.0;  // across() finds the blade at `in`, not at `out`
      if (!across(lines, f, in, z, true).ok || across(lines, f, out, z, true).ok) continue;
      // (1 mm + cutback) / 2^16 < 3e-5 mm in x; the chord's midpoint at that depth below the tip (where
      // the section's tangent is along y) lies within O(depth) of the tip, far below the 0.2 mm asked.
      for (int it = 0; it < 16; ++it) {
        const double mid = 0.5 * (in + out);
        (across(lines, f, mid, z, true).ok ? in : out) = mid;
      }
      const Across chord = across(lines, f, in, z, true);
      tip_y = 0.5 * (chord.lo + chord.hi);
    }
    const double gap = std::abs(info.floor_y - tip_y);
    if (gap < kFloorTipGap)
      throw PassageInputError(field("cutback_length"),
                              info.name + ": the cutback's floor passes " + format_value_limit(gap, kFloorTipGap, Allowed::above).value +
                                  " mm from the trailing edge's tip at span " + format_number(s) + " (at least " +
                                  format_number(kFloorTipGap) + " mm: a floor nearer the tip leaves a knife edge that cannot be cut); "
                                  "change cutback_length, slot_height or lip_thickness");
  }
}

// Where slot `info` sits across the blade at span s: under the lip (cutback: the lip checked, and the
// suction-side wall left under its floor) or on the centreline (the wall on both sides); sets its
// x_lip and floor_y.
void place_slot(const TrailingEdgeDefinition& te, bool cutback, WallLines& lines, const blade::BladeCoordinates& coords,
                const TeFrame& f, double s, SlotInfo& info) {
  const std::string& name = info.name;
  if (cutback) {
    info.x_lip = f.te_x - te.cutback_length;
    check_lip(te, f, s);
    const Across b = across(lines, f, info.x_lip, 0.0, true);
    if (!b.ok) throw FeatureFailure(name + ": cannot find the blade's pressure side at the lip");
    info.floor_y = b.hi - te.lip_thickness - te.slot_height;
    // Suction-side wall left under the floor, from the lip to 1 mm before the TE.
    for (int k = 0; k <= 8; ++k) {
      const double x = info.x_lip + (f.te_x - 1.0 - info.x_lip) * k / 8.0;
      const Across c = across(lines, f, x, 0.0, true);
      const double left = c.ok ? info.floor_y - c.lo : 0.0;
      if (!c.ok || left < 0.1)
        throw PassageInputError(field("slot_height"),
                                name + ": slot_height + lip_thickness " +
                                    (left < 0 ? "reach " + format_number(-left) + " mm past the suction-side wall"
                                              : "leave " + format_number(left) + " mm of suction-side wall") +
                                    " under the cutback at span " + format_number(s) + " (at least 0.1 mm must be left); must be <= " +
                                    format_limit(b.hi - b.lo - 0.1, Allowed::below) + " mm together here");
    }
    check_floor_off_the_tip(te, lines, coords, f, s, info);
  } else {
    info.x_lip = f.te_x;
    info.floor_y = -0.5 * te.slot_height;
    // At least 0.1 mm of wall on both sides of the slot over the first half of the way from the crease
    // to the TE (the blade's flanks; the second half holds the TE's rounding, through which the slot
    // leaves the blade).
    double h_max = HUGE_VAL;
    for (int k = 0; k <= 4; ++k) {
      const double x = f.crease_x + 0.5 * (f.te_x - f.crease_x) * k / 4.0;
      const Across c = across(lines, f, x, 0.0, true);
      if (!c.ok) throw FeatureFailure(name + ": cannot find the blade's walls across the slot");
      h_max = std::min(h_max, 2 * (std::min(-c.lo, c.hi) - 0.1));
    }
    if (!(te.slot_height <= h_max)) {
      const ValueLimitText t = format_value_limit(te.slot_height, std::max(h_max, 0.0), Allowed::below);
      throw PassageInputError(field("slot_height"), name + ": the slot leaves less than 0.1 mm of wall on a side between "
                                                           "the chamber's end and the TE at span " + format_number(s) +
                                                           "; must be <= " + t.limit + " mm here, got " + t.value);
    }
  }
}

// The cutback of slot `info`, joined to its channel's `tool`; adds its share to `expected` (the
// material it removes) and `tool_volume` (its construction volume).
void add_cutback(const TrailingEdgeDefinition& te, WallLines& lines, const TeFrame& f, const SlotInfo& info, double taper,
                 brep::NamedShape& tool, double& expected, double& tool_volume) {
  const std::string& name = info.name;
  const double w = te.slot_width, y0 = info.floor_y;
  // Everything above the floor from the lip to past the TE, between the tapered lands. Lines run from
  // the block's end face past the TE (outside) back to the lip: each enters the blade once through
  // the pressure side or the TE, so its length in the material is smooth in (y, z) up to the height
  // of the pressure surface at the lip, where it drops to zero (a kink: a break of the quadrature).
  // (Lines across the floor would graze the TE's rounding, a square-root singularity.)
  const double we = w - 2 * (info.x_end - info.x_lip) * taper;
  // The block's top at each side z = -+w/2 lies so that the pressure surface at the lip is at the
  // same fraction kLip of its height on both sides: the kink is then (to the surface's curvature
  // across the slot) on one parameter line, a break of the quadrature.
  constexpr double kLip = 0.75;
  double top[2];
  for (int k = 0; k < 2; ++k) {
    const Across a = across(lines, f, info.x_lip, (k ? 0.5 : -0.5) * w, true);
    if (!a.ok) throw FeatureFailure(name + ": cannot find the blade's pressure side at the lip");
    top[k] = y0 + (a.hi - y0) / kLip;
  }
  const RuledBlock cut{bilinear_patch(f.at(info.x_end, y0, -0.5 * we), f.at(info.x_end, top[0], -0.5 * we),
                                      f.at(info.x_end, y0, 0.5 * we), f.at(info.x_end, top[1], 0.5 * we)),
                       bilinear_patch(f.at(info.x_lip, y0, -0.5 * w), f.at(info.x_lip, top[0], -0.5 * w),
                                      f.at(info.x_lip, y0, 0.5 * w), f.at(info.x_lip, top[1], 0.5 * w))};
  const double a_lip = kLip;
  const BlockIntegral vb = integrate_block(cut, lines, Region::Outside, Region::Material, Region::Any,
                                           {kCellsCutback, 2, {a_lip}, false});
  const brep::NamedShape cut_solid = ruled_block_solid(cut, name);
  BRepAlgoAPI_Fuse fuse(tool.shape, cut_solid.shape);
  if (!fuse.IsDone() || fuse.HasErrors()) throw FeatureFailure(name + ": joining the channel and the cutback failed");
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape(), true, true, false);
  unify.Build();
  const std::vector<TopoDS_Shape> solids = solids_of(unify.Shape());
  if (solids.size() != 1) throw FeatureFailure(name + ": channel and cutback do not form one solid");
  tool.shape = solids.front();
  tool.faces.clear();
  for (const TopoDS_Shape& face : faces_of(tool.shape)) tool.faces.push_back({TopoDS::Face(face), name});
  expected += vb.in_region;
  tool_volume += vb.volume;
}

// Slot `name` at span s: its frame, where it sits across the blade (place_slot), its inlet station in
// the last chamber and, centreline, its widths; `count` slots at `pitch` (the layout's).
SlotInfo plan_slot(const std::string& name, double s, const TrailingEdgeDefinition& te, const blade::BladeCoordinates& coords,
                   const CoreDefinition& def, double pitch, int count, WallLines& lines) {
  const bool cutback = te.type == TrailingEdgeType::PressureSideCutback;
  const double taper = std::tan(te.land_taper_deg * kPi / 180);
  const TeFrame f = te_frame(coords, def, s);
  SlotInfo info;
  info.name = name;
  info.span = s;
  info.origin = f.o;
  info.x = f.x;
  info.y = f.y;
  info.z = f.z;
  info.te_x = f.te_x;
  info.crease_x = f.crease_x;
  info.crease_y = f.crease_y;
  info.height = te.slot_height;
  info.width = te.slot_width;
  info.x_end = f.te_x + 1.0;
  place_slot(te, cutback, lines, coords, f, s, info);
  // Centreline: each land side turns by land_taper_deg from the crease (x = 0, slot width w) on, so
  // the slot narrows towards the TE (and widens upstream, inside the chamber).
  const double slot_taper = cutback ? 0.0 : taper;
  const double w = te.slot_width, h = te.slot_height;
  const Inlet in = inlet_station(lines, f, f.crease_x, info.floor_y, h, w, slot_taper, cutback);
  if (std::isnan(in.x))
    throw PassageInputError(field("slot_height"), name + " does not fit into the last chamber at span " + format_number(s) +
                                                       ": no station where the chamber holds its inlet (" + format_number(h) +
                                                       " x " + format_number(w) + " mm, 0.05 mm clear)");
  info.x_inlet = in.x;
  info.y_inlet = in.y;
  if (!cutback) {
    const double xc = info.x_end;
    check_centreline_widths(te, name, s, pitch, count, in.x, xc, w - 2 * in.x * slot_taper, w - 2 * xc * slot_taper);
  }
  return info;
}

// The frame slot `info` was placed in.
TeFrame frame_of(const SlotInfo& info) {
  TeFrame f;
  f.span = info.span;
  f.o = info.origin;
  f.x = info.x;
  f.y = info.y;
  f.z = info.z;
  f.te_x = info.te_x;
  f.crease_x = info.crease_x;
  f.crease_y = info.crease_y;
  return f;
}

// The tool of planned slot `planned`: its channel from the chamber (and its cutback), its expected
// volume, and its info in `out`; its construction volume is appended.
void build_slot(const SlotInfo& planned, const TrailingEdgeDefinition& te, WallLines& lines, TrailingEdgeBuild& out,
                std::vector<double>& construction_volumes) {
  const bool cutback = te.type == TrailingEdgeType::PressureSideCutback;
  const double taper = std::tan(te.land_taper_deg * kPi / 180);
  const TeFrame f = frame_of(planned);
  SlotInfo info = planned;
  const std::string& name = info.name;
  const double w = te.slot_width, y0 = info.floor_y, y1 = y0 + te.slot_height, h = te.slot_height;
  const double slot_taper = cutback ? 0.0 : taper;
  const double x_in = info.x_inlet, y_in = info.y_inlet;
  // Channel: from the inlet face in the chamber (centred in it for a cutback) straight to the slot's
  // exit face under the lip (cutback) or past the TE (centreline).
  const double xc = cutback ? info.x_lip : info.x_end;
  const double w_in = w - 2 * x_in * slot_taper, w_out = w - 2 * xc * slot_taper;
  const RuledBlock channel{bilinear_patch(f.at(x_in, y_in, -0.5 * w_in), f.at(x_in, y_in + h, -0.5 * w_in),
                                          f.at(x_in, y_in, 0.5 * w_in), f.at(x_in, y_in + h, 0.5 * w_in)),
                           bilinear_patch(f.at(xc, y0, -0.5 * w_out), f.at(xc, y1, -0.5 * w_out),
                                          f.at(xc, y0, 0.5 * w_out), f.at(xc, y1, 0.5 * w_out))};
  // The line of the channel through the crease (the inner wall's C0 edge) is a kink of the integrand.
  const double lc = (f.crease_x - x_in) / (xc - x_in);
  const double a_crease = (info.crease_y - y_in - lc * (y0 - y_in)) / h;
  const BlockIntegral vc = integrate_block(channel, lines, Region::Chamber, Region::Material,
                                           cutback ? Region::Material : Region::Outside,
                                           {kCellsChannel, kCellsChannel, {a_crease}, true});
  if (!vc.ok)
    throw PassageInputError(field("slot_height"), name + " at span " + format_number(info.span) + " does not run from the chamber through "
                                                       "the wall as placed (a line of it leaves the blade early)");
  brep::NamedShape tool = ruled_block_solid(channel, name);
  double expected = vc.in_region, tool_volume = vc.volume;
  if (cutback) add_cutback(te, lines, f, info, taper, tool, expected, tool_volume);
  construction_volumes.push_back(tool_volume);  // checked below, all slots at once on both cores
  info.removed_volume = expected;
  FeatureTool ft;
  ft.feature = name;
  ft.shape = tool;
  ft.expected_volume = expected;
  out.slot_tools.push_back(ft);
  out.slots.push_back(info);
}

// Each slot tool's B-rep volume against its construction (volume_of, accurate to 1e-7, against the volume
// checks' 1e-6 tolerance; independent per slot).
void check_slot_volumes(const TrailingEdgeBuild& out, const std::vector<double>& construction_volumes) {
  std::vector<char> volume_ok(out.slot_tools.size(), 1);
  OSD_Parallel::For(0, static_cast<int>(out.slot_tools.size()), [&](int k) {
    const double v = construction_volumes[static_cast<std::size_t>(k)];
    volume_ok[static_cast<std::size_t>(k)] =
        std::abs(volume_of(out.slot_tools[static_cast<std::size_t>(k)].shape.shape) - v) <= 1e-6 * v + 1e-9;
  });
  for (std::size_t k = 0; k < volume_ok.size(); ++k)
    if (!volume_ok[k]) throw FeatureFailure(out.slot_tools[k].feature + ": the tool solid's volume differs from its construction");
}

// Pin fin `name` of row `row` in the TE frame f (at span f.span), station x (upstream of the slots):
// clear of the last rib, across the chamber (axis, ends half a wall thickness inside both walls).
PinInfo plan_pin_fin(const std::string& name, int row, const TeFrame& f, double x, const PinFinDefinition& pf,
                     const blade::BladeCoordinates& coords, const CoreDefinition& def, WallLines& lines) {
  const RibDefinition* last_rib = def.ribs.empty() ? nullptr : &def.ribs.back();
  const double r = 0.5 * pf.diameter, s = f.span;
  if (last_rib) {
    // Clear of the last rib and its fillets: the pin's line (across the blade at x) against the rib's
    // mid-line between its wall points at this span.
    const Vec3 ra = blade::inner_wall_point(coords, def.wall_thickness, s, last_rib->suction_chord);
    const Vec3 rb = blade::inner_wall_point(coords, def.wall_thickness, s, last_rib->pressure_chord);
    const double need = r + 0.5 * last_rib->thickness + last_rib->fillet_radius + 0.1;
    if (segment_distance(f.at(x, -20.0, 0.0), f.at(x, 20.0, 0.0), ra, rb) < need)
      throw PassageInputError(field("pin_fins.rows"),
                              name + " (row " + std::to_string(row + 1) + ") reaches rib " +
                                  std::to_string(def.ribs.size()) + " and its fillet at span " + format_number(s) +
                                  ": fewer rows, a smaller streamwise_pitch or slot_gap");
  }
  const Across c = across(lines, f, x, 0.0, false);
  if (!c.ok) throw PassageInputError(field("pin_fins.rows"), name + ": no chamber across its axis at span " + format_number(s));
  // Axis: across the chamber, the bisector of the two walls' normals (the walls of the TE chamber
  // converge, so a pin along y would meet the pressure-side wall obliquely).
  const Vec3 mid = f.at(x, 0.5 * (c.lo + c.hi), 0.0);
  Vec3 n1 = lines.inner_normal(mid, f.at(x, -8.0, 0.0)), n2 = lines.inner_normal(mid, f.at(x, 8.0, 0.0));
  if (n1.dot(f.y) < 0) n1 = -n1;
  if (n2.dot(f.y) < 0) n2 = -n2;
  const Vec3 axis = (n1 + n2).normalized();
  const std::vector<double> hits = lines.inner_crossings(mid - 8.0 * axis, mid + 8.0 * axis);
  if (hits.size() != 2) throw PassageInputError(field("pin_fins.rows"), name + ": no chamber across its axis at span " + format_number(s));
  const double lo_a = -8.0 + 16.0 * hits[0], hi_a = -8.0 + 16.0 * hits[1];
  const double t = def.wall_thickness.min_value();
  PinInfo info;
  info.name = name;
  info.span = s;
  info.row = row;
  info.base = mid + (lo_a - 0.5 * t) * axis;
  info.axis = axis;
  info.z = f.z;
  info.length = hi_a - lo_a + t;
  info.diameter = pf.diameter;
  info.chamber_length = hi_a - lo_a;
  return info;
}

// The tool of planned pin `planned`: its volume inside the chamber (both ends must lie in the walls) and
// its cylinder, with its info in `out`.
void build_pin_fin(const PinInfo& planned, WallLines& lines, TrailingEdgeBuild& out) {
  PinInfo info = planned;
  const std::string& name = info.name;
  const double r = 0.5 * info.diameter, length = info.length;
  const Vec3 &base = info.base, &axis = info.axis;
  const Vec3 e1 = info.z.cross(axis).normalized(), e2 = axis.cross(e1);
  const double added = disc_integral(r, [&](double rho, double phi_) {
    const Vec3 off = rho * (std::cos(phi_) * e1 + std::sin(phi_) * e2);
    Region end;
    const double frac = total(lines.intervals(base + off, base + off + length * axis, Region::Material,
                                              Region::Chamber, &end));
    if (end != Region::Material)
      throw PassageInputError(field("pin_fins.diameter"), name + " at span " + format_number(info.span) + " does not end inside "
                                                                 "both walls (diameter too large for the chamber "
                                                                 "there)");
    return frac * length;
  });
  BRepPrimAPI_MakeCylinder cyl(gp_Ax2(gp_Pnt(base.x(), base.y(), base.z()), gp_Dir(axis.x(), axis.y(), axis.z())), r,
                               length);
  cyl.Build();
  if (!cyl.IsDone()) throw FeatureFailure(name + ": cannot make its cylinder");
  FeatureTool ft;
  ft.feature = name;
  ft.shape.shape = cyl.Shape();
  for (const TopoDS_Shape& face : faces_of(cyl.Shape())) ft.shape.faces.push_back({TopoDS::Face(face), name});
  ft.expected_volume = added;
  info.added_volume = added;
  out.pin_tools.push_back(ft);
  out.pins.push_back(info);
}

// Pin fins: staggered rows upstream of the slots' inlets (the most upstream one, inlet_x_min).
void plan_pin_fins(const PinFinDefinition& pf, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                   const SpanLine& line, WallLines& lines, double inlet_x_min, TrailingEdgePlan& out) {
  const double r = 0.5 * pf.diameter;
  const double plo = r, phi = line.length() - r;
  int number = 0;
  const int n_even = static_cast<int>(std::floor((phi - plo) / pf.spanwise_pitch + 1e-9)) + 1;
  const std::vector<double> even = centred(plo, phi, pf.spanwise_pitch, n_even);
  std::map<double, TeFrame> frames;  // the rows of one parity share their spans (each frame an exact section)
  for (int row = 0; row < pf.rows; ++row) {
    std::vector<double> at;  // odd rows: shifted by half the pitch (staggered), as many as fit
    for (double y : even)
      if (!(row % 2)) at.push_back(y);
      else if (y + 0.5 * pf.spanwise_pitch <= phi) at.push_back(y + 0.5 * pf.spanwise_pitch);
    for (double yc : at) {
      const double s = line.span_at(yc);
      const std::string name = "pin_fin_" + numbered(++number, 3);
      // Row station: upstream of the slots' inlets (the most upstream one, in this frame).
      const double x = inlet_x_min - pf.slot_gap - r - row * pf.streamwise_pitch;
      auto frame = frames.find(s);
      if (frame == frames.end()) frame = frames.emplace(s, te_frame(coords, def, s)).first;
      out.pins.push_back(plan_pin_fin(name, row, frame->second, x, pf, coords, def, lines));
    }
  }
}

}  // namespace

double te_region_length(const blade::BladeCoordinates& coords, const CoreDefinition& def, double span) {
  const TeFrame f = te_frame(coords, def, span);
  return f.te_x - f.crease_x;
}

TrailingEdgePlan plan_trailing_edge(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core,
                                    WallLines& lines) {
  check_trailing_edge_definition(def);
  TrailingEdgePlan out;
  if (!def.trailing_edge) return out;
  const TrailingEdgeDefinition& te = *def.trailing_edge;
  const bool cutback = te.type == TrailingEdgeType::PressureSideCutback;
  // A centreline slot cuts through the chamber's crease, a false seam of the part (src/brep/boolean/false_seams.hpp):
  // the slot step repairs it first.
  out.through_crease = !cutback;
  const blade::BladeCoordinates coords(model);
  const SlotLayout layout = slot_layout(model, coords, def, core.hub_floor ? &*core.hub_floor : nullptr,
                                        core.tip_cap ? &*core.tip_cap : nullptr);
  int slot_number = 0;
  double inlet_x_min = HUGE_VAL;
  for (double s : layout.spans) {
    out.slots.push_back(plan_slot("te_slot_" + numbered(++slot_number, 2), s, te, coords, def, layout.pitch,
                                  static_cast<int>(layout.spans.size()), lines));
    inlet_x_min = std::min(inlet_x_min, out.slots.back().x_inlet);
  }
  if (te.pin_fins) plan_pin_fins(*te.pin_fins, coords, def, layout.line, lines, inlet_x_min, out);
  return out;
}

TrailingEdgeBuild build_trailing_edge(const CoreDefinition& def, const TrailingEdgePlan& plan, WallLines& lines) {
  TrailingEdgeBuild out;
  if (!def.trailing_edge) return out;
  out.through_crease = plan.through_crease;
  std::vector<double> construction_volumes;
  for (const SlotInfo& slot : plan.slots) build_slot(slot, *def.trailing_edge, lines, out, construction_volumes);
  check_slot_volumes(out, construction_volumes);
  for (const PinInfo& pin : plan.pins) build_pin_fin(pin, lines, out);
  return out;
}

}  // namespace cg::features
