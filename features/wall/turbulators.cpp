#include "features/wall/turbulators.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "features/wall/ruled_block.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/fit/interpolate.hpp"
#include "src/fit/skin.hpp"

namespace cg::features {
namespace {

using Vec3 = Eigen::Vector3d;

std::string field(std::size_t i, const std::string& member) {
  return "core.turbulators[" + std::to_string(i) + "]" + (member.empty() ? "" : "." + member);
}

std::string number3(int n) {
  char b[16];
  std::snprintf(b, sizeof b, "%03d", n);
  return b;
}

// The outer wall S(u, v) and its inward offsets S - depth * n (n the outward unit normal).
class OffsetWall {
 public:
  OffsetWall(const blade::BladeCoordinates& coords) : s_(coords.model().surface) {
    const blade::BladeFrame f = coords.frame(0.5, 0.5);
    const auto d = s_.derivatives<1>(f.u, f.v);
    sign_ = d.S_u().cross(d.S_v()).dot(f.normal) > 0 ? 1.0 : -1.0;
  }
  Vec3 normal(double u, double v) const {
    const auto d = s_.derivatives<1>(u, v);
    return (sign_ * d.S_u().cross(d.S_v())).normalized();
  }
  Vec3 point(double u, double v, double depth) const { return s_.point(u, v) - depth * normal(u, v); }

