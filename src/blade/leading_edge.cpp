#include "src/blade/leading_edge.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "src/algo/ray_curve.hpp"
#include "src/blade/planar_polyline.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg::blade {
namespace {

struct Samples {
  std::vector<Eigen::Vector2d> p;  // n points around the closed curve (no repeat)
  std::vector<double> angle;       // tangent angle (atan2 of C')
};

Samples sample(const BSplineCurve<2>& c) {
  const std::vector<double> u = detail::sample_params(c, 16);
  Samples s;
  const std::size_t n = u.size() - 1;  // the last parameter closes the loop
  s.p.resize(n), s.angle.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Vector2d d[2];
    c.derivatives(u[k], 1, d);
    s.p[k] = d[0];
    s.angle[k] = std::atan2(d[1].y(), d[1].x());
  }
  return s;
}

// Width of the sampled profile across the axis end - far, over the samples within `band` of `end`.
double end_width(const std::vector<Eigen::Vector2d>& p, const Eigen::Vector2d& end, const Eigen::Vector2d& far,
                 double band) {
  const Eigen::Vector2d t = (end - far).normalized(), nrm(-t.y(), t.x());
  const double reach = (end - far).dot(t);
  double lo = 0, hi = 0;
  for (const auto& x : p)
    if ((x - far).dot(t) >= reach - band) {
      const double w = (x - end).dot(nrm);
      lo = std::min(lo, w), hi = std::max(hi, w);
    }
  return hi - lo;
}

// Least-squares circle: Kasa's algebraic fit (linear in centre and c = R^2 - |centre|^2), then
// Gauss-Newton on the geometric residuals |p - centre| - R.
}  // namespace

EdgeCircle fit_circle(const std::vector<Eigen::Vector2d>& p) {
  const auto m = static_cast<Eigen::Index>(p.size());
  Eigen::MatrixXd A(m, 3);
  Eigen::VectorXd b(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Vector2d& q = p[static_cast<std::size_t>(k)];
    A.row(k) << 2 * q.x(), 2 * q.y(), 1;
    b(k) = q.squaredNorm();
  }
  const Eigen::Vector3d x = A.colPivHouseholderQr().solve(b);
  Eigen::Vector3d c(x(0), x(1), std::sqrt(std::max(0.0, x(2) + x.head<2>().squaredNorm())));
  for (int it = 0; it < 20; ++it) {
    Eigen::MatrixXd J(m, 3);
    Eigen::VectorXd r(m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const Eigen::Vector2d d = p[static_cast<std::size_t>(k)] - c.head<2>();
      const double dn = d.norm();
      r(k) = dn - c.z();
      J.row(k) << -d.x() / dn, -d.y() / dn, -1;
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(r);
    if (!step.allFinite()) break;
    c -= step;
    if (step.norm() <= 1e-14 * (1 + c.norm())) break;
  }
  return {c.head<2>(), c.z()};
}

namespace {

// The edge circle around sample `end`: within the contiguous run of samples closer than `reach` to it,
// the stretch turning by kTurn over the shortest arc length.
EdgeCircle edge_circle(const Samples& s, std::size_t end, double reach) {
  constexpr double kTurn = kPi / 3;
  const std::size_t n = s.p.size();
  const auto e = static_cast<std::ptrdiff_t>(end), N = static_cast<std::ptrdiff_t>(n);
  const auto idx = [&](std::ptrdiff_t k) { return static_cast<std::size_t>((k % N + N) % N); };
  auto inside = [&](std::ptrdiff_t k) { return (s.p[idx(k)] - s.p[end]).norm() < reach; };
  std::ptrdiff_t lo = e, hi = e;
  while (hi - lo < N - 1 && inside(lo - 1)) --lo;
  while (hi - lo < N - 1 && inside(hi + 1)) ++hi;
  // The run's points with tangent angles unwrapped and arc lengths accumulated along it.
  std::vector<double> ang, len;
  std::vector<Eigen::Vector2d> pts;
  for (std::ptrdiff_t k = lo; k <= hi; ++k) {
    const std::size_t i = idx(k);
    pts.push_back(s.p[i]);
    double a = s.angle[i];
    if (!ang.empty()) a += 2 * kPi * std::round((ang.back() - a) / (2 * kPi));
    ang.push_back(a);
    len.push_back(len.empty() ? 0.0 : len.back() + (pts[pts.size() - 1] - pts[pts.size() - 2]).norm());
  }
  std::size_t best_a = 0, best_b = pts.size() - 1;
  double best_len = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0, b = 0; a < pts.size(); ++a) {
    b = std::max(b, a);
    while (b + 1 < pts.size() && std::abs(ang[b] - ang[a]) < kTurn) ++b;
    if (std::abs(ang[b] - ang[a]) < kTurn) break;  // no stretch turning enough from here on
    if (len[b] - len[a] < best_len) best_len = len[b] - len[a], best_a = a, best_b = b;
  }
  return fit_circle(std::vector<Eigen::Vector2d>(pts.begin() + static_cast<std::ptrdiff_t>(best_a),
                                                 pts.begin() + static_cast<std::ptrdiff_t>(best_b) + 1));
}

}  // namespace

