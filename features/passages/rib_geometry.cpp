#include "features/passages/rib_geometry.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

#include "adaptors/occt_convert.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/error.hpp"
#include "src/core/newton.hpp"
#include "src/fit/interpolate.hpp"
#include "src/fit/skin.hpp"

namespace cg::features {
namespace {


using Vec3 = Eigen::Vector3d;


// Rational quadratic arc c + r (cos t u + sin t v), t from t0 to t1 (t1 - t0 < pi; u, v orthonormal):
// The NURBS Book 7.5 (middle pole on the bisector at r / cos(sweep / 2), weight cos(sweep / 2)).
BSplineCurve<3> arc(const Vec3& c, const Vec3& u, const Vec3& v, double r, double t0, double t1) {
  const double h = 0.5 * (t1 - t0), m = 0.5 * (t0 + t1);
  auto dir = [&](double t) { return Vec3(std::cos(t) * u + std::sin(t) * v); };
  return BSplineCurve<3>(2, {0, 0, 0, 1, 1, 1}, {c + r * dir(t0), c + (r / std::cos(h)) * dir(m), c + r * dir(t1)},
                         {1.0, std::cos(h), 1.0});
}

BSplineCurve<3> quarter(const Vec3& c, const Vec3& u, const Vec3& v, double r) { return arc(c, u, v, r, 0, 0.5 * kPi); }

// A full round is split into two arcs at 115 degrees, not at its apex: the turnaround's naming sheet
// (the rib's mid-surface) passes through the apex, and an edge there gave sliver faces.
constexpr double kFullRoundSplit = 115.0 * kPi / 180.0;

BSplineCurve<3> segment(const Vec3& a, const Vec3& b) { return BSplineCurve<3>(1, {0, 0, 1, 1}, {a, b}); }

// One profile piece per station, skinned into one face per piece.
struct Piece {
  std::string name;
  std::vector<BSplineCurve<3>> stations;
};

}  // namespace

// ---------------------------------------------------------------------------------------------------

RibMidSurface::RibMidSurface(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                             const RibDefinition& rib)
    : coords_(&coords), wall_(&wall), rib_(rib) {
  Vec3 n, t;
  sign_ = 1;
  frame(0.5, 0.5, n, t);
  const Vec3 le_to_te = coords.frame(0.5, 1.0).point - coords.frame(0.5, 0.0).point;
  if (n.dot(le_to_te) < 0) sign_ = -1;
}

Vec3 RibMidSurface::suction_point(double span) const {
  return blade::inner_wall_point(*coords_, *wall_, span, rib_.suction_chord);
}
Vec3 RibMidSurface::pressure_point(double span) const {
  return blade::inner_wall_point(*coords_, *wall_, span, rib_.pressure_chord);
}
Vec3 RibMidSurface::point(double a, double span) const {
  const Vec3 A = suction_point(span), B = pressure_point(span);
  return A + a * (B - A);
}

namespace {
// Central difference of f over the span, one-sided at the blade surface's span ends.
template <class F>
Vec3 span_derivative(const blade::BladeCoordinates& c, double s, F f) {
  const double lo = c.model().surface.first_v(), hi = c.model().surface.last_v(), h = 1e-6;
  const double a = std::max(s - h, lo), b = std::min(s + h, hi);
  return (f(b) - f(a)) / (b - a);
}
}  // namespace

void RibMidSurface::frame(double a, double span, Vec3& normal, Vec3& span_tangent) const {
  const Vec3 A = suction_point(span), B = pressure_point(span);
  const Vec3 Ms = span_derivative(*coords_, span, [&](double s) { return point(a, s); });
  normal = (sign_ * Ms.cross(B - A)).normalized();
  span_tangent = (Ms - Ms.dot(normal) * normal).normalized();
}

double RibMidSurface::span_scale(double a, double span) const {
  return span_derivative(*coords_, span, [&](double s) { return point(a, s); }).norm();
}

// ---------------------------------------------------------------------------------------------------

namespace {

enum class EndKind { Through, Turnaround };

struct EndSpec {
  EndKind kind = EndKind::Through;
  double through_span = 0;
  double radius = 0;  // tip radius (through ends: half the thickness)
  double gap = 0;
  const EndWall* wall = nullptr;
};

class TubeBuilder {
 public:
  TubeBuilder(const RibMidSurface& mid, const RibDefinition& rib, int index, int turnaround, const EndSpec& hub,
              const EndSpec& tip)
      : mid_(mid), rib_(rib), index_(index), turnaround_(turnaround), hub_(hub), tip_(tip), half_(0.5 * rib.thickness) {}

