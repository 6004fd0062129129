#include "src/blade/edge_arcs.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"
#include "src/modify/degree_elevation.hpp"
#include "src/modify/reparametrize.hpp"

namespace cg::blade::detail {
namespace {

double residual(const std::vector<Eigen::Vector2d>& p, const EdgeCircle& c) {
  double r = 0;
  for (const auto& q : p) r = std::max(r, std::abs((q - c.centre).norm() - c.radius));
  return r;
}

// Circle of given radius closest to the points: Gauss-Newton on the centre from `start`.
EdgeCircle fit_centre(const std::vector<Eigen::Vector2d>& p, double radius, Eigen::Vector2d c) {
  for (int it = 0; it < 30; ++it) {
    Eigen::MatrixXd J(static_cast<Eigen::Index>(p.size()), 2);
    Eigen::VectorXd r(static_cast<Eigen::Index>(p.size()));
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Eigen::Vector2d d = p[k] - c;
      const double dn = d.norm();
      r(static_cast<Eigen::Index>(k)) = dn - radius;
      J.row(static_cast<Eigen::Index>(k)) << -d.x() / dn, -d.y() / dn;
    }
    const Eigen::Vector2d step = J.colPivHouseholderQr().solve(r);
    if (!step.allFinite()) break;
    c -= step;
    if (step.norm() <= 1e-14 * (1 + c.norm())) break;
  }
  return {c, radius};
}

// Points of the run [first, first + count) (cyclic).
std::vector<Eigen::Vector2d> run_points(const std::vector<Eigen::Vector2d>& p, int first, int count) {
  const int n = static_cast<int>(p.size());
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < count; ++k) out.push_back(p[static_cast<std::size_t>(((first + k) % n + n) % n)]);
  return out;
}


// Clamped cubic pieces of the profile, each with its length (for the parameter intervals).
struct Piece {
  BSplineCurve<2> curve;
  double length;
};

// The arc of a run: its start angle and signed sweep (from the first point through the others to the
// last), continued at each end towards the neighbouring given point (`before`, `after`): up to where the
// tangent from that point touches the circle, which is where a side that runs on straight would leave
// it, but by no more than the run's own point spacing (a table would have had another point there).
struct ArcSpan {
  double start = 0, sweep = 0;
};

// Extension (>= 0, rad) from angle `from`, moving in direction `dir` (+1 counter-clockwise), to the
// touching point of the tangent from q; 0 when q is inside the circle or the touching point lies behind.
double tangent_extension(const EdgeCircle& c, const Eigen::Vector2d& q, double from, double dir, double cap) {
  const Eigen::Vector2d d = q - c.centre;
  if (d.norm() <= c.radius) return 0;
  const double base = std::atan2(d.y(), d.x()), alpha = std::acos(c.radius / d.norm());
  double best = 0;
  for (double t : {base + alpha, base - alpha}) {
    const double e = std::remainder(dir * (t - from), 2 * kPi);
    if (e > 0 && (best == 0 || e < best)) best = e;
  }
  return std::min(best, cap);
}

ArcSpan arc_span(const std::vector<Eigen::Vector2d>& run, const EdgeCircle& c, const Eigen::Vector2d& before,
                 const Eigen::Vector2d& after) {
  ArcSpan a;
  for (std::size_t k = 0; k + 1 < run.size(); ++k) {
    const Eigen::Vector2d u = run[k] - c.centre, v = run[k + 1] - c.centre;
    a.sweep += std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  }
  const Eigen::Vector2d a0 = run.front() - c.centre;
  a.start = std::atan2(a0.y(), a0.x());
  const double dir = a.sweep > 0 ? 1 : -1, cap = std::abs(a.sweep) / static_cast<double>(run.size() - 1);
  const double head = tangent_extension(c, before, a.start, -dir, cap);
  const double tail = tangent_extension(c, after, a.start + a.sweep, dir, cap);
  a.start -= dir * head;
  a.sweep += dir * (head + tail);
  return a;
}

Eigen::Vector2d at_angle(const EdgeCircle& c, double a) {
  return c.centre + c.radius * Eigen::Vector2d(std::cos(a), std::sin(a));
}

