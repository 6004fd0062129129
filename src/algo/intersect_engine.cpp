#include "src/algo/intersect_engine.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/algo/intersect_newton.hpp"
#include "src/core/error.hpp"

namespace cg::detail {

namespace {
using V2 = Eigen::Vector2d;
constexpr long kWorkBudget = 1000000;

double cross(const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); }

double control_extent(const std::vector<BezierPiece2>& pieces) {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  for (const auto& pc : pieces) {
    const Box2 b = piece_box(pc);
    x0 = std::min(x0, b.x0);
    y0 = std::min(y0, b.y0);
    x1 = std::max(x1, b.x1);
    y1 = std::max(y1, b.y1);
  }
  return std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1), std::hypot(x1 - x0, y1 - y0)});
}

// Sine of the angle between the tangents of a at s and b at t.
double tangent_sine(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double s, double t) {
  V2 P, dP, Q, dQ;
  a.d1(s, P, dP);
  b.d1(t, Q, dQ);
  return std::abs(cross(dP, dQ)) / std::max(dP.norm() * dQ.norm(), 1e-300);
}

// Curve ends and corners (segment junctions where the tangent direction jumps), sorted.
std::vector<double> ends_and_corners(const std::vector<BezierPiece2>& pieces) {
  std::vector<double> out;
  if (pieces.empty()) return out;
  out.push_back(pieces.front().lo);
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    const BezierPiece2& l = pieces[i];
    const BezierPiece2& r = pieces[i + 1];
    const V2 dl = l.pole(l.degree) - l.pole(l.degree - 1), dr = r.pole(1) - r.pole(0);
    if (std::abs(cross(dl, dr)) > 1e-9 * dl.norm() * dr.norm() || dl.dot(dr) <= 0.0) out.push_back(l.hi);
  }
  out.push_back(pieces.back().hi);
  return out;
}
}  // namespace

CurvePairIntersector::CurvePairIntersector(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double tol, bool self)
    : a_(a), b_(b), ea_(a), eb_(b), pieces_a_(bezier_pieces(a)), self_(self) {
  pieces_b_ = self ? pieces_a_ : bezier_pieces(b);
  ends_a_ = ends_and_corners(pieces_a_);
  ends_b_ = self ? ends_a_ : ends_and_corners(pieces_b_);
  a0_ = a.first_param();
  a1_ = a.last_param();
  b0_ = b.first_param();
  b1_ = b.last_param();
  scale_ = std::max(control_extent(pieces_a_), control_extent(pieces_b_));
  // Below ~1e-13 of the model size a gap is rounding noise of the subdivided poles.
  tol_ = std::max(tol, 1e-13 * scale_);
  // Pruning (boxes, fat lines) uses only a rounding margin: a tol margin would keep every pair along
  // a tangential contact's zone of gaps below tol (length ~sqrt(tol / curvature)) and split it all
  // down to the leaf size. Pairs pruned only by less than tol are near misses, solved directly.
  margin_ = 1e-13 * scale_;
  // Crossings are accepted at a residual that transversal Newton reaches easily and a double root
  // (tangency, reached linearly) does not pass on a sloppy iterate.
  crossing_tol_ = std::min(tol_, 1e-12 * scale_);
  // Pieces smaller than this are not split further: tangential candidates are solved there.
  leaf_ = std::max(tol_, 1e-7 * scale_);
  near_floor_ = std::max(leaf_, 1e-4 * scale_);
  closed_ = self && a.is_closed(tol_);
  // A cusp's two branches stay within tol of each other over a length ~ (tol^2 scale)^(1/3): contacts
  // on an arc that never leaves a ball of this radius are the curve meeting itself trivially.
  trivial_radius_ = std::max(10.0 * leaf_, 10.0 * std::cbrt(tol_ * tol_ * scale_));
  stack_.reserve(16);
}

void CurvePairIntersector::intersect_pieces(const BezierPiece2& x, const BezierPiece2& y) {
  stack_.push_back({x, y, false});
  while (!stack_.empty()) {
    const Task t = stack_.back();
    stack_.pop_back();
    if (t.near)
      process_near_miss(t.x, t.y);
    else
      process(t.x, t.y);
  }
}

