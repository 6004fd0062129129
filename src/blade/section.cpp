#include "src/blade/section.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/analyze/arc_length.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/blade/camber_edges.hpp"
#include "src/blade/chordwise.hpp"
#include "src/blade/edge_arcs.hpp"
#include "src/core/format.hpp"
#include "src/blade/curve_integral.hpp"
#include "src/blade/leading_edge.hpp"
#include "src/blade/periodic_seam.hpp"
#include "src/blade/planar_polyline.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade {
namespace {

void require_simple_polygon(const std::vector<Eigen::Vector2d>& pts, const std::string& what) {
  int a = 0, b = 0;
  if (!detail::polygon_is_simple(pts, a, b))
    throw InvalidGeometry(what + ": the section outline intersects itself (edges " + std::to_string(a) + " and " +
                          std::to_string(b) + ")");
}

// The profile with its curve's seam moved to the LE (u = 0 is the LE, period 1) and the chord line
// from the LE to the TE.
SectionProfile make_profile(const BSplineCurve<2>& curve, double le, double te) {
  SectionProfile s;
  s.curve = detail::with_seam_at(curve, le);
  const double t = (te - le) / curve.period();
  s.le_param = 0;
  s.te_param = t - std::floor(t);
  s.le = s.curve.point(s.le_param);
  s.te = s.curve.point(s.te_param);
  s.chord_direction = (s.te - s.le).normalized();
  return s;
}

// Index of the point nearest to q.
int nearest(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& q) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    if ((pts[i] - q).squaredNorm() < (pts[best] - q).squaredNorm()) best = i;
  return static_cast<int>(best);
}

// The edge circles of the given points (edge_arcs.hpp) and, where the spline sags off one (or a hint
// asks for it), the profile rebuilt to follow it exactly.
SectionProfile with_edge_arcs(SectionProfile s, const std::vector<Eigen::Vector2d>& pts, const PointSectionDefinition& def,
                              int le_index, int te_index, const std::string& what) {
  const int n = static_cast<int>(pts.size());
  struct Edge {
    const char* name;
    detail::EdgeCircleHint hint;
    detail::EdgeCircleRun run;
    bool arc = false;
  };
  Edge edges[2] = {{"le", {def.le_radius, def.le_centre}, {}, false}, {"te", {def.te_radius, def.te_centre}, {}, false}};
  const Eigen::Vector2d ends[2] = {s.le, s.te};
  std::vector<detail::EdgeCircleRun> arcs;
  for (int e = 0; e < 2; ++e) {
    Edge& E = edges[e];
    // An edge circle is at most a quarter of the chord in radius (hints are taken as given).
    const double max_radius = E.hint.given() ? HUGE_VAL : 0.25 * s.chord();
    E.run = detail::find_edge_circle(pts, nearest(pts, ends[e]), E.hint, max_radius);
    if (!E.run.found) {
      if (E.hint.given())
        throw InvalidGeometry(what + ": " + E.name + "_radius/" + E.name + "_centre: no " +
                              (E.hint.centre ? "2" : "3") + " consecutive points at the " +
                              (e == 0 ? "leading" : "trailing") + " edge lie on that circle within " +
                              format_number(detail::kOnCircleTolerance) + " mm");
      continue;
    }
    // The sag due to sparse points alone: the same spline through the run's points moved onto the circle
    // (so scatter of the points, e.g. C3X's LE within 1.3 um of its circle, does not count), measured
    // in the middle half of the run (near its ends the spline meets the sides' curvature whatever the
    // spacing, and the wiggle this makes decays by ~3.7x per interval into the run).
    std::vector<Eigen::Vector2d> q = pts;
    for (int k = 0; k < E.run.count; ++k) {
      Eigen::Vector2d& x = q[static_cast<std::size_t>((E.run.first + k) % n)];
      x = E.run.circle.centre + E.run.circle.radius * (x - E.run.circle.centre).normalized();
    }
    const std::vector<double> t = interpolation_parameters<2>(q, ParamMethod::Centripetal, true);
    const BSplineCurve<2> plain = interpolate_closed<2>(q, 3, ParamMethod::Centripetal);
    const int inset = E.run.count / 4;  // the spline's wiggle from a junction decays ~3.7x per interval
    const double a = t[static_cast<std::size_t>((E.run.first + inset) % n)],
                 b0 = t[static_cast<std::size_t>((E.run.first + E.run.count - 1 - inset) % n)];
    const double sag = detail::deviation_from_circle(plain, a, b0 > a ? b0 : b0 + plain.period(), E.run.circle);
    E.arc = E.hint.given() || sag > detail::kArcSagTolerance;
    if (E.arc) arcs.push_back(E.run);
  }
  if (arcs.size() == 2) {
    const auto& r0 = arcs[0];
    const auto& r1 = arcs[1];
    auto inside = [&](const detail::EdgeCircleRun& r, int i) { return ((i - r.first) % n + n) % n < r.count; };
    require(!inside(r0, r1.first) && !inside(r1, r0.first),
            what + ": the leading- and trailing-edge circles share given points; give le_radius/te_radius");
  }
  if (!arcs.empty()) {
    const BSplineCurve<2> curve = detail::profile_with_arcs(pts, arcs);
    LeadingTrailingEdge d;
    if (le_index >= 0) {
      CurveProjector<2> proj(curve);
      d.le_param = proj.project(pts[static_cast<std::size_t>(le_index)]).param;
      d.te_param = proj.project(pts[static_cast<std::size_t>(te_index)]).param;
    } else {
      const LeadingTrailingEdge fitted = detect_leading_trailing_edge(curve);
      d = edge_points(curve, edges[0].run.found ? edges[0].run.circle : fitted.le_circle,
                      edges[1].run.found ? edges[1].run.circle : fitted.te_circle);
    }
    const EdgeCircle le_c = s.le_circle, te_c = s.te_circle;
    s = make_profile(curve, d.le_param, d.te_param);
    s.le_circle = le_c;
    s.te_circle = te_c;
  }
  if (edges[0].run.found) s.le_circle = edges[0].run.circle, s.le_circle_points = edges[0].run.count;
  if (edges[1].run.found) s.te_circle = edges[1].run.circle, s.te_circle_points = edges[1].run.count;
  s.le_arc = edges[0].arc;
  s.te_arc = edges[1].arc;
  return s;
}

}  // namespace

