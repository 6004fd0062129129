#include "features/film/hole_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/algo/project_point_surface.hpp"
#include "features/film/hole_rays.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/analyze/gauss_legendre.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {


// A reference point of a diffuser piece: its position (x, y) in the section at t is linear in t.
struct PiecePoint {
  double x = 0, y = 0, jacobian = 0;
};

// The nine pieces of the rounded-rectangle section (hole_shape.hpp): 0 centre, 1 right, 2 left,
// 3 front (top), 4 back (bottom) strips, 5..8 corners by quadrant (theta from e_l towards e_f).
PiecePoint piece_point(int piece, double a, double b, const FanSection& s) {
  const double h = s.y1 - s.y0;
  switch (piece) {
    case 0: return {s.w * (2 * a - 1), s.y0 + h * b, 2 * s.w * h};
    case 1: return {s.w + s.rho * a, s.y0 + h * b, s.rho * h};
    case 2: return {-s.w - s.rho * a, s.y0 + h * b, s.rho * h};
    case 3: return {s.w * (2 * a - 1), s.y1 + s.rho * b, 2 * s.w * s.rho};
    case 4: return {s.w * (2 * a - 1), s.y0 - s.rho * b, 2 * s.w * s.rho};
    default: {
      const int q = piece - 5;
      const double cx = (q == 0 || q == 3) ? s.w : -s.w, cy = q <= 1 ? s.y1 : s.y0;
      const double th = 0.5 * kPi * (q + a);
      return {cx + s.rho * b * std::cos(th), cy + s.rho * b * std::sin(th), 0.5 * kPi * s.rho * s.rho * b};
    }
  }
}

[[noreturn]] void fail_hole(const HoleSpec& h, const std::string& sub, const std::string& what) {
  throw FilmInputError(h.field + sub, h.name + " (span " + format_number(h.span) + ", chord " + format_number(h.chord) + "): " + what);
}

}  // namespace

void check_hole_obstacle(const HoleSpec& h, HoleGeometry& g, const TargetObstacle& ob, const FilmLimits& limits) {
  double lig = HUGE_VAL;
  for (const Eigen::Vector3d& p : g.inlet_rim) lig = std::min(lig, ob.distance(p));
  double touch = lig;
  for (const Eigen::Vector3d& p : g.end_rim) touch = std::min(touch, ob.distance(p));
  const std::string& field = ob.field.empty() ? h.position_field : ob.field;
  if (ob.needs_ligament) {
    if (lig < limits.min_ligament) {
      const ValueLimitText t = format_value_limit(lig, limits.min_ligament, Allowed::above);
      fail_hole(h, field,
                (lig < 0 ? "overlaps " + ob.name + " by " + format_number(-lig) + " mm" : "comes " + t.value + " mm close to " + ob.name) +
                    " where it enters the cavity; the ligament must be at least film_limits.min_ligament = " + t.limit + " mm");
    }
    if (lig < g.obstacle_ligament) g.obstacle_ligament = lig, g.nearest_obstacle = ob.name;
  }
  if (touch <= 0) fail_hole(h, field, "its tool would cut " + ob.name);
}

void gauss_legendre_01(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  std::vector<double> x(static_cast<std::size_t>(std::max(n, 1))), w(x.size());
  gauss_legendre(n, x.data(), w.data());
  nodes.assign(n, 0);
  weights.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    nodes[n - 1 - i] = 0.5 * (1 + x[i]);  // ascending on [0, 1]
    weights[n - 1 - i] = 0.5 * w[i];
  }
}

struct HoleAnalyser::Impl {
  const HoleTarget& target;
  FilmLimits limits;
  HoleQuadrature quad;
  NearCaster outer, inner;
  blade::BladeCoordinates coords;
  SurfaceProjector projector;
  std::vector<double> rx, rw, px, pw;

  Impl(const HoleTarget& t, const FilmLimits& l, const HoleQuadrature& q)
      : target(t), limits(l), quad(q), outer(t.model->surface), inner(t.cavity_wall), coords(*t.model),
        projector(t.model->surface) {
    gauss_legendre_01(q.radial, rx, rw);
    gauss_legendre_01(q.piece, px, pw);
  }

  [[noreturn]] static void fail(const HoleSpec& h, const std::string& sub, const std::string& what) { fail_hole(h, sub, what); }