  // The rounded end at the junction span s_j: pieces from P- to P+ (top, `up` = true) or from P+ to P-
  // (bottom), as exact quarter circles and a flat when the radius is below half the thickness.
  std::vector<BSplineCurve<3>> round(double a, double sj, bool up, double r) const {
    Vec3 N, T;
    mid_.frame(a, sj, N, T);
    const Vec3 M = mid_.point(a, sj);
    const Vec3 cp = M + (half_ - r) * N, cm = M - (half_ - r) * N;
    std::vector<BSplineCurve<3>> out;
    const bool flat = half_ - r > 1e-9 * half_;
    if (!flat) {  // full round about M: from -N over +-T to +N (up) or from +N over -T to -N (down)
      const Vec3 u = up ? Vec3(-N) : N, v = up ? T : Vec3(-T);
      out.push_back(arc(M, u, v, r, 0, kFullRoundSplit));
      out.push_back(arc(M, u, v, r, kFullRoundSplit, kPi));
    } else if (up) {
      out.push_back(quarter(cm, -N, T, r));
      out.push_back(segment(cm + r * T, cp + r * T));
      out.push_back(quarter(cp, T, N, r));
    } else {
      out.push_back(quarter(cp, N, -T, r));
      out.push_back(segment(cp - r * T, cm - r * T));
      out.push_back(quarter(cm, -T, -N, r));
    }
    return out;
  }

  // Closest signed distance of the rounded end to its end wall (dense samples of the exact arcs).
  double end_distance(double a, double sj, bool up, const EndSpec& e) const {
    double best = HUGE_VAL;
    for (const auto& c : round(a, sj, up, e.radius))
      for (int k = 0; k <= 96; ++k) best = std::min(best, e.wall->signed_distance(c.point(k / 96.0)));
    return best;
  }

  // Junction span of an end at station a: the through span, or the span at which the end's closest
  // distance to its wall is the gap (bisection; the distance is monotone in the junction span).
  double junction(double a, bool up, const EndSpec& e, double other) const {
    if (e.kind == EndKind::Through) return e.through_span;
    double lo = other, hi = e.through_span;  // lo: far from the wall, hi: beyond it
    if (!up) std::swap(lo, hi);
    auto f = [&](double s) { return end_distance(a, s, up, e) - e.gap; };
    const double far_side = up ? lo : hi, near_side = up ? hi : lo;
    const double f_far = f(far_side), f_near = f(near_side);
    if (f_far <= 0)
      throw InvalidGeometry("rib " + std::to_string(index_) + ": the turnaround gap " + format_number(e.gap) +
                            " mm leaves no rib (the end wall is closer than the gap even at the rib's other end)");
    if (f_near >= 0)
      throw InvalidGeometry("rib " + std::to_string(index_) + ": cannot place the turnaround end " + format_number(e.gap) +
                            " mm from its end wall within the blade");
    // f falls from the far side to the near side; to 1e-14 of the span range (~1e-12 mm).
    return newton::solve_bracketed_secant(f, far_side, near_side, f_far, f_near, 1e-14 * std::abs(hi - lo));
  }

  // Side curve M + side * (t / 2) N from the bottom junction to the top (side = -1) or from the top
  // to the bottom (side = +1), end tangents along +-T (tangent to the rounds).
  BSplineCurve<3> side(double a, double sb, double st, int sgn) const {
    const int n = 33;
    PointList<3> pts;
    std::vector<double> params;
    for (int k = 0; k < n; ++k) {
      const double s = sgn < 0 ? sb + (st - sb) * k / (n - 1) : st - (st - sb) * k / (n - 1);
      Vec3 N, T;
      mid_.frame(a, s, N, T);
      pts.push_back(mid_.point(a, s) + sgn * half_ * N);
      params.push_back(static_cast<double>(k) / (n - 1));
    }
    auto tangent = [&](double s) {
      Vec3 N, T;
      mid_.frame(a, s, N, T);
      // |d/ds (M + side (t/2) N)| by a difference of the side points.
      const double h = 1e-5;
      Vec3 N2, T2;
      mid_.frame(a, s + h, N2, T2);
      const double speed = ((mid_.point(a, s + h) + sgn * half_ * N2) - (mid_.point(a, s) + sgn * half_ * N)).norm() / h;
      return Vec3(speed * (st - sb) * T);
    };
    const Vec3 d_bottom = tangent(sb), d_top = tangent(st);
    const Vec3 d0 = sgn < 0 ? d_bottom : Vec3(-d_top), dn = sgn < 0 ? d_top : Vec3(-d_bottom);
    return interpolate_end_derivatives<3>(pts, d0, dn, 3, params, averaged_knots_end_derivatives(params, 3));
  }

