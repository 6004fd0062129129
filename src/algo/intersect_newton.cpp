#include "src/algo/intersect_newton.hpp"

#include <algorithm>
#include <cmath>

#include "src/algo/project_point_curve.hpp"
#include "src/core/newton.hpp"

namespace cg::detail {

namespace {
using V2 = Eigen::Vector2d;
double cross(const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); }

// (s, t) in the two curve domains, clamped (the iterates never leave them).
newton::Domain<2> domains(CurveEvaluator<2>& a, CurveEvaluator<2>& b) {
  newton::Domain<2> dom;
  dom.lo = V2(a.curve().first_param(), b.curve().first_param());
  dom.hi = V2(a.curve().last_param(), b.curve().last_param());
  return dom;
}
}  // namespace

bool refine_crossing(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double residual_tol) {
  const newton::Domain<2> dom = domains(a, b);
  V2 P, dP, Q, dQ;
  const auto r = newton::solve_system<2>(
      [&](const V2& x, V2& F, Eigen::Matrix2d& J) {
        a.d1(x[0], P, dP);
        b.d1(x[1], Q, dQ);
        F = P - Q;
        J << dP.x(), -dQ.x(), dP.y(), -dQ.y();
      },
      V2(s, t), dom, dom.hi - dom.lo);
  s = r.x[0];
  t = r.x[1];
  return (a.point(s) - b.point(t)).norm() <= residual_tol;
}

bool refine_tangency(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double& gap) {
  const newton::Domain<2> dom = domains(a, b);
  V2 P, dP, ddP, Q, dQ, ddQ;
  newton::SystemOptions opt;
  opt.max_iterations = 60;
  const auto r = newton::solve_system<2>(
      [&](const V2& x, V2& G, Eigen::Matrix2d& J) {
        a.d2(x[0], P, dP, ddP);
        b.d2(x[1], Q, dQ, ddQ);
        const V2 F = P - Q;
        G = V2(F.dot(dP), cross(dP, dQ));
        J << dP.squaredNorm() + F.dot(ddP), -dQ.dot(dP), cross(ddP, dQ), cross(dP, ddQ);
      },
      V2(s, t), dom, dom.hi - dom.lo, opt);
  s = r.x[0];
  t = r.x[1];
  bool settled = r.settled;
  if (r.singular) {
    // Singular only when the contact is of higher order or a derivative vanishes: keep the iterate
    // if it already satisfies the system to rounding.
    a.d1(s, P, dP);
    b.d1(t, Q, dQ);
    const V2 F = P - Q;
    settled = std::abs(cross(dP, dQ)) <= 1e-14 * dP.norm() * dQ.norm() &&
              std::abs(F.dot(dP)) <= 1e-14 * (F.norm() + 1) * dP.norm();
  }
  a.d1(s, P, dP);
  b.d1(t, Q, dQ);
  gap = (P - Q).norm();
  // Accept only points whose tangents really are parallel (the iteration may stop on a domain end).
  const double sine = std::abs(cross(dP, dQ)) / std::max(dP.norm() * dQ.norm(), 1e-300);
  return settled && sine <= 1e-6;
}

double project_point(CurveEvaluator<2>& c, const Eigen::Vector2d& x, double& t, double lo, double hi) {
  newton::Domain<1> dom;
  dom.lo[0] = lo;
  dom.hi[0] = hi;
  t = refine_foot<2>(c, x, t, dom, 30);
  return (c.point(t) - x).norm();
}

}  // namespace cg::detail