  // Chordwise coordinate of the foot of p on the outer wall (Newton from the exit's parameters, else the
  // global projection), on the section at `span` (NaN: the foot's own span). Evaluating the rim's feet on
  // the section of the axis' inlet keeps to one section per hole (a section is an iso-curve with its
  // arc-length map); the feet lie within a hole diameter of that span.
  double chord_of(const Eigen::Vector3d& p, const RaySurfaceHit& exit, double span = std::nan(""), double* foot_span = nullptr) {
    double u = exit.u, v = exit.v;
    if (foot_near(target.model->surface, p, u, v)) {
      if (foot_span) {
        // The axis' inlet decides the chamber: make sure Newton's foot is the closest point (in a thin
        // region another side of the blade can be closer): global search within its distance.
        const double dist = (target.model->surface.point(u, v) - p).norm();
        const SurfaceProjection g = projector.project(p, dist * (1 + 1e-9) + 1e-9);
        if (g.found && g.distance < dist * (1 - 1e-9) - 1e-9) u = g.u, v = g.v;
        *foot_span = v;
      }
      return coords.section(std::isnan(span) ? v : span).chordwise_at_u(u);
    }
    const blade::BladeLocateResult loc = coords.locate(p);
    if (foot_span) *foot_span = loc.v;
    return loc.found ? loc.coordinate.chord : std::nan("");
  }
  std::vector<Eigen::Vector3d> inlet_rim, exit_outline, end_rim;  // work buffers
  std::vector<double> rim_si, rim_sf;

  HoleGeometry analyse(const HoleSpec& h);
  struct Analysis;
};

HoleAnalyser::HoleAnalyser(const HoleTarget& target, const FilmLimits& limits, const HoleQuadrature& quadrature) {
  require(target.model != nullptr, "HoleAnalyser: the target has no blade model");
  require(quadrature.radial >= 2 && quadrature.angular >= 4 && quadrature.piece >= 2, "HoleAnalyser: quadrature too coarse");
  impl_ = std::make_unique<Impl>(target, limits, quadrature);
}
HoleAnalyser::~HoleAnalyser() = default;
HoleGeometry HoleAnalyser::analyse(const HoleSpec& hole) { return impl_->analyse(hole); }

// One hole's analysis: the quantities its stages pass on, named as in the stages (the analyser's
// casters, quadrature and work buffers by reference).
struct HoleAnalyser::Impl::Analysis {
  Impl& im;
  const HoleTarget& target;
  const FilmLimits& limits;
  const HoleQuadrature& quad;
  NearCaster &outer, &inner;
  const std::vector<double>&rx, &rw, &px, &pw;
  std::vector<Eigen::Vector3d>&inlet_rim, &exit_outline, &end_rim;
  std::vector<double>&rim_si, &rim_sf;
  const HoleSpec& h;
  HoleGeometry g;
  const double D, r, c;
  const Eigen::Vector3d E, d, fw, lat;
  const bool fan;
  const double s_out;  // lines start this far outside (along the axis)
  const double search;
  const std::string dsub = ".diameter";
  const Eigen::Vector3d base;
  // The axis' hits
  RaySurfaceHit ao, ai, af;
  double sense_o = 0, sense_i = 0, sense_f = 0, inlet_span = 0;
  const TargetChamber* chamber = nullptr;
  // The diffuser
  std::unique_ptr<FanProfile> prof;
  double sd = 0;
  // The lines through the metering disc
  double s_o_min = HUGE_VAL, s_i_max = -HUGE_VAL, s_i_min = HUGE_VAL, depth_n = 0, axis_far = HUGE_VAL;
  Eigen::Vector3d n_inlet;
  // The diffuser lines
  double t_c_max = 0;

  Analysis(Impl& impl, const HoleSpec& hole)
      : im(impl), target(impl.target), limits(impl.limits), quad(impl.quad), outer(impl.outer), inner(impl.inner),
        rx(impl.rx), rw(impl.rw), px(impl.px), pw(impl.pw), inlet_rim(impl.inlet_rim), exit_outline(impl.exit_outline),
        end_rim(impl.end_rim), rim_si(impl.rim_si), rim_sf(impl.rim_sf), h(hole), D(h.shape.diameter), r(0.5 * D),
        c(limits.clearance), E(h.frame.exit), d(h.frame.axis), fw(h.frame.forward), lat(h.frame.lateral()),
        fan(h.shape.kind == HoleKind::FanShaped), s_out(1.0 + 6 * D), search(s_out + 40 + 20 * D), base(E - s_out * d) {}