  struct Profile {
    double sb, st;
    std::vector<BSplineCurve<3>> pieces;  // side-, top round..., side+, bottom round...
  };

  // The junction spans (bottom, top) at station a. Each turnaround end is placed against the other
  // end's junction (a through end's span, or the mid-span when both ends turn: a rib needs at least one
  // through end, checked by the caller).
  std::pair<double, double> junctions(double a) const {
    const double sb = junction(a, false, hub_, tip_.kind == EndKind::Through ? tip_.through_span : 0.5);
    const double st = junction(a, true, tip_, sb);
    if (!(st > sb)) throw InvalidGeometry("rib " + std::to_string(index_) + ": its ends overlap");
    return {sb, st};
  }

  Profile profile(double a) const {
    Profile p;
    std::tie(p.sb, p.st) = junctions(a);
    p.pieces.push_back(side(a, p.sb, p.st, -1));
    for (auto& c : round(a, p.st, true, tip_.radius)) p.pieces.push_back(std::move(c));
    p.pieces.push_back(side(a, p.sb, p.st, +1));
    for (auto& c : round(a, p.sb, false, hub_.radius)) p.pieces.push_back(std::move(c));
    return p;
  }

  std::vector<std::string> piece_names() const {
    std::vector<std::string> names;
    const std::string rib = "rib_" + std::to_string(index_);
    auto end_name = [&](const EndSpec& e) {
      return e.kind == EndKind::Turnaround ? "turnaround_" + std::to_string(turnaround_) : rib + "_end";
    };
    const bool tip_flat = half_ - tip_.radius > 1e-9 * half_, hub_flat = half_ - hub_.radius > 1e-9 * half_;
    names.push_back(rib);
    for (int k = 0; k < (tip_flat ? 3 : 2); ++k) names.push_back(end_name(tip_));
    names.push_back(rib);
    for (int k = 0; k < (hub_flat ? 3 : 2); ++k) names.push_back(end_name(hub_));
    return names;
  }

  const EndSpec& hub() const { return hub_; }
  const EndSpec& tip() const { return tip_; }

