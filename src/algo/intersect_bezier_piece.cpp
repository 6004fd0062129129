#include "src/algo/intersect_bezier_piece.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/bezier_ops.hpp"
#include "src/core/constants.hpp"

namespace cg::detail {

namespace {
// Interval of abscissae j/p where the convex hull of (j/p, v_j) has points with ordinate >= 0.
bool nonnegative_hull_range(const double* v, int p, double& lo, double& hi) {
  lo = 2.0;
  hi = -1.0;
  for (int i = 0; i <= p; ++i) {
    const double xi = static_cast<double>(i) / p;
    if (v[i] >= 0.0) {
      lo = std::min(lo, xi);
      hi = std::max(hi, xi);
      continue;
    }
    for (int j = 0; j <= p; ++j) {
      if (v[j] < 0.0) continue;
      const double xj = static_cast<double>(j) / p;
      const double xc = xi + (xj - xi) * (-v[i]) / (v[j] - v[i]);
      lo = std::min(lo, xc);
      hi = std::max(hi, xc);
    }
  }
  return lo <= hi;
}

// Adds the direction of every non-degenerate leg of the control polygon to the running cone
// (angles relative to the first leg, so the interval never wraps).
struct ConeBuilder {
  bool any = false;
  double base = 0.0, lo = 0.0, hi = 0.0;
  void add_legs(const BezierPiece2& pc) {
    double px = pc.x(0), py = pc.y(0);
    for (int i = 1; i <= pc.degree; ++i) {
      const double qx = pc.x(i), qy = pc.y(i);
      const double dx = qx - px, dy = qy - py;
      px = qx;
      py = qy;
      if (dx == 0.0 && dy == 0.0) continue;
      const double a = std::atan2(dy, dx);
      if (!any) {
        any = true;
        base = a;
        continue;
      }
      double r = a - base;
      if (r > kPi) r -= 2 * kPi;
      if (r < -kPi) r += 2 * kPi;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  DirectionCone cone() const {
    DirectionCone c;
    c.narrow = any && hi - lo < kPi - 1e-9;
    c.lo = base + lo;
    c.hi = base + hi;
    return c;
  }
};
}  // namespace

std::vector<BezierPiece2> bezier_pieces(const BSplineCurve<2>& curve) {
  const int p = curve.degree();
  const auto& U = curve.knots();
  const auto& H = curve.homogeneous_poles();
  std::vector<BezierPiece2> out;
  const int n = curve.num_poles() - 1;
  out.reserve(static_cast<std::size_t>(n - p + 1));
  for (int i = p; i <= n; ++i) {
    const double a = U[static_cast<std::size_t>(i)], b = U[static_cast<std::size_t>(i + 1)];
    if (!(b > a)) continue;
    BezierPiece2 pc;
    pc.degree = p;
    pc.lo = a;
    pc.hi = b;
    span_bezier_poles(p, U.data(), i, H.col(i - p).data(), 3, &pc.h[0][0]);
    out.push_back(pc);
  }
  return out;
}

void restrict_piece(BezierPiece2& pc, double a, double b) {
  restrict_bezier(pc.degree, 3, &pc.h[0][0], a, b);
  const double lo = pc.lo, w = pc.hi - pc.lo;
  if (a > 0.0) pc.lo = lo + a * w;
  if (b < 1.0) pc.hi = lo + b * w;
}

void halve_piece(const BezierPiece2& pc, BezierPiece2& left, BezierPiece2& right) {
  split_bezier(pc.degree, 3, &pc.h[0][0], 0.5, &left.h[0][0], &right.h[0][0]);
  left.degree = right.degree = pc.degree;
  const double mid = 0.5 * (pc.lo + pc.hi);
  left.lo = pc.lo;
  left.hi = mid;
  right.lo = mid;
  right.hi = pc.hi;
}

double Box2::diagonal() const { return std::hypot(x1 - x0, y1 - y0); }

Box2 piece_box(const BezierPiece2& pc) {
  Box2 b{pc.x(0), pc.y(0), pc.x(0), pc.y(0)};
  for (int i = 1; i <= pc.degree; ++i) {
    const double x = pc.x(i), y = pc.y(i);
    b.x0 = std::min(b.x0, x);
    b.x1 = std::max(b.x1, x);
    b.y0 = std::min(b.y0, y);
    b.y1 = std::max(b.y1, y);
  }
  return b;
}

DirectionCone piece_cone(const BezierPiece2& pc) {
  ConeBuilder b;
  b.add_legs(pc);
  return b.cone();
}

DirectionCone joined_cone(const BezierPiece2& first, const BezierPiece2& second) {
  ConeBuilder b;
  b.add_legs(first);
  b.add_legs(second);
  return b.cone();
}

bool cones_separated(const DirectionCone& a, const DirectionCone& b) {
  if (!a.narrow || !b.narrow) return false;
  // Angles lie in [-2pi, 2pi]; shifting b by k*pi for |k| <= 5 covers every parallel alignment.
  // The margin exceeds the rounding of leg directions on the smallest pieces split (1e-7 of the
  // model size: ~1e-9 rad), so touching cones are never taken as separated.
  constexpr double margin = 1e-6;
  for (int k = -5; k <= 5; ++k) {
    const double lo = b.lo + k * kPi, hi = b.hi + k * kPi;
    if (a.lo <= hi + margin && lo <= a.hi + margin) return false;
  }
  return true;
}

bool clip_by_fat_line(const BezierPiece2& line, const BezierPiece2& target, double margin, double& a, double& b) {
  a = 0.0;
  b = 1.0;
  const int p = line.degree;
  const double x0 = line.x(0), y0 = line.y(0);
  double dx = line.x(p) - x0, dy = line.y(p) - y0;
  if (dx == 0.0 && dy == 0.0) {  // closed piece: use the chord to the farthest pole
    double best = 0.0;
    for (int i = 1; i < p; ++i) {
      const double ex = line.x(i) - x0, ey = line.y(i) - y0, d2 = ex * ex + ey * ey;
      if (d2 > best) {
        best = d2;
        dx = ex;
        dy = ey;
      }
    }
    if (best == 0.0) return true;
  }
  const double len = std::hypot(dx, dy);
  const double nx = -dy / len, ny = dx / len, c = nx * x0 + ny * y0;
  double dmin = 0.0, dmax = 0.0;
  for (int i = 0; i <= p; ++i) {
    const double d = nx * line.x(i) + ny * line.y(i) - c;
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
  }
  dmin -= margin;
  dmax += margin;
  const int q = target.degree;
  double lower[kMaxDegree + 1], upper[kMaxDegree + 1];
  for (int j = 0; j <= q; ++j) {
    const double w = target.h[j][2];
    const double f = nx * target.h[j][0] + ny * target.h[j][1] - c * w;  // w * signed distance
    lower[j] = f - dmin * w;
    upper[j] = dmax * w - f;
  }
  double a1, b1, a2, b2;
  if (!nonnegative_hull_range(lower, q, a1, b1) || !nonnegative_hull_range(upper, q, a2, b2)) return false;
  a = std::max(a1, a2);
  b = std::min(b1, b2);
  return a <= b;
}

}  // namespace cg::detail