  void axis();
  void diffuser();
  void metering_lines();
  void diffuser_lines();
  void tool_extent();
  void inlet_and_obstacles();
  void breakout_width();
  void envelope();
};

// The axis: exit point, cavity wall, chamber (global first hits; the other lines start from these).
void HoleAnalyser::Impl::Analysis::axis() {
  ao = outer.first(base, d, search);
  if (!ao.found || std::abs(ao.ray_param - s_out) > 1e-6 * (1 + s_out))
    fail(h, h.position_field, "the hole axis meets the outer wall " + format_number(s_out - ao.ray_param) + " mm before its exit point "
                         "(the hole would cut the blade elsewhere first)");
  Eigen::Vector3d n_exit = target.model->surface.normal(ao.u, ao.v);
  if (n_exit.dot(d) > 0) n_exit = -n_exit;
  g.inclination_deg = std::asin(std::min(1.0, -n_exit.dot(d))) * 180 / kPi;
  ai = inner.first(base, d, search);
  const RaySurfaceHit ao2 = outer.first(ao.point + 1e-6 * d, d, search);
  if (ao2.found && (!ai.found || ao.ray_param + 1e-6 + ao2.ray_param < ai.ray_param))
    fail(h, h.position_field, "reaches no chamber: its axis leaves the blade again " + format_number(ao2.ray_param) +
                             " mm past its exit point, before it enters the cavity");
  if (!ai.found || ai.ray_param <= s_out)
    fail(h, h.position_field, "reaches no chamber: its axis does not enter the cavity within " + format_number(search - s_out) + " mm");
  sense_o = outer.sense(d, ao), sense_i = inner.sense(d, ai);
  af = inner.first(ai.point + 1e-6 * d, d, search);
  sense_f = af.found ? inner.sense(d, af) : 0;
  g.length = ai.ray_param - s_out;
  g.inlet = ai.point;
  g.inlet_chord = im.chord_of(ai.point, ao, std::nan(""), &inlet_span);
  g.chamber = std::isnan(g.inlet_chord) ? -1 : target.chamber_at(g.inlet_chord);
  if (g.chamber < 0)
    fail(h, h.position_field, "reaches no chamber: its axis enters the cavity at chord " + format_number(g.inlet_chord) +
                             ", which belongs to no chamber (a rib or beyond the core)");
  chamber = &target.chambers[g.chamber];
  if (h.required_chamber > 0 && chamber->number != h.required_chamber)
    fail(h, ".chamber", "feeds from " + chamber->name + ", not from chamber_" + std::to_string(h.required_chamber) +
                            " as configured");
  g.metering_area = kPi * r * r;
}

// Fan-shaped: diffuser length and profile from the local wall.
void HoleAnalyser::Impl::Analysis::diffuser() {
  if (fan) {
    const FanDiffuser& fd = h.shape.fan;
    const double ld = fd.diffuser_length_d > 0 ? fd.diffuser_length_d * D : g.length - fd.metering_length_d * D;
    if (ld <= 0)
      fail(h, ".fan.metering_length_d", "the metering length " + format_number(fd.metering_length_d * D) + " mm leaves no diffuser: the "
                                    "hole is only " + format_number(g.length) + " mm long through the wall");
    if (ld >= g.length)
      fail(h, dsub, "larger than the wall allows: its diffuser (" + format_number(ld) + " mm along the axis) is longer than the "
                    "hole through the wall (" + format_number(g.length) + " mm at inclination " + format_number(g.inclination_deg) + " deg)");
    if (h.shape.fan.edge_radius_d * D > max_edge_radius(h.shape, ld)) {
      const ValueLimitText t = format_value_limit(h.shape.fan.edge_radius_d * D, max_edge_radius(h.shape, ld), Allowed::below);
      fail(h, ".fan.edge_radius_d", "edge radius " + t.value + " mm exceeds the largest the diffuser allows, " + t.limit + " mm");
    }
    prof = std::make_unique<FanProfile>(h.shape, ld);
    sd = ld;
    g.diffuser_length = ld;
    g.metering_length = g.length - ld;
  } else {
    g.metering_length = g.length;
  }
}