 private:
  const RibMidSurface& mid_;
  RibDefinition rib_;
  int index_, turnaround_;
  EndSpec hub_, tip_;
  double half_;
};

BSplineSurface<3> skin_stations(const std::vector<BSplineCurve<3>>& curves, const std::vector<double>& stations) {
  SkinOptions o;
  o.degree_v = 3;
  o.v_params = stations;
  return skin(curves, o).surface;
}

TopoDS_Face face_of(const BSplineSurface<3>& s) {
  BRepBuilderAPI_MakeFace mk(occt::to_occt(s), Precision::Confusion());
  if (!mk.IsDone()) throw AlgorithmFailure("rib: cannot make a face of a rib surface");
  return mk.Face();
}

// Midway between stations: exact profile points against the skinned pieces (the largest distance).
double station_error(const TubeBuilder& tb, const std::vector<double>& st, const std::vector<BSplineSurface<3>>& surf) {
  double worst = 0;
  for (std::size_t k = 0; k + 1 < st.size(); ++k) {
    const double am = 0.5 * (st[k] + st[k + 1]);
    const TubeBuilder::Profile e = tb.profile(am);
    for (std::size_t p = 0; p < surf.size(); ++p) {
      SurfaceProjector proj(surf[p]);
      for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const BSplineCurve<3>& c = e.pieces[p];
        const double u = c.first_param() + t * (c.last_param() - c.first_param());
        worst = std::max(worst, proj.project(c.point(u)).distance);
      }
    }
  }
  return worst;
}

// The open ends must lie outside the core: farther than t from no wall point, i.e. within the wall.
// True when an end still lies inside the core (the extent must grow).
bool ends_inside_core(const TubeBuilder& tb, const std::vector<double>& st, const blade::BladeCoordinates& coords,
                      const blade::ThicknessField& wall) {
  bool refine = false;
  for (double a : {st.front(), st.back()}) {
    const TubeBuilder::Profile e = tb.profile(a);
    for (const auto& c : e.pieces)
      for (double t : {0.0, 0.5}) {
        const Eigen::Vector3d p = c.point(c.first_param() + t * (c.last_param() - c.first_param()));
        const blade::BladeLocateResult r = coords.locate(p);
        if (r.found && r.coordinate.depth > wall.at(r.coordinate.span, r.coordinate.chord) * 0.999) refine = true;
      }
  }
  return refine;
}

// Faces, sewn into the open tube (out.faces, out.shell).
void sew_tube(const std::vector<BSplineSurface<3>>& surf, const std::vector<std::string>& names, const std::string& who,
              RibTube& out) {
  BRepBuilderAPI_Sewing sew(1e-6);
  std::vector<TopoDS_Face> faces;
  for (const auto& s : surf) {
    faces.push_back(face_of(s));
    sew.Add(faces.back());
  }
  sew.Perform();
  TopoDS_Shell shell;
  for (TopExp_Explorer e(sew.SewedShape(), TopAbs_SHELL); e.More(); e.Next()) shell = TopoDS::Shell(e.Current());
  if (shell.IsNull()) throw AlgorithmFailure(who + ": sewing the rib faces gave no shell");
  out.faces.clear();
  for (std::size_t p = 0; p < surf.size(); ++p) {
    const TopoDS_Shape f = sew.IsModified(faces[p]) ? sew.Modified(faces[p]) : faces[p];
    out.faces.push_back({TopoDS::Face(f), names[p]});
  }
  out.shell = shell;
}

// Turnaround sheet: the mid-surface from the rounded end's junction to past the end wall.
TopoDS_Face turnaround_sheet(const RibMidSurface& mid, const RibDefinition& rib, const RibEnds& ends,
                             const std::vector<double>& st, const std::vector<TubeBuilder::Profile>& prof) {
  const bool at_tip = rib.turnaround->end == SpanEnd::Tip;
  const double far = at_tip ? ends.tip_through_span : ends.hub_through_span;
  std::vector<BSplineCurve<3>> cs;
  for (std::size_t k = 0; k < st.size(); ++k) {
    const double s0 = at_tip ? prof[k].st : prof[k].sb;
    PointList<3> pts;
    for (int j = 0; j < 9; ++j) pts.push_back(mid.point(st[k], s0 + (far - s0) * j / 8.0));
    cs.push_back(interpolate<3>(pts, 3, ParamMethod::Uniform));
  }
  return face_of(skin_stations(cs, st));
}

}  // namespace

namespace {

// The rib's end specifications (hub, tip) from its definition and `ends`; InvalidGeometry / require
// for sizes build_rib_tube cannot take.
void end_specs(const RibDefinition& rib, const std::string& who, const RibEnds& ends, EndSpec& hub, EndSpec& tip) {
  require(rib.thickness > 0, who + ": thickness must be > 0 mm");
  require(rib.fillet_radius >= 0, who + ": fillet radius must be >= 0 mm");
  hub.through_span = ends.hub_through_span;
  tip.through_span = ends.tip_through_span;
  hub.radius = tip.radius = 0.5 * rib.thickness;
  if (!rib.turnaround) return;
  const TurnaroundDefinition& t = *rib.turnaround;
  require(t.gap > 0, who + ": turnaround gap must be > 0 mm");
  require(t.tip_radius > 0 && t.tip_radius <= 0.5 * rib.thickness * (1 + 1e-12),
          who + ": tip radius must be in (0, thickness / 2 = " + format_limit(0.5 * rib.thickness, Allowed::below) + "] mm, got " +
              format_value_limit(t.tip_radius, 0.5 * rib.thickness, Allowed::below).value);
  EndSpec& e = t.end == SpanEnd::Tip ? tip : hub;
  e.kind = EndKind::Turnaround;
  e.radius = std::min(t.tip_radius, 0.5 * rib.thickness);
  e.gap = t.gap;
  e.wall = t.end == SpanEnd::Tip ? ends.tip_wall : ends.hub_wall;
  require(e.wall != nullptr, who + ": a turnaround needs the end wall it stops short of (the end is open)");
}

// The first extent of the tube along the rib line (fraction of its length at mid-span past each wall):
// the rib's thickness, fillets and the wall, so the open ends lie outside the core.
double first_extent(const RibMidSurface& mid, const RibDefinition& rib, const blade::ThicknessField& wall,
                    const std::string& who) {
  const double len = (mid.pressure_point(0.5) - mid.suction_point(0.5)).norm();
  require(len > 0, who + ": its suction and pressure points coincide");
  return (rib.thickness + 2 * rib.fillet_radius + wall.max_value() + 0.5) / len;
}

std::vector<double> tube_stations(double ext, int n) {
  std::vector<double> st;
  for (int k = 0; k < n; ++k) st.push_back(-ext + (1 + 2 * ext) * k / (n - 1));
  return st;
}

constexpr int kFirstStations = 7;

}  // namespace