double SectionProfile::suction_length() const { return ChordwiseMap<2>(curve, le_param, te_param).suction_length(); }

double SectionProfile::pressure_length() const { return ChordwiseMap<2>(curve, le_param, te_param).pressure_length(); }

std::vector<double> SectionProfile::params_at_chordwise(const std::vector<double>& c) const {
  const ChordwiseMap<2> map(curve, le_param, te_param);
  std::vector<double> out(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) out[k] = map.param_at(c[k]);
  return out;
}

double SectionProfile::param_at_chordwise(double c) const { return ChordwiseMap<2>(curve, le_param, te_param).param_at(c); }

double SectionProfile::chordwise_at_param(double u) const {
  return ChordwiseMap<2>(curve, le_param, te_param).chordwise_at(u);
}

SectionProperties section_properties(const BSplineCurve<2>& curve, bool with_perimeter) {
  SectionProperties r;
  double a2 = 0, mx = 0, my = 0;  // 2A, integral of x dA, integral of y dA (Green's theorem)
  const auto& U = curve.knots();
  for (int i = curve.degree(); i < curve.num_poles(); ++i) {
    const double lo = U[static_cast<std::size_t>(i)], hi = U[static_cast<std::size_t>(i) + 1];
    if (hi <= lo) continue;
    // Integrands are polynomials of degree <= 3p - 1 per span for polynomial curves: 8 points are exact
    // up to cubic; rational curves get the usual Gauss accuracy.
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (int k = 0; k < 8; ++k) {
      Eigen::Vector2d d[2];
      curve.derivatives(mid + half * detail::kGaussLegendre8Nodes[k], 1, d);
      const double w = detail::kGaussLegendre8Weights[k] * half;
      a2 += w * (d[0].x() * d[1].y() - d[0].y() * d[1].x());
      mx += w * 0.5 * d[0].x() * d[0].x() * d[1].y();
      my -= w * 0.5 * d[0].y() * d[0].y() * d[1].x();
    }
  }
  r.area = 0.5 * a2;
  if (r.area != 0) r.centroid = Eigen::Vector2d(mx, my) / r.area;
  if (with_perimeter) r.perimeter = arc_length(curve);
  return r;
}