// Lines parallel to the axis through the metering disc (and its rim, for outlines and obstacles).
void HoleAnalyser::Impl::Analysis::metering_lines() {
  inlet_rim.clear();
  exit_outline.clear();
  end_rim.clear();
  rim_si.clear();
  rim_sf.clear();
  n_inlet = inner.normal(ai);
  if (n_inlet.dot(d) < 0) n_inlet = -n_inlet;
  const int na = quad.angular;
  for (int k = 0; k <= quad.radial; ++k) {
    const bool rim = k == quad.radial;
    const double rho = rim ? r : r * rx[k];
    for (int j = 0; j < na; ++j) {
      const double th = 2 * kPi * j / na;
      const Eigen::Vector3d o = base + rho * (std::cos(th) * lat + std::sin(th) * fw);
      const RaySurfaceHit ho = outer.near(o, d, ao, sense_o, 0, search, search);
      const RaySurfaceHit hi = inner.near(o, d, ai, sense_i, 0, search, search);
      if (!ho.found || !hi.found || hi.ray_param <= ho.ray_param)
        fail(h, h.position_field, "does not cross the wall cleanly into the cavity (a line of the hole at " + format_number(rho) +
                                 " mm from the axis misses the outer or the cavity wall)");
      const double so = ho.ray_param - s_out, si = hi.ray_param - s_out;
      if (fan && so >= sd)
        fail(h, ".fan.diffuser_length_d", "the metering part breaks out of the outer wall: the diffuser (" + format_number(sd) +
                                          " mm) is too short for the inclination and the wall curvature");
      if (fan && si <= sd)
        fail(h, dsub, "larger than the wall allows: the diffuser reaches the cavity");
      s_o_min = std::min(s_o_min, so);
      s_i_max = std::max(s_i_max, si);
      s_i_min = std::min(s_i_min, si);
      depth_n = std::max(depth_n, (hi.point - ai.point).dot(n_inlet));
      if (rim) {
        double sf = HUGE_VAL;
        if (af.found) {
          const RaySurfaceHit hf = inner.near(o, d, af, sense_f, hi.ray_param + 1e-9, search, search);
          if (hf.found && hf.ray_param > hi.ray_param) sf = hf.ray_param - s_out;
        }
        inlet_rim.push_back(hi.point);
        if (!fan) exit_outline.push_back(ho.point);
        end_rim.push_back(o);  // moved to the tool end below
        rim_si.push_back(si);
        rim_sf.push_back(sf);
        continue;
      }
      const double w = r * r * rx[k] * rw[k] * 2 * kPi / na;
      g.expected_volume += w * (si - (fan ? sd : so));
      if (!fan) {
        const Eigen::Vector3d n = target.model->surface.normal(ho.u, ho.v);
        g.footprint_area += w / std::abs(n.dot(d));
      }
    }
  }
  axis_far = af.found ? ai.ray_param + 1e-6 + af.ray_param - s_out : HUGE_VAL;
}