// The arc as rational quadratic pieces of at most 90 deg with double knots (A7.1), elevated to degree 3;
// t0, t1 are its unit tangents (direction of travel) at both ends.
Piece arc_piece(const EdgeCircle& c, const ArcSpan& span, Eigen::Vector2d& t0, Eigen::Vector2d& t1) {
  const double start = span.start, sweep = span.sweep;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (0.5 * kPi) - 1e-9)));
  const double d = sweep / pieces, w = std::cos(0.5 * d);
  std::vector<Eigen::Vector2d> poles;
  std::vector<double> weights, knots{0, 0, 0};
  for (int j = 0; j < pieces; ++j) {
    const double a = start + j * d, mid = a + 0.5 * d;
    if (j == 0) poles.push_back(at_angle(c, a)), weights.push_back(1);
    poles.push_back(c.centre + c.radius / w * Eigen::Vector2d(std::cos(mid), std::sin(mid)));
    weights.push_back(w);
    poles.push_back(at_angle(c, a + d));
    weights.push_back(1);
    if (j > 0) knots.push_back(static_cast<double>(j) / pieces), knots.push_back(static_cast<double>(j) / pieces);
  }
  knots.insert(knots.end(), {1, 1, 1});
  const double sense = sweep > 0 ? 1 : -1;
  t0 = sense * Eigen::Vector2d(-std::sin(start), std::cos(start));
  t1 = sense * Eigen::Vector2d(-std::sin(start + sweep), std::cos(start + sweep));
  return {elevate_degree(BSplineCurve<2>(2, knots, poles, weights), 1), c.radius * std::abs(sweep)};
}

// Cubic spline through `pts` leaving pts.front() along t0 and arriving at pts.back() along t1.
Piece side_piece(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& t0, const Eigen::Vector2d& t1) {
  double L = 0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) L += (pts[k + 1] - pts[k]).norm();
  // Parameters on [0, 1]: derivatives of length L match a parametrisation proportional to arc length.
  return {interpolate_end_derivatives<2>(pts, L * t0, L * t1, 3, ParamMethod::ChordLength), L};
}

}  // namespace

EdgeCircleRun find_edge_circle(const std::vector<Eigen::Vector2d>& p, int apex, const EdgeCircleHint& hint,
                               double max_radius, double tol) {
  const int n = static_cast<int>(p.size());
  EdgeCircleRun best;
  if (n < 8) return best;  // a run must leave 4 points for the sides
  auto circle_of = [&](const std::vector<Eigen::Vector2d>& q) {
    if (hint.centre) {
      const double R = hint.radius > 0 ? hint.radius : (p[static_cast<std::size_t>(apex)] - *hint.centre).norm();
      return EdgeCircle{*hint.centre, R};
    }
    const EdgeCircle free = fit_circle(q);
    return hint.radius > 0 ? fit_centre(q, hint.radius, free.centre) : free;
  };
  auto consider = [&](int first, int count) {
    const std::vector<Eigen::Vector2d> q = run_points(p, first, count);
    const EdgeCircle c = circle_of(q);
    const double r = residual(q, c);
    return std::make_pair(r <= tol && std::isfinite(c.radius) && c.radius > 0 && c.radius <= max_radius,
                          EdgeCircleRun{true, first, count, c, r});
  };
  const int seed = hint.centre ? 1 : 3;
  for (int start = apex - seed + 1 - 2; start <= apex + 2; ++start) {
    auto [ok, run] = consider(start, seed);
    if (!ok) continue;
    for (;;) {  // grow by the neighbour that keeps the smaller residual
      if (run.count >= n - 4) break;
      const auto left = consider(run.first - 1, run.count + 1), right = consider(run.first, run.count + 1);
      if (left.first && (!right.first || left.second.residual <= right.second.residual))
        run = left.second;
      else if (right.first)
        run = right.second;
      else
        break;
    }
    const int needed = hint.centre ? 2 : hint.radius > 0 ? 3 : 4;
    if (run.count < needed) continue;
    if (!best.found || run.count > best.count || (run.count == best.count && run.residual < best.residual)) best = run;
  }
  if (best.found) best.first = ((best.first % n) + n) % n;
  return best;
}

double deviation_from_circle(const BSplineCurve<2>& curve, double a, double b, const EdgeCircle& circle) {
  int spans = 0;
  for (double k : curve.knots())
    if (k > a && k < b) ++spans;
  const int m = 64 * (spans + 1);
  double worst = 0;
  for (int i = 0; i <= m; ++i) {
    const Eigen::Vector2d q = curve.point(curve.check_param(a + (b - a) * i / m));
    worst = std::max(worst, std::abs((q - circle.centre).norm() - circle.radius));
  }
  return worst;
}

