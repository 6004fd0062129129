#include "src/algo/ray_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "src/core/error.hpp"

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
    : proj_(curve), curve_(&curve) {
  for (const auto& b : curve_span_boxes(curve)) box_.add(b);
  scale_ = box_.diagonal();
  hit_tol_ = hit_tol > 0 ? hit_tol : 1e-9 * (1.0 + scale_);
}

// Damped Newton on g(s, u) = |o + s d - C(u)|^2 / 2 with the exact Hessian
// [d.d, -d.C'; -d.C', C'.C' - C''.F], u clamped to the domain, backtracking so g never increases.
// Returns true when (s, u) is a critical point (gradient ~ 0 relative to the terms).
template <int Dim>
bool RayCurveCaster<Dim>::closest_approach(const Point& o, const Point& d, double& s, double& u, double& gap) {
  const double lo = curve_->first_param(), hi = curve_->last_param();
  const double eu = 1e-15 * (hi - lo + std::abs(hi)), es = 1e-15 * (std::abs(s) + scale_ / d.norm());
  Point D[3];
  auto value = [&](double ss, double uu) { return 0.5 * (o + ss * d - curve_->point(uu)).squaredNorm(); };
  double f = value(s, u);
  bool critical = false;
  for (int it = 0; it < 60; ++it) {
    curve_->derivatives(u, 2, D);
    const Point F = o + s * d - D[0];
    const double gs = d.dot(F), gu = -D[1].dot(F);
    critical = std::abs(gs) <= 1e-13 * d.norm() * (F.norm() + scale_) &&
               std::abs(gu) <= 1e-13 * D[1].norm() * (F.norm() + scale_);
    double a = d.dot(d), b = -d.dot(D[1]), c = D[1].dot(D[1]) - D[2].dot(F);
    const double tr = a + c, det = a * c - b * b;
    const double lmin = 0.5 * tr - std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
    // Keep H positive definite; the floor is at the rounding level of det (~1e-16 tr^2) so a
    // degenerate (tangent) minimum still gets full Newton steps.
    const double floor = 1e-18 * std::abs(tr);
    if (lmin < floor) {
      const double shift = floor - lmin;
      a += shift;
      c += shift;
    }
    const double dd = a * c - b * b;
    double ds = -(c * gs - b * gu) / dd, du = -(a * gu - b * gs) / dd;
    bool moved = false;
    for (int half = 0; half < 50; ++half) {
      const double sn = s + ds, un = std::clamp(u + du, lo, hi);
      const double fn = value(sn, un);
      if (fn <= f) {
        moved = std::abs(sn - s) > es || std::abs(un - u) > eu;
        s = sn;
        u = un;
        f = fn;
        break;
      }
      ds *= 0.5;
      du *= 0.5;
    }
    if (!moved) break;
  }
  gap = std::sqrt(2.0 * f);
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
        hit.point = curve_->point(uu);
        hit.gap = gap;
        hit.tangent = sine_to<Dim>(d, curve_->derivatives(uu, 1)[1]) <= kTangentSine;
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
  double q[kMaxDegree + 1];
  std::copy(c, c + n + 1, q);
  for (int k = 1; k <= n; ++k)
    for (int i = 0; i <= n - k; ++i) q[i] = (1.0 - t) * q[i] + t * q[i + 1];
  return q[0];
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
    double glo = g(lo, nullptr);
    const double eps = 4e-16 * (std::abs(lo) + std::abs(hi) + (hi - lo));
    for (int it = 0; it < 100; ++it) {
      double dg = 0;
      const double gu = g(u, &dg);
      if (gu == 0) break;
      if ((gu < 0) == (glo < 0)) {
        lo = u;
        glo = gu;
      } else {
        hi = u;
      }
      double next = u - gu / dg;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool done = std::abs(next - u) <= eps || hi - lo <= eps;
      u = next;
      if (done) break;
    }
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