// Diffuser lines: every reference point of every piece moves on a straight line as t grows.
void HoleAnalyser::Impl::Analysis::diffuser_lines() {
  if (fan) {
    const double t_far = sd + s_out;
    auto line = [&](int piece, double a, double b, double& t_c, Eigen::Vector3d& v, RaySurfaceHit& hit) {
      const PiecePoint p0 = piece_point(piece, a, b, prof->at(0)), p1 = piece_point(piece, a, b, prof->at(1));
      v = d - (p1.x - p0.x) * lat - (p1.y - p0.y) * fw;  // towards growing s, unit axial component
      const Eigen::Vector3d origin = E + (sd - t_far) * d + (p0.x + t_far * (p1.x - p0.x)) * lat +
                                     (p0.y + t_far * (p1.y - p0.y)) * fw;
      const double vn = v.norm();
      hit = outer.near(origin, v / vn, ao, sense_o, 0, search * vn, search * vn);
      if (!hit.found) fail(h, h.position_field, "a diffuser line misses the outer wall");
      t_c = t_far - hit.ray_param / vn;
      if (t_c <= 0)
        fail(h, ".fan.diffuser_length_d", "the metering part breaks out of the outer wall: the diffuser (" + format_number(sd) +
                                          " mm) is too short for the inclination and the wall curvature");
      // Only a cavity crossing within the diffuser (ray parameter <= t_far vn) matters: the global search, where
      // Newton does not settle, looks no further.
      const RaySurfaceHit hi = inner.near(origin, v / vn, ai, sense_i, 0, search * vn, t_far * vn);
      if (hi.found && t_far - hi.ray_param / vn >= 0) fail(h, dsub, "larger than the wall allows: the diffuser reaches the cavity");
    };
    const double g1 = 0.5 - 0.5 / std::sqrt(3.0), g2 = 0.5 + 0.5 / std::sqrt(3.0);
    for (int piece = 0; piece < 9; ++piece) {
      if (piece_point(piece, 0.5, 0.5, prof->at(1)).jacobian <= 0) continue;  // degenerate (no expansion)
      for (int i = 0; i < quad.piece; ++i)
        for (int j = 0; j < quad.piece; ++j) {
          double t_c;
          Eigen::Vector3d v;
          RaySurfaceHit hit;
          line(piece, px[i], px[j], t_c, v, hit);
          t_c_max = std::max(t_c_max, t_c);
          const double w = pw[i] * pw[j];
          const double jint = 0.5 * t_c * (piece_point(piece, px[i], px[j], prof->at(g1 * t_c)).jacobian +
                                           piece_point(piece, px[i], px[j], prof->at(g2 * t_c)).jacobian);
          g.expected_volume += w * jint;
          const Eigen::Vector3d n = target.model->surface.normal(hit.u, hit.v);
          g.footprint_area += w * piece_point(piece, px[i], px[j], prof->at(t_c)).jacobian / std::abs(n.dot(v));
        }
    }
    // The section's outline: corner arcs and the straight sides' mid points.
    for (int q = 0; q < 4; ++q) {
      for (int k = 0; k < 4; ++k) {
        double t_c;
        Eigen::Vector3d v;
        RaySurfaceHit hit;
        line(5 + q, 0.25 * k, 1.0, t_c, v, hit);
        t_c_max = std::max(t_c_max, t_c);
        exit_outline.push_back(hit.point);
      }
      const int side[4] = {1, 3, 2, 4};
      double t_c;
      Eigen::Vector3d v;
      RaySurfaceHit hit;
      line(side[q], side[q] <= 2 ? 1.0 : 0.5, side[q] <= 2 ? 0.5 : 1.0, t_c, v, hit);
      t_c_max = std::max(t_c_max, t_c);
      exit_outline.push_back(hit.point);
    }
    const double ls = area_ratio_station(h.shape, sd, g.inclination_deg);
    g.exit_area = prof->at(ls > 0 ? ls : sd).area();
  } else {
    g.exit_area = g.metering_area;
  }
}

// Tool extent: clear of the outer wall; the end a plane normal to the axis `clearance` past the last
// line's inlet. Where the far side of the cavity is closer than that (a hole entering at a shallow
// angle, e.g. a showerhead hole angled to the span), or a line would reach further into the chamber
// than it allows (an insert behind a narrow gap), the end plane follows the cavity wall instead: its
// normal is the wall's normal at the axis' inlet, placed `clearance` (along the lines) past every inlet.
void HoleAnalyser::Impl::Analysis::tool_extent() {
  g.extent.s_top = fan ? sd - (t_c_max + c) : s_o_min - c;
  g.extent.s_diffuser = sd;
  g.extent.diffuser_length = sd;
  const std::size_t nr = end_rim.size();
  std::vector<double> s_end_rim(nr, s_i_max + c);
  g.extent.s_end = s_i_max + c;
  const double cos_t = n_inlet.dot(d);
  bool clear = axis_far >= g.extent.s_end + c;
  for (std::size_t q = 0; q < nr; ++q) clear = clear && rim_sf[q] >= s_end_rim[q] + c;
  // A normal end reaching past the chamber's allowance: the wall-following end unless the hole grazes
  // the wall (then the reach below is the refusal, naming what to change).
  if (cos_t >= 0.2)
    for (std::size_t q = 0; q < nr; ++q) clear = clear && s_end_rim[q] - rim_si[q] <= chamber->reach;
  if (!clear) {
    if (cos_t < 0.2)
      fail(h, h.position_field, "enters the cavity at a grazing angle (" + format_number(std::acos(cos_t) * 180 / kPi) +
                               " deg from the wall's normal)");
    const double delta = depth_n + c * cos_t;
    auto plane_s = [&](const Eigen::Vector3d& o) { return (delta - (o - ai.point).dot(n_inlet)) / cos_t - s_out; };
    g.extent.s_end = plane_s(base);
    g.extent.end_normal = n_inlet;
    // The tool keeps what lies before that plane: a plane before the tool's start keeps nothing.
    if (g.extent.s_end <= g.extent.s_top + c)
      fail(h, h.position_field, "does not fit here: the cavity wall its axis enters lies across the hole's own start (" +
                                    format_number(g.extent.s_end - g.extent.s_top) + " mm along the axis; the wall is too thin "
                                    "or too curved here for this inclination)");
    double worst = axis_far - g.extent.s_end;
    for (std::size_t q = 0; q < nr; ++q) {
      s_end_rim[q] = plane_s(end_rim[q]);
      worst = std::min(worst, rim_sf[q] - s_end_rim[q]);
    }
    if (worst < c)
      fail(h, h.position_field, "the cavity behind the hole is too narrow: its tool must cross the cavity wall by " + format_number(c) +
                               " mm and stay " + format_number(c) + " mm from the far wall (" + format_number(worst) + " mm left)");
    if (fan && g.extent.s_end - r * std::sqrt(1 - cos_t * cos_t) / cos_t <= sd)
      fail(h, dsub, "larger than the wall allows: the diffuser reaches the cavity");
  }
  double reach = 0;
  for (std::size_t q = 0; q < nr; ++q) {
    reach = std::max(reach, s_end_rim[q] - rim_si[q]);
    end_rim[q] += (s_out + s_end_rim[q]) * d;
  }
  if (reach > chamber->reach) {
    const ValueLimitText t = format_value_limit(reach, chamber->reach, Allowed::below);
    fail(h, h.position_field, "its tool would reach " + t.value + " mm into " + chamber->name + ", which allows " + t.limit +
                             " mm (an insert lies behind the gap)");
  }
}

