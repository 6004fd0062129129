#include "src/blade/section.hpp"

#include <Eigen/Dense>
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

double suction_end(const SectionProfile& s) {
  double te = s.te_param;
  while (te <= s.le_param) te += s.curve.period();
  return te;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Newton for an extreme of C(u).d: g(u) = C'(u).d = 0, g' = C''(u).d; steps limited to step_limit.
double extreme_param(const BSplineCurve<2>& c, const Eigen::Vector2d& d, double u, double step_limit) {
  for (int it = 0; it < 50; ++it) {
    Eigen::Vector2d q[3];
    c.derivatives(u, 2, q);
    const double gp = q[2].dot(d);
    if (gp == 0) break;
    const double step = std::clamp(-q[1].dot(d) / gp, -step_limit, step_limit);
    u += step;
    if (std::abs(step) <= 1e-15 * (1.0 + std::abs(u))) break;
  }
  return u;
}

// Newton for the bitangent through C(s), C(t): C'(s) and C'(t) both parallel to D = C(t) - C(s).
bool refine_bitangent(const BSplineCurve<2>& c, double& s, double& t, double step_limit) {
  for (int it = 0; it < 50; ++it) {
    Eigen::Vector2d a[3], b[3];
    c.derivatives(s, 2, a);
    c.derivatives(t, 2, b);
    const Eigen::Vector2d D = b[0] - a[0];
    const Eigen::Vector2d f(cross2(a[1], D), cross2(b[1], D));
    Eigen::Matrix2d J;
    J << cross2(a[2], D), cross2(a[1], b[1]), -cross2(b[1], a[1]), cross2(b[2], D);
    const Eigen::Vector2d step = J.fullPivLu().solve(f);
    if (!step.allFinite() || step.lpNorm<Eigen::Infinity>() > step_limit) return false;
    s -= step.x(), t -= step.y();
    if (step.lpNorm<Eigen::Infinity>() <= 1e-15 * (1.0 + std::abs(s) + std::abs(t))) return true;
  }
  return false;
}

// Indices of the convex hull of p, counter-clockwise (Andrew's monotone chain).
std::vector<std::size_t> convex_hull(const std::vector<Eigen::Vector2d>& p) {
  std::vector<std::size_t> idx(p.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return p[a].x() < p[b].x() || (p[a].x() == p[b].x() && p[a].y() < p[b].y());
  });
  std::vector<std::size_t> h(2 * idx.size());
  std::size_t k = 0;
  auto turn = [&](std::size_t o, std::size_t a, std::size_t b) { return cross2(p[a] - p[o], p[b] - p[o]); };
  for (std::size_t i : idx) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  for (std::size_t n = idx.size(), i = n - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], idx[i]) <= 0) --k;
    h[k++] = idx[i];
  }
  h.resize(k - 1);
  return h;
}

double curvature(const BSplineCurve<2>& c, double u) {
  Eigen::Vector2d d[3];
  c.derivatives(u, 2, d);
  return std::abs(d[1].x() * d[2].y() - d[1].y() * d[2].x()) / std::pow(d[1].norm(), 3);
}

void require_simple_polygon(const std::vector<Eigen::Vector2d>& pts, const std::string& what) {
  int a = 0, b = 0;
  if (!detail::polygon_is_simple(pts, a, b))
    throw InvalidGeometry(what + ": the section outline intersects itself (edges " + std::to_string(a) + " and " +
                          std::to_string(b) + ")");
}

struct Detected {
  double le, te;
  Eigen::Vector2d direction;  // chord line, not yet oriented
};

// LE/TE of a closed curve: the extreme points along the chord line (see section.hpp), the LE at the
// blunter end.
Detected detect_le_te(const BSplineCurve<2>& c) {
  const std::vector<double> u = detail::sample_params(c, 16);
  std::vector<Eigen::Vector2d> p(u.size() - 1);  // the last sample repeats the first (closed)
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = c.point(u[k]);
  std::size_t bi = 0, bj = 0;
  double diameter = -1;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = (p[i] - p[j]).norm();
      if (d > diameter) diameter = d, bi = i, bj = j;
    }
  const double h = c.period() / static_cast<double>(p.size());
  Eigen::Vector2d dir = (p[bj] - p[bi]).normalized();
  // The longest convex-hull edge bridges the concave (pressure) side when there is one.
  const std::vector<std::size_t> hull = convex_hull(p);
  double longest = 0;
  std::size_t hi = 0, hj = 0;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const std::size_t a = hull[k], b = hull[(k + 1) % hull.size()];
    const double l = (p[b] - p[a]).norm();
    if (l > longest) longest = l, hi = a, hj = b;
  }
  if (longest >= 0.5 * diameter) {
    double s = u[hi], t = u[hj];
    dir = (p[hj] - p[hi]).normalized();
    if (refine_bitangent(c, s, t, 4 * h)) dir = (c.point(t) - c.point(s)).normalized();
  }
  std::size_t imin = 0, imax = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k].dot(dir) < p[imin].dot(dir)) imin = k;
    if (p[k].dot(dir) > p[imax].dot(dir)) imax = k;
  }
  const double a = c.check_param(extreme_param(c, dir, u[imin], h));
  const double b = c.check_param(extreme_param(c, dir, u[imax], h));
  return curvature(c, a) <= curvature(c, b) ? Detected{a, b, dir} : Detected{b, a, dir};
}

SectionProfile make_profile(const BSplineCurve<2>& curve, double le, double te, Eigen::Vector2d direction) {
  SectionProfile s;
  s.curve = curve;
  s.le_param = le;
  s.te_param = te;
  while (s.te_param <= s.le_param) s.te_param += curve.period();
  s.le = curve.point(le);
  s.te = curve.point(te);
  s.chord_direction = direction.dot(s.te - s.le) >= 0 ? direction : Eigen::Vector2d(-direction);
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
      curve.derivatives(mid + half * detail::kGaussLegendre8Nodes[k], 1, d);
      const double w = detail::kGaussLegendre8Weights[k] * half;
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
           curve.check_param(params[static_cast<std::size_t>(te_index)]),
           (pts[static_cast<std::size_t>(te_index)] - pts[static_cast<std::size_t>(le_index)]).normalized()};
    } else {
      d = detect_le_te(curve);
    }
    SectionProfile s = make_profile(curve, d.le, d.te, d.direction);
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