void CurvePairIntersector::self_intersect_piece(const BezierPiece2& x) {
  std::vector<BezierPiece2> pending{x};
  while (!pending.empty()) {
    const BezierPiece2 pc = pending.back();
    pending.pop_back();
    // A piece whose tangents stay within an open half-plane cannot meet itself.
    if (piece_cone(pc).narrow || piece_box(pc).diagonal() <= leaf_) continue;
    BezierPiece2 l, r;
    halve_piece(pc, l, r);
    pending.push_back(l);
    pending.push_back(r);
    intersect_pieces(l, r);
  }
}

void CurvePairIntersector::split_and_push(const BezierPiece2& x, const BezierPiece2& y, double size_x,
                                          double size_y, bool near) {
  BezierPiece2 l, r;
  if (size_x >= size_y) {
    halve_piece(x, l, r);
    stack_.push_back({l, y, near});
    stack_.push_back({r, y, near});
  } else {
    halve_piece(y, l, r);
    stack_.push_back({x, l, near});
    stack_.push_back({x, r, near});
  }
}

void CurvePairIntersector::count_work() {
  if (++work_ > kWorkBudget)
    throw AlgorithmFailure("curve intersection: subdivision budget of " + std::to_string(kWorkBudget) +
                           " piece pairs exhausted");
}

void CurvePairIntersector::process_near_miss(BezierPiece2 x, BezierPiece2 y) {
  // The pair does not meet (it was pruned exactly) but comes within tol: look for a tangential
  // near-contact, pruning with the tol margin. Within the contact's zone nothing can be pruned, so
  // instead of splitting down to the leaf size, every stalled pair tries the tangency system and
  // stops when it holds inside the pair.
  for (;;) {
    count_work();
    const Box2 bx = piece_box(x), by = piece_box(y);
    if (!bx.overlaps(by, tol_)) return;
    const double sx = bx.diagonal(), sy = by.diagonal();
    // A local minimum of the distance inside both pieces needs parallel tangents; with separated
    // cones the pair can only hold a touching curve end. Below near_floor_ pieces are well inside
    // the tangency system's basin, which the stalled pairs above have tried: splitting further would
    // only crawl along zones where the curves run within tol of each other (small-angle crossings).
    if (std::max(sx, sy) <= near_floor_ || cones_separated(piece_cone(x), piece_cone(y))) {
      end_touches(x, y);
      return;
    }
    double ya, yb, xa, xb;
    if (!clip_by_fat_line(x, y, tol_, ya, yb) || !clip_by_fat_line(y, x, tol_, xa, xb)) return;
    const bool progress = yb - ya < 0.8 || xb - xa < 0.8;
    if (ya > 0.0 || yb < 1.0) restrict_piece(y, ya, yb);
    if (xa > 0.0 || xb < 1.0) restrict_piece(x, xa, xb);
    if (progress) continue;
    double s = x.param(0.5), t = y.param(0.5), gap = 0.0;
    if (refine_tangency(ea_, eb_, s, t, gap) && s >= x.lo && s <= x.hi && t >= y.lo && t <= y.hi) {
      if (gap <= tol_ && !crossed_extremum(s, t)) {
        record(s, t, ContactKind::tangent);
        return;
      }
    }
    split_and_push(x, y, sx, sy, true);
    return;
  }
}