// Chamber of the whole inlet, obstacles.
void HoleAnalyser::Impl::Analysis::inlet_and_obstacles() {
  for (const Eigen::Vector3d& p : inlet_rim) {
    const double ch = im.chord_of(p, ao, inlet_span);
    const int k = std::isnan(ch) ? -1 : target.chamber_at(ch);
    if (k != g.chamber)
      fail(h, h.position_field, "its inlet straddles " + chamber->name + " and " +
                               (k < 0 ? std::string("no chamber (a rib)") : target.chambers[k].name));
  }
  g.inlet_rim = inlet_rim;
  g.end_rim = end_rim;
  for (const TargetObstacle& ob : target.obstacles) check_hole_obstacle(h, g, ob, limits);
}

// Breakout width along the row: extent of the outline; on the cylinder's evenly spaced rim the extreme
// values are refined by a parabola through the extreme sample and its neighbours.
void HoleAnalyser::Impl::Analysis::breakout_width() {
  std::vector<double> xs;
  for (const Eigen::Vector3d& p : exit_outline) xs.push_back((p - E).dot(h.row_direction));
  auto extreme = [&](double sign) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < xs.size(); ++i)
      if (sign * xs[i] > sign * xs[k]) k = i;
    if (fan) return xs[k];
    const double a = xs[(k + xs.size() - 1) % xs.size()], b = xs[k], cc = xs[(k + 1) % xs.size()];
    const double den = a - 2 * b + cc;
    return std::abs(den) > 1e-300 ? b - 0.125 * (cc - a) * (cc - a) / den : b;
  };
  g.breakout_width = extreme(1) - extreme(-1);
}

// Envelope between the outer and the cavity wall (balls along the axis).
void HoleAnalyser::Impl::Analysis::envelope() {
  const double s_lo = fan ? sd - t_c_max : s_o_min, s_hi = s_i_max;
  const int ns = std::min(80, 2 + static_cast<int>(std::ceil((s_hi - s_lo) / (0.5 * r))));
  for (int k = 0; k < ns; ++k) {
    const double s = s_lo + (s_hi - s_lo) * k / (ns - 1);
    double radius = r;
    if (fan && s < sd) {
      const FanSection sec = prof->at(sd - s);
      radius = std::hypot(sec.w, std::max(std::abs(sec.y0), std::abs(sec.y1))) + sec.rho;
    }
    g.envelope_points.push_back(E + s * d);
    g.envelope_radii.push_back(radius);
  }
}

HoleGeometry HoleAnalyser::Impl::analyse(const HoleSpec& h) {
  Analysis a(*this, h);
  a.axis();
  a.diffuser();
  a.metering_lines();
  a.diffuser_lines();
  a.tool_extent();
  a.inlet_and_obstacles();
  a.breakout_width();
  a.envelope();
  return std::move(a.g);
}

}  // namespace cg::features
