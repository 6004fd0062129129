#include "src/algo/ray_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "src/core/bezier_ops.hpp"
#include "src/core/error.hpp"
#include "src/core/newton.hpp"

namespace cg {

namespace {

// Sine of the angle between ray and tangent below which a hit counts as a tangent contact (a tangent
// contact is located to ~sqrt(rounding) along the curve, so its computed angle is ~1e-8).
constexpr double kTangentSine = 1e-6;

template <int Dim>
void check_ray(const Eigen::Matrix<double, Dim, 1>& o, const Eigen::Matrix<double, Dim, 1>& d) {
  require(o.allFinite(), "ray origin must have finite coordinates");
  require(d.allFinite() && d.norm() > 0, "ray direction must be finite and non-zero");
}

template <int Dim>
double sine_to(const Eigen::Matrix<double, Dim, 1>& d, const Eigen::Matrix<double, Dim, 1>& t) {
  const double dt = d.norm() * t.norm();
  if (!(dt > 0)) return 0.0;
  const double c = d.dot(t) / dt;
  return std::sqrt(std::max(0.0, 1.0 - c * c));
}

}  // namespace

template <int Dim>
RayCurveCaster<Dim>::RayCurveCaster(const BSplineCurve<Dim>& curve, double hit_tol)
    : proj_(curve) {
  for (const auto& b : curve_span_boxes(curve)) box_.add(b);
  scale_ = box_.diagonal();
  hit_tol_ = hit_tol > 0 ? hit_tol : 1e-9 * (1.0 + scale_);
}

// Damped Newton (newton::minimize) on g(s, u) = |o + s d - C(u)|^2 / 2 with the exact Hessian
// [d.d, -d.C'; -d.C', C'.C' - C''.F], u clamped to the domain, g never increasing. The Hessian is kept
// positive definite with a floor at the rounding level of its determinant (~1e-16 tr^2), so a
// degenerate (tangent) minimum still gets full Newton steps. Returns true when (s, u) is a critical
// point (gradient ~ 0 relative to the terms) or a hit to rounding.
template <int Dim>
bool RayCurveCaster<Dim>::closest_approach(const Point& o, const Point& d, double& s, double& u, double& gap) {
  const BSplineCurve<Dim>& c = curve();
  newton::Domain<2> dom;
  dom.lo[1] = c.first_param();
  dom.hi[1] = c.last_param();
  newton::MinimizeOptions<2> opt;
  opt.max_iterations = 60;
  opt.max_halvings = 50;
  opt.shift_floor = 1e-18;
  opt.xtol = Eigen::Vector2d(1e-15 * (std::abs(s) + scale_ / d.norm()), 1e-15 * (dom.hi[1] - dom.lo[1] + std::abs(dom.hi[1])));
  Point D[3];
  auto objective = [&](const Eigen::Vector2d& x, Eigen::Vector2d* g, Eigen::Matrix2d* H) {
    if (!g) return 0.5 * (o + x[0] * d - c.point(x[1])).squaredNorm();
    c.derivatives(x[1], 2, D);
    const Point F = o + x[0] * d - D[0];
    *g = Eigen::Vector2d(d.dot(F), -D[1].dot(F));
    *H << d.dot(d), -d.dot(D[1]), -d.dot(D[1]), D[1].dot(D[1]) - D[2].dot(F);
    return 0.5 * F.squaredNorm();
  };
  const auto r = newton::minimize<2>(objective, Eigen::Vector2d(s, u), dom, opt);
  s = r.x[0];
  u = r.x[1];
  gap = std::sqrt(2.0 * r.value);
  c.derivatives(u, 1, D);
  const Point F = o + s * d - D[0];
  const bool critical = std::abs(d.dot(F)) <= 1e-13 * d.norm() * (F.norm() + scale_) &&
                        std::abs(D[1].dot(F)) <= 1e-13 * D[1].norm() * (F.norm() + scale_);
  return critical || gap <= 1e-12 * (1.0 + scale_);
}

template <int Dim>
RayCurveHit<Dim> RayCurveCaster<Dim>::first_hit(const Point& o, const Point& d, double s_max) {
  check_ray<Dim>(o, d);
  require(s_max >= 0, "s_max must be >= 0");
  RayCurveHit<Dim> hit;
  double s0 = 0.0, s1 = s_max;
  if (!box_.clip_ray(o, d, s0, s1, hit_tol_)) return hit;
  const double L = d.norm();
  const double switch_tol = 1e-3 * (1.0 + scale_);
  double s = s0;
  double last_solved = std::numeric_limits<double>::infinity(), dist_mark = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 1000000; ++it) {
    const auto pr = proj_.project(o + s * d);
    const double dist = pr.distance;
    // Close to the curve, or stalled (the distance did not halve in 32 steps: a grazing ray).
    const bool stalled = it % 32 == 31 && dist > 0.5 * dist_mark;
    if (it % 32 == 31) dist_mark = dist;
    if ((dist <= switch_tol && dist <= 0.5 * last_solved) || stalled || dist <= hit_tol_) {
      last_solved = dist;
      double ss = s, uu = pr.param, gap = 0;
      const bool ok = closest_approach(o, d, ss, uu, gap);
      // The sphere at s holds no curve point, so a hit lies at or beyond s (up to rounding).
      if (ok && gap <= hit_tol_ && ss >= s - hit_tol_ / L && ss <= s_max) {
        hit.found = true;
        hit.ray_param = std::max(ss, 0.0);
        hit.curve_param = uu;
        hit.point = curve().point(uu);
        hit.gap = gap;
        hit.tangent = sine_to<Dim>(d, curve().derivatives(uu, 1)[1]) <= kTangentSine;
        return hit;
      }
      // Otherwise a near miss (gap > hit_tol): the march goes on past it with plain sphere steps.
    }
    s += dist / L;
    if (s > s1) return hit;
  }
  throw AlgorithmFailure("ray marching did not terminate within 10^6 steps");
}