void CurvePairIntersector::process(BezierPiece2 x, BezierPiece2 y) {
  for (;;) {
    count_work();
    const Box2 bx = piece_box(x), by = piece_box(y);
    if (!bx.overlaps(by, margin_)) {
      if (bx.overlaps(by, tol_)) stack_.push_back({x, y, true});
      return;
    }
    const double sx = bx.diagonal(), sy = by.diagonal();
    const bool small = std::max(sx, sy) <= leaf_;
    if (self_) {
      const bool consecutive = x.hi == y.lo;
      const bool seam = closed_ && x.lo == a0_ && y.hi == a1_;
      if (consecutive || seam) {
        // Pieces sharing an end meet there; if their joined polygon turns by less than pi they
        // cannot meet anywhere else. Tiny junction pairs are the shared point itself.
        if (small) return;
        if (!(consecutive && seam) && joined_cone(consecutive ? x : y, consecutive ? y : x).narrow) return;
        split_and_push(x, y, sx, sy, false);
        return;
      }
    }
    if (cones_separated(piece_cone(x), piece_cone(y))) {
      if (isolated_crossing(x, y)) return;
      if (small) {
        leaf(x, y);
        return;
      }
      split_and_push(x, y, sx, sy, false);
      return;
    }
    double ya, yb, xa, xb;
    if (!clip_by_fat_line(x, y, margin_, ya, yb) || !clip_by_fat_line(y, x, margin_, xa, xb)) {
      double a, b;
      if (clip_by_fat_line(x, y, tol_, a, b) && clip_by_fat_line(y, x, tol_, a, b)) stack_.push_back({x, y, true});
      return;
    }
    // Sederberg & Nishita: keep clipping while an interval shrinks by 20 %, split otherwise.
    const bool progress = yb - ya < 0.8 || xb - xa < 0.8;
    if (ya > 0.0 || yb < 1.0) restrict_piece(y, ya, yb);
    if (xa > 0.0 || xb < 1.0) restrict_piece(x, xa, xb);
    if (progress) continue;
    if (small) {
      leaf(x, y);
      return;
    }
    if (record_overlap(x, y)) return;
    split_and_push(x, y, sx, sy, false);
    return;
  }
}

bool CurvePairIntersector::isolated_crossing(const BezierPiece2& x, const BezierPiece2& y) {
  // Start from the crossing of the end-to-end chords (clamped), else the midpoints.
  const V2 p0 = x.pole(0), p1 = x.pole(x.degree), q0 = y.pole(0), q1 = y.pole(y.degree);
  const V2 dp = p1 - p0, dq = q1 - q0, r = q0 - p0;
  double al = 0.5, be = 0.5;
  const double den = cross(dp, dq);
  if (std::abs(den) > 1e-14 * dp.norm() * dq.norm()) {
    al = std::clamp(cross(r, dq) / den, 0.0, 1.0);
    be = std::clamp(cross(r, dp) / den, 0.0, 1.0);
  }
  double s = x.param(al), t = y.param(be);
  if (!refine_crossing(ea_, eb_, s, t, crossing_tol_)) return false;
  // The pair holds at most one crossing; one found outside (a neighbour's, found there too) proves
  // nothing about this pair. The margin only absorbs rounding at the piece ends.
  const double ms = 1e-9 * (x.hi - x.lo), mt = 1e-9 * (y.hi - y.lo);
  if (s < x.lo - ms || s > x.hi + ms || t < y.lo - mt || t > y.hi + mt) return false;
  record(s, t, ContactKind::transversal);
  return true;
}

void CurvePairIntersector::leaf(const BezierPiece2& x, const BezierPiece2& y) {
  double s = x.param(0.5), t = y.param(0.5), gap = 0.0;
  if (refine_tangency(ea_, eb_, s, t, gap) && gap <= tol_ && !crossed_extremum(s, t)) {
    record(s, t, ContactKind::tangent);
    return;
  }
  s = x.param(0.5);
  t = y.param(0.5);
  if (refine_crossing(ea_, eb_, s, t, crossing_tol_)) {
    record(s, t, tangent_sine(ea_, eb_, s, t) <= 1e-6 ? ContactKind::tangent : ContactKind::transversal);
    return;
  }
  end_touches(x, y);
}

void CurvePairIntersector::end_touches(const BezierPiece2& x, const BezierPiece2& y) {
  // An end or a corner of one curve within tol of the other without a crossing: the distance has a
  // local minimum there without parallel tangents.
  auto is_end = [](const std::vector<double>& ends, double u) {
    return std::binary_search(ends.begin(), ends.end(), u);
  };
  for (double u : {x.lo, x.hi})
    if (is_end(ends_a_, u)) end_touch(u, true, y.param(0.5));
  for (double u : {y.lo, y.hi})
    if (is_end(ends_b_, u)) end_touch(x.param(0.5), false, u);
}

