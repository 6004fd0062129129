#include "src/blade/section.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/analyze/arc_length.hpp"
#include "src/blade/chordwise.hpp"
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
    SectionProfile s = make_profile(curve, d.le_param, d.te_param);
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
    if (a_is_suction || attempt == 1) return s;
    std::reverse(pts.begin(), pts.end());
    if (le_index >= 0) le_index = n - 1 - le_index, te_index = n - 1 - te_index;
  }
  throw AlgorithmFailure(what + ": orientation could not be fixed");  // unreachable: attempt 1 returns
}

}  // namespace cg::blade
