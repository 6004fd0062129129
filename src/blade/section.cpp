#include "src/blade/section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/blade/curve_integral.hpp"
#include "src/blade/planar_polyline.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade {
namespace {

using detail::CurveIntegral;
using detail::Integrand;

constexpr double kGaussNodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                   0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
constexpr double kGaussWeights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                     0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

double suction_end(const SectionProfile& s) {
  double te = s.te_param;
  while (te <= s.le_param) te += s.curve.period();
  return te;
}

// Newton for a local maximum of |C(u) - P|^2: g(u) = (C - P).C' = 0, g' = |C'|^2 + (C - P).C''.
double farthest_param(const BSplineCurve<2>& c, const Eigen::Vector2d& P, double u, double step_limit) {
  for (int it = 0; it < 50; ++it) {
    Eigen::Vector2d d[3];
    c.derivatives(u, 2, d);
    const Eigen::Vector2d w = d[0] - P;
    const double g = w.dot(d[1]), gp = d[1].squaredNorm() + w.dot(d[2]);
    if (gp >= 0) break;  // not near a maximum: keep the sampled start
    const double step = std::clamp(-g / gp, -step_limit, step_limit);
    u += step;
    if (std::abs(step) <= 1e-15 * (1.0 + std::abs(u))) break;
  }
  return u;
}

double curvature(const BSplineCurve<2>& c, double u) {
  Eigen::Vector2d d[3];
  c.derivatives(u, 2, d);
  return std::abs(d[1].x() * d[2].y() - d[1].y() * d[2].x()) / std::pow(d[1].norm(), 3);
}

// Polygon (closed) with no two non-adjacent edges intersecting.
void require_simple_polygon(const std::vector<Eigen::Vector2d>& pts, const std::string& what) {
  std::vector<Eigen::Vector2d> closed = pts;
  closed.push_back(pts.front());
  const int n = static_cast<int>(pts.size());
  for (const auto& h : detail::polyline_crossings(closed, closed, 0.0)) {
    const int d = std::abs(h.i - h.j);
    if (d <= 1 || d == n - 1) continue;  // the same or adjacent edges
    throw InvalidGeometry(what + ": the section outline intersects itself (edges " + std::to_string(h.i) + " and " +
                          std::to_string(h.j) + ")");
  }
}

struct Detected {
  double le, te;
};

// LE/TE of a closed curve as the diameter pair (see section.hpp), the LE at the blunter end.
Detected detect_le_te(const BSplineCurve<2>& c) {
  const std::vector<double> u = detail::sample_params(c, 16);
  std::vector<Eigen::Vector2d> p(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) p[k] = c.point(u[k]);
  std::size_t bi = 0, bj = 0;
  double best = -1;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = (p[i] - p[j]).squaredNorm();
      if (d > best) best = d, bi = i, bj = j;
    }
  const double h = c.period() / static_cast<double>(u.size());
  double a = u[bi], b = u[bj];
  for (int it = 0; it < 100; ++it) {
    const double b1 = farthest_param(c, c.point(a), b, h);
    const double a1 = farthest_param(c, c.point(b1), a, h);
    const bool done = std::abs(a1 - a) <= 1e-14 && std::abs(b1 - b) <= 1e-14;
    a = a1, b = b1;
    if (done) break;
  }
  a = c.check_param(a), b = c.check_param(b);
  return curvature(c, a) <= curvature(c, b) ? Detected{a, b} : Detected{b, a};
}

SectionProfile make_profile(const BSplineCurve<2>& curve, double le, double te) {
  SectionProfile s;
  s.curve = curve;
  s.le_param = le;
  s.te_param = te;
  while (s.te_param <= s.le_param) s.te_param += curve.period();
  s.le = curve.point(le);
  s.te = curve.point(te);
  return s;
}

}  // namespace

double SectionProfile::suction_length() const {
  return CurveIntegral(curve, le_param, suction_end(*this), Integrand::ArcLength).total();
}

double SectionProfile::pressure_length() const {
  return CurveIntegral(curve, suction_end(*this), le_param + curve.period(), Integrand::ArcLength).total();
}

std::vector<double> SectionProfile::params_at_chordwise(const std::vector<double>& c) const {
  const double te = suction_end(*this);
  const CurveIntegral suction(curve, le_param, te, Integrand::ArcLength);
  const CurveIntegral pressure(curve, te, le_param + curve.period(), Integrand::ArcLength);
  std::vector<double> out(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double ck = c[k];
    require(ck >= -1 && ck <= 1, "chordwise coordinate " + std::to_string(ck) + " is outside [-1, 1]");
    if (ck >= 0)
      out[k] = ck == 0 ? le_param : suction.inverse(curve, ck * suction.total());
    else
      out[k] = pressure.inverse(curve, (1 + ck) * pressure.total());
  }
  return out;
}

double SectionProfile::param_at_chordwise(double c) const { return params_at_chordwise({c}).front(); }

SectionProperties section_properties(const BSplineCurve<2>& curve) {
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
      curve.derivatives(mid + half * kGaussNodes[k], 1, d);
      const double w = kGaussWeights[k] * half;
      a2 += w * (d[0].x() * d[1].y() - d[0].y() * d[1].x());
      mx += w * 0.5 * d[0].x() * d[0].x() * d[1].y();
      my -= w * 0.5 * d[0].y() * d[0].y() * d[1].x();
    }
  }
  r.area = 0.5 * a2;
  if (r.area != 0) r.centroid = Eigen::Vector2d(mx, my) / r.area;
  r.perimeter = CurveIntegral(curve, curve.first_param(), curve.last_param(), Integrand::ArcLength).total();
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
    Detected d{};
    if (le_index >= 0) {
      d = {curve.check_param(params[static_cast<std::size_t>(le_index)]),
           curve.check_param(params[static_cast<std::size_t>(te_index)])};
    } else {
      d = detect_le_te(curve);
    }
    SectionProfile s = make_profile(curve, d.le, d.te);
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
