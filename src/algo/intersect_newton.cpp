#include "src/algo/intersect_newton.hpp"

#include <algorithm>
#include <cmath>

namespace cg::detail {

namespace {
using V2 = Eigen::Vector2d;
double cross(const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); }
double clamp_to(double u, double lo, double hi) { return u < lo ? lo : (u > hi ? hi : u); }
double first(CurveEvaluator<2>& c) { return c.curve().first_param(); }
double last(CurveEvaluator<2>& c) { return c.curve().last_param(); }

// Solves [[a, b], [c, d]] x = r; false when singular.
bool solve2(double a, double b, double c, double d, double r0, double r1, double& x0, double& x1) {
  const double det = a * d - b * c;
  const double scale = std::max(std::abs(a * d), std::abs(b * c));
  if (!(std::abs(det) > 1e-300) || std::abs(det) <= 1e-15 * scale) return false;
  x0 = (r0 * d - b * r1) / det;
  x1 = (a * r1 - c * r0) / det;
  return std::isfinite(x0) && std::isfinite(x1);
}

// Stops when the step falls below a few ulps of the domain lengths or stops shrinking.
struct StepMonitor {
  double ls, lt, prev = HUGE_VAL;
  int stalls = 0;
  bool done(double ds, double dt) {
    const double r = std::max(std::abs(ds) / ls, std::abs(dt) / lt);
    if (r <= 1e-15) return true;
    stalls = r >= 0.5 * prev ? stalls + 1 : 0;
    prev = r;
    return stalls >= 4;
  }
};
}  // namespace

bool refine_crossing(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double residual_tol) {
  const double a0 = first(a), a1 = last(a), b0 = first(b), b1 = last(b);
  StepMonitor mon{a1 - a0, b1 - b0};
  V2 P, dP, Q, dQ;
  for (int it = 0; it < 40; ++it) {
    a.d1(s, P, dP);
    b.d1(t, Q, dQ);
    const V2 F = P - Q;
    double ds, dt;
    if (!solve2(dP.x(), -dQ.x(), dP.y(), -dQ.y(), -F.x(), -F.y(), ds, dt)) return F.norm() <= residual_tol;
    const double ns = clamp_to(s + ds, a0, a1), nt = clamp_to(t + dt, b0, b1);
    ds = ns - s;
    dt = nt - t;
    s = ns;
    t = nt;
    if (mon.done(ds, dt)) break;
  }
  return (a.point(s) - b.point(t)).norm() <= residual_tol;
}

bool refine_tangency(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double& gap) {
  const double a0 = first(a), a1 = last(a), b0 = first(b), b1 = last(b);
  StepMonitor mon{a1 - a0, b1 - b0};
  V2 P, dP, ddP, Q, dQ, ddQ;
  bool settled = false;
  for (int it = 0; it < 60; ++it) {
    a.d2(s, P, dP, ddP);
    b.d2(t, Q, dQ, ddQ);
    const V2 F = P - Q;
    const double g1 = F.dot(dP), g2 = cross(dP, dQ);
    double ds, dt;
    if (!solve2(dP.squaredNorm() + F.dot(ddP), -dQ.dot(dP), cross(ddP, dQ), cross(dP, ddQ), -g1, -g2, ds, dt)) {
      // Singular only when the contact is of higher order or a derivative vanishes: keep the iterate
      // if it already satisfies the system to rounding.
      settled = std::abs(g2) <= 1e-14 * dP.norm() * dQ.norm() && std::abs(g1) <= 1e-14 * (F.norm() + 1) * dP.norm();
      break;
    }
    const double ns = clamp_to(s + ds, a0, a1), nt = clamp_to(t + dt, b0, b1);
    ds = ns - s;
    dt = nt - t;
    s = ns;
    t = nt;
    if (mon.done(ds, dt)) {
      settled = true;
      break;
    }
  }
  a.d1(s, P, dP);
  b.d1(t, Q, dQ);
  gap = (P - Q).norm();
  // Accept only points whose tangents really are parallel (the iteration may stop on a domain end).
  const double sine = std::abs(cross(dP, dQ)) / std::max(dP.norm() * dQ.norm(), 1e-300);
  return settled && sine <= 1e-6;
}

double project_point(CurveEvaluator<2>& c, const Eigen::Vector2d& x, double& t, double lo, double hi) {
  V2 C, d1, d2;
  double prev = HUGE_VAL;
  for (int it = 0; it < 30; ++it) {
    c.d2(t, C, d1, d2);
    const V2 r = C - x;
    const double f = r.dot(d1), df = d1.squaredNorm() + r.dot(d2);
    double step = df > 0 ? -f / df : -f / std::max(d1.squaredNorm(), 1e-300);
    const double nt = clamp_to(t + step, lo, hi);
    step = nt - t;
    t = nt;
    const double r_step = std::abs(step) / std::max(hi - lo, 1e-300);
    if (r_step <= 1e-15 || (r_step >= 0.5 * prev && it > 10)) break;
    prev = r_step;
  }
  return (c.point(t) - x).norm();
}

}  // namespace cg::detail