SectionProfile section_from_points(const PointSectionDefinition& def) {
  const std::string what = def.file.empty() ? std::string("point section") : "point section '" + def.file + "'";
  std::vector<Eigen::Vector2d> pts = def.points;
  if (pts.empty()) {
    require(!def.file.empty(), "point section: give either points or a file");
    pts = read_section_points(def.file, def.unit);
  }
  if (pts.size() > 1 && (pts.front() - pts.back()).norm() <= 1e-12 * (1.0 + pts.front().norm())) pts.pop_back();
  const int n = static_cast<int>(pts.size());
  require(n >= 4, what + ": needs at least 4 points, got " + std::to_string(n));
  double size = 0;
  for (const auto& p : pts) size = std::max(size, (p - pts.front()).norm());
  for (int i = 0; i < n; ++i)
    require((pts[static_cast<std::size_t>((i + 1) % n)] - pts[static_cast<std::size_t>(i)]).norm() > 1e-12 * size,
            what + ": points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide");
  require(def.le_index >= -1 && def.le_index < n && def.te_index >= -1 && def.te_index < n,
          what + ": le_index/te_index must be -1 (detect) or in [0, " + std::to_string(n - 1) + "]");
  require((def.le_index < 0) == (def.te_index < 0), what + ": give both le_index and te_index or neither");
  require(def.le_index < 0 || def.le_index != def.te_index, what + ": le_index and te_index must differ");
  require_simple_polygon(pts, what);

  int le_index = def.le_index, te_index = def.te_index;
  SectionProfile s;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const std::vector<double> params = interpolation_parameters<2>(pts, ParamMethod::Centripetal, true);
    const BSplineCurve<2> curve = interpolate_closed<2>(pts, 3, ParamMethod::Centripetal);
    LeadingTrailingEdge d;
    if (le_index >= 0) {
      try {
        d = detect_leading_trailing_edge(curve);  // for its edge circles (reported)
      } catch (const Error&) {
      }
      d.le_param = curve.check_param(params[static_cast<std::size_t>(le_index)]);
      d.te_param = curve.check_param(params[static_cast<std::size_t>(te_index)]);
    } else {
      d = detect_leading_trailing_edge(curve);
    }
    s = make_profile(curve, d.le_param, d.te_param);
    s.le_circle = d.le_circle;
    s.te_circle = d.te_circle;
    // Side A is reached from the LE with increasing u; it is the suction side or the points are reversed.
    const double la = s.suction_length(), lb = s.pressure_length();
    const bool ccw = section_properties(curve).area > 0;
    bool a_is_suction = true;
    switch (def.suction_side) {
      case SuctionSide::Longer: a_is_suction = la >= lb; break;
      case SuctionSide::CounterClockwise: a_is_suction = ccw; break;
      case SuctionSide::Clockwise: a_is_suction = !ccw; break;
    }
    if (a_is_suction || attempt == 1) break;
    std::reverse(pts.begin(), pts.end());
    if (le_index >= 0) le_index = n - 1 - le_index, te_index = n - 1 - te_index;
  }
  s = with_edge_arcs(s, pts, def, le_index, te_index, what);
  if (def.edges == EdgeRule::CamberLine && le_index < 0) {
    // The edge circles of the final curve by the 60-degree stretch (leading_edge.hpp) give each edge's
    // centre and size; the profile keeps its reported circles and arcs.
    const LeadingTrailingEdge d = camber_edge_points(s.curve, detect_leading_trailing_edge(s.curve));
    SectionProfile c = make_profile(s.curve, d.le_param, d.te_param);
    c.le_circle = s.le_circle, c.te_circle = s.te_circle;
    c.le_circle_points = s.le_circle_points, c.te_circle_points = s.te_circle_points;
    c.le_arc = s.le_arc, c.te_arc = s.te_arc;
    s = std::move(c);
  }
  return s;
}

}  // namespace cg::blade