 private:
  const BSplineSurface<3>& s_;
  double sign_ = 1;
};

// Root of a monotone f on [lo, hi] (f(lo) and f(hi) of opposite signs), by bisection.
template <class F>
double bisect(F f, double lo, double hi, int iterations = 40) {
  const bool rising = f(lo) < 0;
  for (int it = 0; it < iterations; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct WallSide {
  bool suction = true;
  double chord_from = 0, chord_to = 0;  // LE-side rib and TE-side rib chords (signed)
  const RibDefinition* rib_from = nullptr;
  const RibDefinition* rib_to = nullptr;
  double chord_mid() const { return 0.5 * (chord_from + chord_to); }
};

}  // namespace

void check_turbulator_definitions(const CoreDefinition& def) {
  const int chambers = static_cast<int>(def.ribs.size()) + 1;
  std::vector<bool> seen(static_cast<std::size_t>(chambers + 1), false);
  for (std::size_t i = 0; i < def.turbulators.size(); ++i) {
    const TurbulatorDefinition& t = def.turbulators[i];
    if (t.chamber < 2 || t.chamber > chambers - 1)
      throw PassageInputError(field(i, "chamber"),
                              "turbulators need a chamber between two ribs: must be in [2, " + std::to_string(chambers - 1) +
                                  "] (" + std::to_string(chambers) + " chambers; the LE chamber's walls meet at the "
                                  "leading edge and the last one ends at the trailing edge), got " + std::to_string(t.chamber));
    if (seen[static_cast<std::size_t>(t.chamber)])
      throw PassageInputError(field(i, "chamber"), "chamber " + std::to_string(t.chamber) + " has turbulators already");
    seen[static_cast<std::size_t>(t.chamber)] = true;
    auto positive = [&](double v, const char* name, double hi) {
      if (!(v > 0 && v <= hi))
        throw PassageInputError(field(i, name), "must be in (0, " + format_limit(hi, Allowed::below) + "] mm, got " +
                                                    format_value_range(v, 0, hi).value);
    };
    positive(t.height, "height", 5);
    positive(t.width, "width", 10);
    positive(t.pitch, "pitch", 100);
    if (!(t.angle_deg >= 30 && t.angle_deg <= 90))
      throw PassageInputError(field(i, "angle_deg"), "must be in [30, 90] deg, got " + format_value_range(t.angle_deg, 30, 90).value);
    if (!(t.end_gap >= 0 && t.end_gap <= 10))
      throw PassageInputError(field(i, "end_gap"), "must be in [0, 10] mm, got " + format_value_range(t.end_gap, 0, 10).value);
    if (!(t.span_margin >= 0 && t.span_margin <= 50))
      throw PassageInputError(field(i, "span_margin"), "must be in [0, 50] mm, got " + format_value_range(t.span_margin, 0, 50).value);
    // Along the passage axis a turbulator covers width / sin(angle): neighbours must not touch.
    const double along = t.width / std::sin(t.angle_deg * kPi / 180);
    if (!(t.pitch > along)) {
      const ValueLimitText p = format_value_limit(t.pitch, along, Allowed::above);
      throw PassageInputError(field(i, "pitch"), "must be > width / sin(angle) = " + p.limit +
                                                     " mm (neighbouring turbulators would touch), got " + p.value);
    }
  }
}

namespace {

// The spans of one definition's turbulators on the inline and on the shifted (staggered) wall.
struct RowSpans {
  std::vector<double> inline_spans, shifted_spans;
};

// Span range of the chamber's straight part on the first wall's mid line (iso-chord line), and the
// turbulators spread along it at their pitch.
RowSpans turbulator_spans(std::size_t i, const TurbulatorDefinition& td, const WallSide& first, const RibDefinition& ra,
                          const RibDefinition& rb, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                          const EndWall& hub, const EndWall& tip) {
  const double sin_a = std::sin(td.angle_deg * kPi / 180), cot_a = std::cos(td.angle_deg * kPi / 180) / sin_a;
  const double cm = first.chord_mid();
  auto mid_point = [&](double s) { return blade::inner_wall_point(coords, def.wall_thickness, s, cm); };
  auto end_clearance = [&](SpanEnd end) {
    double d = td.span_margin;
    for (const RibDefinition* r : {first.rib_from, first.rib_to})
      if (r->turnaround && r->turnaround->end == end)
        d = std::max(d, td.span_margin + r->turnaround->gap + 0.5 * r->thickness + r->fillet_radius);
    return d;
  };
  const double d_hub = end_clearance(SpanEnd::Hub), d_tip = end_clearance(SpanEnd::Tip);
  const double s_lo = bisect([&](double s) { return hub.signed_distance(mid_point(s)) - d_hub; }, 0.0, 1.0, 30);
  const double s_hi = bisect([&](double s) { return tip.signed_distance(mid_point(s)) - d_tip; }, 0.0, 1.0, 30);
  // Arc length along the mid line (polygon of 48 chords: the line is nearly straight).
  const int ns = 48;
  std::vector<double> sv(ns + 1), len(ns + 1, 0.0);
  Vec3 prev;
  for (int j = 0; j <= ns; ++j) {
    sv[j] = s_lo + (s_hi - s_lo) * j / ns;
    const Vec3 p = mid_point(sv[j]);
    if (j > 0) len[j] = len[j - 1] + (p - prev).norm();
    prev = p;
  }
  auto span_at = [&](double y) {
    int j = 0;
    while (j < ns - 1 && len[j + 1] < y) ++j;
    return sv[j] + (sv[j + 1] - sv[j]) * (y - len[j]) / (len[j + 1] - len[j]);
  };
  // Turbulator length across the wall at mid-span (for its extent along the axis).
  const double s_mid = 0.5 * (s_lo + s_hi);
  const double wall_width = (blade::inner_wall_point(coords, def.wall_thickness, s_mid, first.chord_to) -
                             blade::inner_wall_point(coords, def.wall_thickness, s_mid, first.chord_from)).norm();
  const double clear_a = 0.5 * ra.thickness + ra.fillet_radius + td.end_gap;
  const double clear_b = 0.5 * rb.thickness + rb.fillet_radius + td.end_gap;
  const double length_mid = wall_width - clear_a - clear_b;
  if (!(length_mid > td.width))
    throw PassageInputError(field(i, "end_gap"), "no turbulator fits across chamber " + std::to_string(td.chamber) +
                                                     ": the wall between the rib fillets is " +
                                                     format_number(wall_width - clear_a - clear_b + 2 * td.end_gap) +
                                                     " mm wide at mid-span");
  const double half_extent = 0.5 * length_mid * std::abs(cot_a) + 0.5 * td.width / sin_a;
  const double available = len[ns] - 2 * half_extent;
  if (available < 0)
    throw PassageInputError(field(i, "span_margin"),
                            "no turbulator fits in chamber " + std::to_string(td.chamber) + " between the end walls: " +
                                format_number(len[ns]) + " mm of straight passage, one turbulator needs " + format_number(2 * half_extent) + " mm");
  const int n = static_cast<int>(std::floor(available / td.pitch + 1e-9)) + 1;
  const double y0 = half_extent + 0.5 * (available - (n - 1) * td.pitch);
  RowSpans out;
  for (int j = 0; j < n; ++j) out.inline_spans.push_back(span_at(y0 + j * td.pitch));
  for (int j = 0; j + 1 < n; ++j) out.shifted_spans.push_back(span_at(y0 + (j + 0.5) * td.pitch));
  return out;
}

// Local development of the inner wall at the centre: x chordwise (LE side -> TE side), y along the
// passage axis (hub -> tip), mm -> outer-surface parameters (u, v) by the inverse metric.
struct WallDevelopment {
  blade::BladeFrame fc;
  double t = 0;  // wall thickness at the centre
  Vec3 ra_pt, rb_pt, centre, nrm, e1, e2;
  Eigen::Matrix<double, 3, 2> J;
  Eigen::Matrix2d G;
  Eigen::Vector2d params(double x, double y) const {
    return Eigen::Vector2d(fc.u, fc.v) + G.ldlt().solve(J.transpose() * (x * e1 + y * e2));
  }
};

WallDevelopment develop_wall(const blade::BladeCoordinates& coords, const CoreDefinition& def, const OffsetWall& wall,
                             const WallSide& side, double s) {
  WallDevelopment d;
  d.fc = coords.frame(s, side.chord_mid());
  const blade::BladeFrame& fc = d.fc;
  const double t = d.t = def.wall_thickness.at(s, side.chord_mid());
  d.ra_pt = blade::inner_wall_point(coords, def.wall_thickness, s, side.chord_from);
  d.rb_pt = blade::inner_wall_point(coords, def.wall_thickness, s, side.chord_to);
  const double h = 1e-5;
  const Vec3 Iu = (wall.point(fc.u + h, fc.v, t) - wall.point(fc.u - h, fc.v, t)) / (2 * h);
  const Vec3 Iv = (wall.point(fc.u, fc.v + h, t) - wall.point(fc.u, fc.v - h, t)) / (2 * h);
  d.centre = wall.point(fc.u, fc.v, t);
  Vec3 e1 = (d.rb_pt - d.ra_pt);
  d.nrm = wall.normal(fc.u, fc.v);
  e1 = (e1 - e1.dot(d.nrm) * d.nrm).normalized();
  Vec3 e2 = d.nrm.cross(e1);
  if (e2.dot(Iv) < 0) e2 = -e2;
  d.e1 = e1;
  d.e2 = e2;
  d.J << Iu, Iv;
  d.G = d.J.transpose() * d.J;
  return d;
}

// The rib next to a turbulator end in the cross-section through its foot on this wall: x along the wall
// away from the rib (perpendicular to the foot line), z along the wall's inward normal, both from the
// foot of the rib's mid-surface M(a, s) = A(s) + a (B(s) - A(s)) (rib_geometry.hpp). The rib is the slab
// within thickness / 2 of the mid-surface (its normal m, toward the chamber, taken perpendicular to the
// foot line's span tangent: the foot line is not along the development's passage axis where the blade
// twists or tapers); its fillet is the circle of radius r tangent to the wall and the rib's face in the
// corner on the chamber's side, of angle b: acute where the rib leans over the chamber (its fillet then
// reaches r cot(b / 2) along the wall from the face), obtuse on the other side.
class RibFootSection {
 public:
  RibFootSection(const RibDefinition& r, double s, double foot_chord, const Vec3& centre, const blade::BladeCoordinates& coords,
                 const CoreDefinition& def)
      : half_t_(0.5 * r.thickness), r_(r.fillet_radius) {
    auto inner = [&](double span, double chord) { return blade::inner_wall_point(coords, def.wall_thickness, span, chord); };
    foot_ = inner(s, foot_chord);
    const double ds = 1e-4;
    const Vec3 tangent = (inner(std::min(1.0, s + ds), foot_chord) - inner(std::max(0.0, s - ds), foot_chord)).normalized();
    ez_ = -coords.frame(s, foot_chord).normal;
    ex_ = ez_.cross(tangent).normalized();
    if ((centre - foot_).dot(ex_) < 0) ex_ = -ex_;
    const Vec3 across = inner(s, r.suction_chord) - inner(s, r.pressure_chord);
    Vec3 m3 = across.cross(tangent).normalized();
    if (m3.dot(ex_) < 0) m3 = -m3;
    m_ = Eigen::Vector2d(m3.dot(ex_), m3.dot(ez_)).normalized();
    const Eigen::Vector2d k(half_t_ / m_.x(), 0.0), along(1.0, 0.0), up(-m_.y(), m_.x());  // corner, wall, face
    const double theta = std::acos(std::clamp(up.x(), -1.0, 1.0));
    centre_ = k + r_ / std::sin(0.5 * theta) * (along + up).normalized();
    on_wall_ = k + r_ / std::tan(0.5 * theta) * along;
    on_face_ = k + r_ / std::tan(0.5 * theta) * up;
  }
  // Clear distance from the point to the rib and its fillet (negative inside them).
  double distance(const Vec3& p3) const {
    const Eigen::Vector2d p((p3 - foot_).dot(ex_), (p3 - foot_).dot(ez_));
    const double slab = p.dot(m_) - half_t_;
    if (r_ <= 0) return slab;
    const Eigen::Vector2d a1 = on_wall_ - centre_, a2 = on_face_ - centre_, q = p - centre_;
    auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
    const double turn = cross(a1, a2);
    const bool in_sector = cross(a1, q) * turn >= 0 && cross(q, a2) * turn >= 0;
    const double fillet = in_sector ? r_ - q.norm() : std::min((p - on_wall_).norm(), (p - on_face_).norm());
    return std::min(slab, fillet);
  }
  const Vec3& foot() const { return foot_; }

 private:
  double half_t_, r_;
  Vec3 foot_, ex_, ez_;
  Eigen::Vector2d m_, centre_, on_wall_, on_face_;
};

// The end's x next to rib r (foot_chord: the rib's chord on this wall), NaN without room: the end face
// (normal to the wall from the inner wall to `height` above it, at both corners of the `width`) keeps
// end_gap clear of the rib and its fillet (RibFootSection), measured at 9 heights on each corner's line.
// Measured on the centre line only, an end came up to ~0.03 mm into the rib (data/repro/
// turbulator_volume_mismatch.json: the fuse then added less than the independent volume, which counts
// the whole block above the wall, and the volume check failed on every retry).
double turbulator_end(const WallDevelopment& wd, const RibDefinition& r, double foot_chord, double s, double cot_a, double sin_a,
                      const TurbulatorDefinition& td, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                      const OffsetWall& wall) {
  const RibFootSection rib(r, s, foot_chord, wd.centre, coords, def);
  auto gap = [&](double x) {
    double g = HUGE_VAL;
    for (double side : {-0.5, 0.5}) {
      const Eigen::Vector2d uv = wd.params(x, x * cot_a + side * td.width / sin_a);
      const Vec3 bottom = wall.point(uv.x(), uv.y(), wd.t), top = wall.point(uv.x(), uv.y(), wd.t + td.height);
      for (int k = 0; k <= 8; ++k) g = std::min(g, rib.distance(bottom + (top - bottom) * (k / 8.0)) - td.end_gap);
    }
    return g;
  };
  // The development is linear in (u, v) at the centre, so its x is not the distance along the wall: far
  // from the centre the developed line can reach the rib before or after the foot's x. Bracket the end
  // by steps of a sixteenth of the way to the foot, out to twice as far.
  const double step = (rib.foot() - wd.centre).dot(wd.e1) / 16;
  if (gap(0.0) <= 0) return std::nan("");
  for (int j = 1; j <= 32; ++j)
    if (gap(j * step) <= 0) return bisect(gap, (j - 1) * step, j * step, 40);
  return std::nan("");
}

// 13 x 3 grid between the ends xa, xb (centre xm): top at depth t + e, bottom at depth t / 2.
RuledBlock turbulator_block(const WallDevelopment& wd, double xa, double xb, double xm, double cot_a, double sin_a,
                            const TurbulatorDefinition& td, const OffsetWall& wall) {
  const double t = wd.t;
  const int nx = 13, ny = 3;
  std::vector<double> px(nx), py{0.0, 0.5, 1.0};
  for (int a = 0; a < nx; ++a) px[a] = static_cast<double>(a) / (nx - 1);
  std::vector<BSplineCurve<3>> top_rows, bottom_rows;
  for (int b = 0; b < ny; ++b) {
    PointList<3> top, bottom;
    for (int a = 0; a < nx; ++a) {
      const double x = xa + (xb - xa) * px[a];
      const double y = (x - xm) * cot_a + (py[b] - 0.5) * td.width / sin_a;
      const Eigen::Vector2d uv = wd.params(x, y);
      top.push_back(wall.point(uv.x(), uv.y(), t + td.height));
      bottom.push_back(wall.point(uv.x(), uv.y(), 0.5 * t));
    }
    const std::vector<double> knots = averaged_knots(px, 3);
    top_rows.push_back(interpolate<3>(top, 3, px, knots));
    bottom_rows.push_back(interpolate<3>(bottom, 3, px, knots));
  }
  SkinOptions so;
  so.degree_v = 2;
  so.v_params = py;
  return RuledBlock{skin(bottom_rows, so).surface, skin(top_rows, so).surface};
}

// One turbulator `name` of definition i on `side` at span s (other_height: that of the opposite
// wall's turbulators, 0 without): its ends, block, height check, tool and info in `out`.
void build_turbulator(const std::string& name, std::size_t i, const TurbulatorDefinition& td, const WallSide& side, double s,
                      double other_height, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                      const OffsetWall& wall, WallLines& lines, TurbulatorOutput output, TurbulatorBuild& out) {
  const std::size_t k = static_cast<std::size_t>(td.chamber);  // ribs k-2 (LE side) and k-1 (TE side)
  const RibDefinition& ra = def.ribs[k - 2];
  const RibDefinition& rb = def.ribs[k - 1];
  const double sin_a = std::sin(td.angle_deg * kPi / 180), cot_a = std::cos(td.angle_deg * kPi / 180) / sin_a;
  const WallDevelopment wd = develop_wall(coords, def, wall, side, s);
  const double t = wd.t;
  const double xa = turbulator_end(wd, ra, side.chord_from, s, cot_a, sin_a, td, coords, def, wall);
  const double xb = turbulator_end(wd, rb, side.chord_to, s, cot_a, sin_a, td, coords, def, wall);
  if (std::isnan(xa) || std::isnan(xb))
    throw PassageInputError(field(i, "end_gap"), name + ": no room between the rib fillets at span " + format_number(s));
  if (!(xb - xa > td.width))
    throw PassageInputError(field(i, "end_gap"), name + ": no room between the rib fillets at span " + format_number(s));
  const double xm = 0.5 * (xa + xb);
  // Taller than the chamber: the clear height above the top, from its centre line, must leave room
  // for the opposite wall's turbulators and 0.1 mm.
  for (double x : {xa, xm, xb}) {
    const Eigen::Vector2d uv = wd.params(x, (x - xm) * cot_a);
    const Vec3 top = wall.point(uv.x(), uv.y(), t + td.height);
    const Vec3 far = top - 50.0 * wall.normal(uv.x(), uv.y());
    const std::vector<double> hits = lines.inner_crossings(top, far);
    const double clear = hits.empty() ? 0.0 : 50.0 * hits.front();
    if (hits.empty() || clear < other_height + 0.1)
      throw PassageInputError(field(i, "height"),
                              name + " is taller than its chamber at span " + format_number(s) + ": " + format_number(clear + td.height) +
                                  " mm from the wall to the opposite wall, the turbulators need " +
                                  format_number(td.height + other_height) + " mm and 0.1 mm clear; height must be < " +
                                  format_limit(0.5 * (clear + td.height - 0.1), Allowed::below) + " mm here");
  }
  TurbulatorInfo info;
  info.name = name;
  info.chamber = td.chamber;
  info.definition = static_cast<int>(i);
  info.suction = side.suction;
  info.span = s;
  info.centre = wall.point(wd.fc.u, wd.fc.v, t + td.height);
  info.normal = wd.nrm;
  info.height = td.height;
  info.width = td.width;
  info.length = (xb - xa) / sin_a;
  if (output == TurbulatorOutput::kPlacement) {
    out.turbulators.push_back(info);
    return;
  }
  RuledBlock block = turbulator_block(wd, xa, xb, xm, cot_a, sin_a, td, wall);
  const BlockIntegral vi = integrate_block(block, lines, Region::Material, Region::Chamber, Region::Chamber);
  if (!vi.ok)
    throw PassageInputError(field(i, "height"), name + " does not stand on the chamber wall as placed (its top "
                                                       "leaves the chamber); reduce the height or move it");
  FeatureTool tool;
  tool.feature = name;
  tool.shape = ruled_block_solid(block, name);
  tool.expected_volume = vi.in_region;
  info.added_volume = vi.in_region;
  out.turbulators.push_back(info);
  out.tools.push_back(std::move(tool));
}

}  // namespace

TurbulatorBuild build_turbulators(const blade::BladeModel& model, const CoreDefinition& def, const CoreBuild& core,
                                  WallLines& lines, TurbulatorOutput output) {
  check_turbulator_definitions(def);
  TurbulatorBuild out;
  if (def.turbulators.empty()) return out;
  const blade::BladeCoordinates coords(model);
  const OffsetWall wall(coords);
  const EndWall hub = core.hub_floor ? *core.hub_floor : EndWall(model, SpanEnd::Hub, 0.0);
  const EndWall tip = core.tip_cap ? *core.tip_cap : EndWall(model, SpanEnd::Tip, 0.0);

  for (std::size_t i = 0; i < def.turbulators.size(); ++i) {
    const TurbulatorDefinition& td = def.turbulators[i];
    const std::size_t k = static_cast<std::size_t>(td.chamber);  // ribs k-2 (LE side) and k-1 (TE side)
    const RibDefinition& ra = def.ribs[k - 2];
    const RibDefinition& rb = def.ribs[k - 1];
    std::vector<WallSide> sides;
    if (td.walls != TurbulatorWalls::Pressure) sides.push_back({true, ra.suction_chord, rb.suction_chord, &ra, &rb});
    if (td.walls != TurbulatorWalls::Suction) sides.push_back({false, ra.pressure_chord, rb.pressure_chord, &ra, &rb});
    const RowSpans spans = turbulator_spans(i, td, sides.front(), ra, rb, coords, def, hub, tip);
    int number = 0;
    for (const WallSide& side : sides) {
      const bool shifted = td.staggered && !side.suction && sides.size() == 2;
      const double other_height = sides.size() == 2 ? td.height : 0.0;
      for (double s : shifted ? spans.shifted_spans : spans.inline_spans)
        build_turbulator("turbulator_" + std::to_string(td.chamber) + "_" + number3(++number), i, td, side, s, other_height,
                         coords, def, wall, lines, output, out);
    }
  }
  return out;
}

}  // namespace cg::features