bool CurvePairIntersector::crossed_extremum(double s, double t) {
  // Near a parallel-tangent point, in the frame of A's tangent T and normal N, the signed gap along
  // the common tangent is h(x) = h* + (kA - kB) x^2 / 2 (kB signed for B's sense relative to A's).
  // When h* and kA - kB differ in sign the curves cross twice around the point, 2 sqrt(2|h*|/|dk|)
  // apart: those crossings are the intersections, the extremum between them is not a contact.
  V2 P, dP, ddP, Q, dQ, ddQ;
  ea_.d2(s, P, dP, ddP);
  eb_.d2(t, Q, dQ, ddQ);
  const V2 N = V2(-dP.y(), dP.x()) / dP.norm();
  const double h = (P - Q).dot(N);
  if (std::abs(h) <= crossing_tol_) return false;  // an exact touch (to rounding)
  const double ka = cross(dP, ddP) / std::pow(dP.norm(), 3);
  const double kb = (dP.dot(dQ) < 0 ? -1.0 : 1.0) * cross(dQ, ddQ) / std::pow(dQ.norm(), 3);
  return h * (ka - kb) < 0.0;
}

void CurvePairIntersector::end_touch(double s, bool s_fixed, double t) {
  double d;
  if (s_fixed)
    d = project_point(eb_, ea_.point(s), t, b0_, b1_);
  else
    d = project_point(ea_, eb_.point(t), s, a0_, a1_);
  if (d <= tol_) record(s, t, tangent_sine(ea_, eb_, s, t) <= 1e-6 ? ContactKind::tangent : ContactKind::transversal);
}

bool CurvePairIntersector::covered(CurveEvaluator<2>& on, const BezierPiece2& x, CurveEvaluator<2>& other,
                                   const BezierPiece2& y, double lo, double hi, double& t0, double& t1) {
  // Cheap rejection at the midpoint first (most stalled pairs are two nearby crossings).
  double t = y.param(0.5);
  if (project_point(other, on.point(x.param(0.5)), t, lo, hi) > tol_) return false;
  const int m = 2 * (x.degree + y.degree) + 3;
  double prev = 0.0, sense = 0.0;
  for (int k = 0; k < m; ++k) {
    const V2 q = on.point(x.param(static_cast<double>(k) / (m - 1)));
    if (k == 0) {  // best of three starts for the first sample, then continuation
      double best = HUGE_VAL;
      for (double st : {0.0, 0.5, 1.0}) {
        double tt = y.param(st);
        const double d = project_point(other, q, tt, lo, hi);
        if (d < best) {
          best = d;
          t = tt;
        }
      }
      if (best > tol_) return false;
    } else if (project_point(other, q, t, lo, hi) > tol_) {
      return false;
    }
    // Coincidence, not a tangential contact: near a contact of curvatures differing by dk the gap
    // stays below tol over a length ~sqrt(8 tol / dk), which small pieces fit into; coincident
    // curves have equal curvature everywhere (here: to 1e-6 relative, or 1e-9 of the model size).
    V2 P, dP, ddP, Q, dQ, ddQ;
    on.d2(x.param(static_cast<double>(k) / (m - 1)), P, dP, ddP);
    other.d2(t, Q, dQ, ddQ);
    const double ka = cross(dP, ddP) / std::pow(dP.norm(), 3);
    const double kb = (dP.dot(dQ) < 0 ? -1.0 : 1.0) * cross(dQ, ddQ) / std::pow(dQ.norm(), 3);
    if (!(std::abs(ka - kb) <= 1e-6 * std::max(std::abs(ka), std::abs(kb)) + 1e-9 / scale_))
      return false;
    if (k == 0) {
      t0 = t;
    } else {
      const double step = t - prev;
      if (sense == 0.0) sense = step;
      if (step * sense < 0.0) return false;  // not a monotone run along the other curve
    }
    prev = t;
  }
  t1 = t;
  return t1 != t0;
}