template <int Dim>
RayCurveHit<Dim> ray_curve_first_hit(const BSplineCurve<Dim>& curve, const Eigen::Matrix<double, Dim, 1>& origin,
                                     const Eigen::Matrix<double, Dim, 1>& direction, double s_max) {
  RayCurveCaster<Dim> caster(curve);
  return caster.first_hit(origin, direction, s_max);
}

namespace {

// Value at t of the Bernstein polynomial of degree n with coefficients c (de Casteljau, A1.5).
double bernstein_value(const double* c, int n, double t) {
  double v;
  de_casteljau_point(n, 1, c, t, &v);
  return v;
}

struct LineRoots {
  const BSplineCurve<2>* curve;
  CurveEvaluator<2>* ev;
  Eigen::Vector2d o, n;
  int p;
  double tol;  // |g| below this is zero (g in length units)
  std::vector<std::pair<double, bool>>* roots;  // (u, tangent)

  double g(double u, double* dg) {
    Eigen::Vector2d C, C1;
    ev->d1(u, C, C1);
    if (dg) *dg = n.dot(C1);
    return n.dot(C - o);
  }

  // Bracketed Newton on g in [lo, hi] with g(lo), g(hi) of opposite signs.
  void newton(double lo, double hi, double u) {
    const int sign_lo = g(lo, nullptr) < 0 ? -1 : 1;
    const double eps = 4e-16 * (std::abs(lo) + std::abs(hi) + (hi - lo));
    u = newton::solve_bracketed([&](double x, double& dg) { return g(x, &dg); }, lo, hi, sign_lo, u, eps);
    roots->emplace_back(u, false);
  }