BSplineCurve<2> profile_with_arcs(const std::vector<Eigen::Vector2d>& points, const std::vector<EdgeCircleRun>& runs) {
  const int n = static_cast<int>(points.size());
  require(!runs.empty() && runs.size() <= 2, "profile_with_arcs: one or two edge circles are needed");
  // Rotate the points so the first run starts at index 0, and order the runs along the profile.
  const int shift = runs.front().first;
  std::vector<Eigen::Vector2d> p(points.size());
  for (int k = 0; k < n; ++k) p[static_cast<std::size_t>(k)] = points[static_cast<std::size_t>((k + shift) % n)];
  std::vector<EdgeCircleRun> r = runs;
  for (auto& x : r) x.first = ((x.first - shift) % n + n) % n;
  std::sort(r.begin(), r.end(), [](const EdgeCircleRun& a, const EdgeCircleRun& b) { return a.first < b.first; });
  require(r.size() == 1 || r[0].first + r[0].count <= r[1].first, "profile_with_arcs: the edge circles overlap");
  require(r.back().first + r.back().count <= n, "profile_with_arcs: the edge circles overlap");

  // Pieces: arc, side, (arc, side); each side runs from an arc's end to the next arc's start through the
  // given points in between.
  std::vector<ArcSpan> spans;
  for (const EdgeCircleRun& x : r)
    spans.push_back(arc_span(run_points(p, x.first, x.count), x.circle, p[static_cast<std::size_t>((x.first - 1 + n) % n)],
                             p[static_cast<std::size_t>((x.first + x.count) % n)]));
  std::vector<Piece> pieces;
  std::vector<Eigen::Vector2d> t_start(r.size()), t_end(r.size());
  std::vector<Piece> arcs;
  for (std::size_t j = 0; j < r.size(); ++j) arcs.push_back(arc_piece(r[j].circle, spans[j], t_start[j], t_end[j]));
  for (std::size_t j = 0; j < r.size(); ++j) {
    pieces.push_back(arcs[j]);
    const std::size_t k = (j + 1) % r.size();  // the next arc (the first again after the last)
    const int from = r[j].first + r[j].count, to = k == 0 ? n : r[k].first;  // side points [from, to)
    std::vector<Eigen::Vector2d> side{at_angle(r[j].circle, spans[j].start + spans[j].sweep)};
    for (int i = from; i < to; ++i) side.push_back(p[static_cast<std::size_t>(i % n)]);
    side.push_back(at_angle(r[k].circle, spans[k].start));
    pieces.push_back(side_piece(side, t_end[j], t_start[k]));
  }

  // Concatenate: each piece on an interval proportional to its length, C0 knots (multiplicity 3) at the
  // joins; the shared end poles (weight 1 on both sides) stored once.
  double total = 0;
  for (const Piece& q : pieces) total += q.length;
  std::vector<double> period_knots{0, 0, 0};
  std::vector<Eigen::Vector2d> poles;
  std::vector<double> weights;
  double s0 = 0;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const BSplineCurve<2>& c = pieces[j].curve;
    const double a = c.first_param(), b = c.last_param(), len = pieces[j].length / total;
    const auto& K = c.knots();
    for (std::size_t k = 4; k + 4 < K.size(); ++k) period_knots.push_back(s0 + len * (K[k] - a) / (b - a));
    s0 += len;
    if (j + 1 < pieces.size()) period_knots.insert(period_knots.end(), {s0, s0, s0});
    for (int i = 0; i + 1 < c.num_poles(); ++i) {  // the last pole is the next piece's first
      poles.push_back(c.pole(i));
      weights.push_back(c.weight(i));
    }
  }
  // With the seam knot of multiplicity 3 first, the periodic form's pole 2 is the curve's start (the
  // unwrapped span at the seam uses poles 2..5): rotate the poles by 2.
  const std::size_t m = poles.size();
  std::vector<Eigen::Vector2d> P(m);
  std::vector<double> W(m);
  for (std::size_t i = 0; i < m; ++i) P[(i + 2) % m] = poles[i], W[(i + 2) % m] = weights[i];
  return BSplineCurve<2>::periodic(3, period_knots, 1.0, P, W);
}

}  // namespace cg::blade::detail