std::vector<std::pair<double, double>> check_rib_ends(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                                                      const RibDefinition& rib, int index, const RibEnds& ends) {
  const std::string who = "rib " + std::to_string(index);
  const RibMidSurface mid(coords, wall, rib);
  EndSpec hub, tip;
  end_specs(rib, who, ends, hub, tip);
  const TubeBuilder tb(mid, rib, index, 0, hub, tip);
  std::vector<std::pair<double, double>> junctions;
  for (double a : tube_stations(first_extent(mid, rib, wall, who), kFirstStations)) {
    junctions.push_back(tb.junctions(a));
  }
  return junctions;
}

RibTube build_rib_tube(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                       const RibDefinition& rib, int index, int turnaround_index, const RibEnds& ends,
                       double tolerance) {
  const std::string who = "rib " + std::to_string(index);
  const RibMidSurface mid(coords, wall, rib);
  EndSpec hub, tip;
  end_specs(rib, who, ends, hub, tip);
  const TubeBuilder tb(mid, rib, index, turnaround_index, hub, tip);

  // Extent along the rib line: past both inner walls by the rib's thickness, fillets and the wall, so
  // the open ends lie outside the core (checked below, extended if not).
  double ext = first_extent(mid, rib, wall, who);
  RibTube out;
  out.index = index;
  out.turnaround = rib.turnaround ? turnaround_index : 0;

  for (int attempt = 0;; ++attempt) {
    bool refine = false;
    for (int n = kFirstStations; n <= 49; n = 2 * n - 1) {
      const std::vector<double> st = tube_stations(ext, n);
      std::vector<TubeBuilder::Profile> prof;
      for (double a : st) prof.push_back(tb.profile(a));
      const std::size_t np = prof[0].pieces.size();
      std::vector<BSplineSurface<3>> surf;
      for (std::size_t p = 0; p < np; ++p) {
        std::vector<BSplineCurve<3>> cs;
        for (const auto& pr : prof) cs.push_back(pr.pieces[p]);
        surf.push_back(skin_stations(cs, st));
      }
      // Midway between stations: exact profile points against the skinned pieces.
      const double worst = station_error(tb, st, surf);
      out.max_station_error = worst;
      if (worst > tolerance && n < 49) continue;
      if (worst > tolerance)
        throw AlgorithmFailure(who + ": the skinned rib surfaces stay " + format_number(worst) + " mm from the exact rib (tolerance " +
                               format_number(tolerance) + " mm)");
      // The open ends must lie outside the core: farther than t from no wall point, i.e. within the wall.
      refine = ends_inside_core(tb, st, coords, wall);
      if (refine) break;
      // Faces, sewn into the open tube.
      const std::vector<std::string> names = tb.piece_names();
      require(names.size() == np, who + ": internal piece count mismatch");
      sew_tube(surf, names, who, out);
      out.a_min = st.front();
      out.a_max = st.back();
      out.stations = st;
      for (const auto& pr : prof) {
        out.hub_junction.push_back(pr.sb);
        out.tip_junction.push_back(pr.st);
      }
      if (rib.turnaround) out.turnaround_sheet = turnaround_sheet(mid, rib, ends, st, prof);
      return out;
    }
    if (!refine || attempt >= 4)
      throw AlgorithmFailure(who + ": cannot extend the rib's ends outside the core");
    ext *= 1.6;
  }
}

}  // namespace cg::features