  void piece(const double* hp, double a, double b, int depth) {
    double c[kMaxDegree + 1], wmax = 0;
    int changes = 0, last = 0;
    double cmin = 1e300;
    for (int j = 0; j <= p; ++j) {
      const double* h = hp + j * 3;
      c[j] = n[0] * (h[0] - h[2] * o[0]) + n[1] * (h[1] - h[2] * o[1]);
      wmax = std::max(wmax, h[2]);
      cmin = std::min(cmin, std::abs(c[j]));
      const int sg = c[j] > 0 ? 1 : c[j] < 0 ? -1 : 0;
      if (sg != 0 && last != 0 && sg != last) ++changes;
      if (sg != 0) last = sg;
    }
    // No sign change and clear of zero (the curve lies in the hull of the coefficients): no root.
    if (changes == 0 && cmin > tol * wmax) return;
    double cmax = 0;
    for (int j = 0; j <= p; ++j) cmax = std::max(cmax, std::abs(c[j]));
    if (cmax <= tol * wmax) {
      // The piece lies on the line (overlap): its end points stand for it.
      roots->emplace_back(a, true);
      roots->emplace_back(b, true);
      return;
    }
    if (changes == 1 && std::abs(c[0]) > 0 && std::abs(c[p]) > 0) {
      int k = 0;
      while (k < p && (c[k + 1] > 0) == (c[0] > 0)) ++k;
      const double t = (k + c[k] / (c[k] - c[k + 1])) / p;
      newton(a, b, a + std::clamp(t, 0.0, 1.0) * (b - a));
      return;
    }
    if (changes == 0) {
      // Close to the line without crossing it: a root can only be at an end or a tangent contact at
      // an extremum of g. One sign change of g' isolates the extremum (found by bisection on the
      // Bernstein form of g'); more need subdivision.
      const double w0 = hp[2], wp = hp[p * 3 + 2];
      if (std::abs(c[0]) <= tol * w0) roots->emplace_back(a, false);
      if (std::abs(c[p]) <= tol * wp) roots->emplace_back(b, false);
      double dc[kMaxDegree];
      int dchanges = 0, dlast = 0;
      for (int j = 0; j < p; ++j) {
        dc[j] = c[j + 1] - c[j];
        const int sg = dc[j] > 0 ? 1 : dc[j] < 0 ? -1 : 0;
        if (sg != 0 && dlast != 0 && sg != dlast) ++dchanges;
        if (sg != 0) dlast = sg;
      }
      if (dchanges == 0) return;
      if (dchanges == 1) {
        double lo = 0, hi = 1;
        const bool rising_first = bernstein_value(dc, p - 1, 0.0) > 0;
        for (int it = 0; it < 60; ++it) {
          const double t = 0.5 * (lo + hi);
          ((bernstein_value(dc, p - 1, t) > 0) == rising_first ? lo : hi) = t;
        }
        const double t = 0.5 * (lo + hi);
        double wts[kMaxDegree + 1];
        for (int j = 0; j <= p; ++j) wts[j] = hp[j * 3 + 2];
        if (std::abs(bernstein_value(c, p, t)) <= tol * bernstein_value(wts, p, t))
          roots->emplace_back(a + t * (b - a), true);
        return;
      }
    }
    const double m = 0.5 * (a + b);
    if (depth >= 52 || b - a <= 1e-15 * (std::abs(a) + std::abs(b))) {
      // Unresolved at parameter resolution: a tangent contact (or a root at an end) when |g| ~ 0.
      if (std::abs(g(m, nullptr)) <= tol) roots->emplace_back(m, changes != 1);
      return;
    }
    double left[(kMaxDegree + 1) * 3], right[(kMaxDegree + 1) * 3];
    split_bezier(p, 3, hp, 0.5, left, right);
    piece(left, a, m, depth + 1);
    piece(right, m, b, depth + 1);
  }
};

}  // namespace

std::vector<RayCurveHit<2>> line_curve_intersections(const BSplineCurve<2>& curve, const Eigen::Vector2d& origin,
                                                     const Eigen::Vector2d& direction, double s_min, double s_max) {
  check_ray<2>(origin, direction);
  require(s_min <= s_max, "s_min must not exceed s_max");
  CurveEvaluator<2> ev(curve);
  const auto spans = curve_bezier_spans(curve);
  BoundingBox<2> box;
  for (const auto& sp : spans) box.add(sp.box);
  const double scale = box.diagonal();
  std::vector<std::pair<double, bool>> roots;
  LineRoots lr{&curve, &ev, origin, Eigen::Vector2d(-direction.y(), direction.x()).normalized(), curve.degree(),
               1e-12 * (1.0 + scale), &roots};
  for (const auto& sp : spans) lr.piece(sp.hpoles.data(), sp.a, sp.b, 0);

  std::vector<RayCurveHit<2>> hits;
  const double L2 = direction.squaredNorm();
  for (const auto& [u, flagged] : roots) {
    RayCurveHit<2> h;
    h.found = true;
    h.curve_param = u;
    h.point = curve.point(u);
    h.ray_param = direction.dot(h.point - origin) / L2;
    h.gap = (origin + h.ray_param * direction - h.point).norm();
    h.tangent = flagged || sine_to<2>(direction, curve.derivatives(u, 1)[1]) <= kTangentSine;
    if (h.ray_param < s_min - 1e-12 || h.ray_param > s_max + 1e-12) continue;
    // A root on a knot is found from both spans (and both ends of a closed curve): keep one.
    bool dup = false;
    for (const auto& k : hits) dup = dup || (k.point - h.point).norm() <= 1e-9 * (1.0 + scale);
    if (!dup) hits.push_back(h);
  }
  std::sort(hits.begin(), hits.end(), [](const auto& x, const auto& y) { return x.ray_param < y.ray_param; });
  return hits;
}

template class RayCurveCaster<2>;
template class RayCurveCaster<3>;
template RayCurveHit<2> ray_curve_first_hit<2>(const BSplineCurve<2>&, const Eigen::Vector2d&, const Eigen::Vector2d&,
                                               double);
template RayCurveHit<3> ray_curve_first_hit<3>(const BSplineCurve<3>&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                                               double);

}  // namespace cg