LeadingTrailingEdge detect_leading_trailing_edge(const BSplineCurve<2>& c) {
  require(c.is_periodic(), "LE/TE detection: the section curve must be closed (periodic)");
  const Samples s = sample(c);
  const std::vector<Eigen::Vector2d>& p = s.p;
  // Longest extent among the samples: the first pair (i < j) of greatest distance. Pairs that cannot
  // reach a known lower bound of it (|pi - pj| <= |pi - m| + |pj - m|, m the samples' mean; the bound
  // is the farthest sample from the one farthest from m) are skipped, so dense sections (an imported
  // CAD blade's cuts) do not pay n^2 distances; the pair found is the plain double loop's.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : p) mean += q;
  mean /= static_cast<double>(p.size());
  std::vector<double> rad(p.size());
  std::size_t far = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    rad[i] = (p[i] - mean).norm();
    if (rad[i] > rad[far]) far = i;
  }
  double lower = 0;
  for (const auto& q : p) lower = std::max(lower, (q - p[far]).norm());
  const double cut = lower * (1 - 1e-9);  // rounding margin: never skips a pair that could tie
  std::size_t bi = 0, bj = 0;
  double d2 = -1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (rad[i] + rad[far] < cut) continue;  // rad[far] is the largest r
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (rad[i] + rad[j] < cut) continue;
      const double d = (p[i] - p[j]).squaredNorm();
      if (d > d2) d2 = d, bi = i, bj = j;
    }
  }
  const double extent = std::sqrt(d2);
  if (end_width(p, p[bj], p[bi], 0.05 * extent) > end_width(p, p[bi], p[bj], 0.05 * extent)) std::swap(bi, bj);
  // Now bi is the LE end, bj the TE end.
  LeadingTrailingEdge r;
  r.le_circle = edge_circle(s, bi, 0.3 * extent);
  r.te_circle = edge_circle(s, bj, 0.3 * extent);
  return edge_points(c, r.le_circle, r.te_circle);
}

LeadingTrailingEdge edge_points(const BSplineCurve<2>& c, const EdgeCircle& le, const EdgeCircle& te) {
  LeadingTrailingEdge r;
  r.le_circle = le;
  r.te_circle = te;
  const Eigen::Vector2d dir = r.le_circle.centre - r.te_circle.centre;
  if (!(dir.norm() > 0))
    throw AlgorithmFailure("LE/TE detection: the leading- and trailing-edge circles have the same centre");
  const std::vector<RayCurveHit<2>> hits =
      line_curve_intersections(c, r.te_circle.centre, dir, -std::numeric_limits<double>::infinity());
  if (hits.size() < 2 || !(hits.back().ray_param > 1) || !(hits.front().ray_param < 0))
    throw AlgorithmFailure("LE/TE detection: the line through the edge circle centres does not cross the profile "
                           "beyond both centres");
  r.le_param = c.check_param(hits.back().curve_param);
  r.te_param = c.check_param(hits.front().curve_param);
  return r;
}

}  // namespace cg::blade