bool CurvePairIntersector::record_overlap(const BezierPiece2& x, const BezierPiece2& y) {
  double u0, u1;
  // Projections run over the whole other curve (an overlap may straddle its segments); on one curve
  // they stay on y's side of x, or every piece would cover itself.
  if (piece_box(x).diagonal() > leaf_ && covered(ea_, x, eb_, y, self_ ? x.hi : b0_, b1_, u0, u1)) {
    overlaps_.push_back({x.lo, x.hi, u0, u1});
    return true;
  }
  if (piece_box(y).diagonal() > leaf_ && covered(eb_, y, ea_, x, a0_, self_ ? y.lo : a1_, u0, u1)) {
    if (u0 < u1)
      overlaps_.push_back({u0, u1, y.lo, y.hi});
    else
      overlaps_.push_back({u1, u0, y.hi, y.lo});
    return true;
  }
  return false;
}

void CurvePairIntersector::record(double s, double t, ContactKind kind) {
  points_.push_back({s, t, 0.5 * (ea_.point(s) + eb_.point(t)), kind});
}

bool CurvePairIntersector::trivial_self_contact(double s, double t) {
  const V2 p = ea_.point(s);
  auto stays_near = [&](double u0, double u1) {
    for (int k = 0; k <= 16; ++k)
      if ((ea_.point(u0 + (u1 - u0) * k / 16.0) - p).norm() > trivial_radius_) return false;
    return true;
  };
  if (stays_near(s, t)) return true;
  return closed_ && stays_near(t, a1_) && stays_near(a0_, s);
}

CurveCurveIntersections CurvePairIntersector::finish() {
  CurveCurveIntersections out;
  const double la = a1_ - a0_, lb = b1_ - b0_;
  // Overlap pieces from neighbouring pairs join where their parameter ranges touch (pieces split
  // down to the leaf size leave gaps far below 1e-6 of the domain).
  const double es = 1e-6 * la, et = 1e-6 * lb;
  std::sort(overlaps_.begin(), overlaps_.end(),
            [](const CurveCurveOverlap& p, const CurveCurveOverlap& q) { return p.s0 < q.s0; });
  for (const auto& o : overlaps_) {
    if (!out.overlaps.empty()) {
      auto& c = out.overlaps.back();
      const double clo = std::min(c.t0, c.t1), chi = std::max(c.t0, c.t1);
      const double olo = std::min(o.t0, o.t1), ohi = std::max(o.t0, o.t1);
      if (o.s0 <= c.s1 + es && olo <= chi + et && clo <= ohi + et) {
        if (o.s1 > c.s1) {
          c.s1 = o.s1;
          c.t1 = o.t1;
        }
        continue;
      }
    }
    out.overlaps.push_back(o);
  }
  auto in_overlap = [&](const CurveCurvePoint& p) {
    for (const auto& o : out.overlaps)
      if (p.s >= o.s0 - es && p.s <= o.s1 + es && p.t >= std::min(o.t0, o.t1) - et &&
          p.t <= std::max(o.t0, o.t1) + et)
        return true;
    return false;
  };
  // On a closed curve the end parameter names the start point: report the start.
  if (a_.is_closed(tol_))
    for (auto& p : points_)
      if (p.s >= a1_ - 1e-12 * la) p.s = a0_;
  if (!self_ && b_.is_closed(tol_))
    for (auto& p : points_)
      if (p.t >= b1_ - 1e-12 * lb) p.t = b0_;
  std::sort(points_.begin(), points_.end(), [](const CurveCurvePoint& p, const CurveCurvePoint& q) { return p.s < q.s; });
  for (const auto& p : points_) {
    if (in_overlap(p)) continue;
    if (self_ && trivial_self_contact(p.s, p.t)) continue;
    bool duplicate = false;
    for (auto& q : out.points) {
      // The same root reached from neighbouring pairs: equal to rounding, or (tangential contacts,
      // whose parameters are less sharply defined) the same point within tol.
      const bool same_params = std::abs(p.s - q.s) <= 1e-9 * la && std::abs(p.t - q.t) <= 1e-9 * lb;
      const bool same_point = (p.point - q.point).norm() <= tol_ && std::abs(p.s - q.s) <= 1e-5 * la &&
                              std::abs(p.t - q.t) <= 1e-5 * lb;
      if (same_params || same_point) {
        if (p.kind == ContactKind::tangent) q.kind = ContactKind::tangent;
        duplicate = true;
        break;
      }
    }
    if (!duplicate) out.points.push_back(p);
  }
  return out;
}

}  // namespace cg::detail
