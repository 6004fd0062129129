#include "src/blade/camber_edges.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "src/algo/ray_curve.hpp"
#include "src/blade/planar_polyline.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade {
namespace {

// The whole profile sampled once (32 points per knot span, no repeat), with unit tangents and its
// orientation (+1 counter-clockwise: the inward normal is left of the tangent).
struct Outline {
  std::vector<Eigen::Vector2d> p, tangent;
  double orientation = 1;
};

Outline outline_of(const BSplineCurve<2>& curve) {
  const std::vector<double> u = detail::sample_params(curve, 32);
  Outline o;
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {  // the last parameter closes the loop
    Eigen::Vector2d d[2];
    curve.derivatives(u[k], 1, d);
    o.p.push_back(d[0]);
    o.tangent.push_back(d[1].normalized());
  }
  o.orientation = detail::polygon_signed_area(o.p) > 0 ? 1.0 : -1.0;
  return o;
}

// The samples of one edge's neighbourhood: the contiguous run around the edge point within `reach` of
// the edge circle's centre, at least `spacing` apart, with inward normals and arc lengths along the run.
struct EdgeRun {
  std::vector<Eigen::Vector2d> p, inward;
  std::vector<double> s;
};

EdgeRun edge_run(const Outline& outline, const Eigen::Vector2d& apex_point, const Eigen::Vector2d& centre, double reach,
                 double spacing) {
  const std::vector<Eigen::Vector2d>& pt = outline.p;
  const std::vector<Eigen::Vector2d>& tan = outline.tangent;
  const auto n = static_cast<std::ptrdiff_t>(pt.size());
  std::ptrdiff_t apex = 0;
  for (std::ptrdiff_t k = 1; k < n; ++k)
    if ((pt[static_cast<std::size_t>(k)] - apex_point).squaredNorm() < (pt[static_cast<std::size_t>(apex)] - apex_point).squaredNorm())
      apex = k;
  const auto idx = [&](std::ptrdiff_t k) { return static_cast<std::size_t>((k % n + n) % n); };
  auto inside = [&](std::ptrdiff_t k) { return (pt[idx(k)] - centre).norm() < reach; };
  std::ptrdiff_t lo = apex, hi = apex;
  while (hi - lo < n - 1 && inside(lo - 1)) --lo;
  while (hi - lo < n - 1 && inside(hi + 1)) ++hi;
  EdgeRun r;
  double s = 0;
  for (std::ptrdiff_t k = lo; k <= hi; ++k) {
    const Eigen::Vector2d& q = pt[idx(k)];
    if (!r.p.empty()) {
      const double step = (q - r.p.back()).norm();
      if (step < spacing && k != hi) continue;
      s += step;
    }
    const Eigen::Vector2d& t = tan[idx(k)];
    r.p.push_back(q);
    r.inward.push_back(outline.orientation * Eigen::Vector2d(-t.y(), t.x()));
    r.s.push_back(s);
  }
  return r;
}

// Centre of the circle inscribed in the profile that touches it at run sample i: the largest rho (at
// most `limit`) for which p_i + rho n_i is at least rho from every run sample farther than `gap` along
// the run; none when even a circle of radius `limit` stays clear of the run.
std::optional<Eigen::Vector2d> inscribed_centre(const EdgeRun& r, std::size_t i, double gap, double limit) {
  auto dist = [&](const Eigen::Vector2d& x) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < r.p.size(); ++j)
      if (std::abs(r.s[j] - r.s[i]) >= gap) d = std::min(d, (r.p[j] - x).norm());
    return d;
  };
  double lo = 0, hi = limit;
  if (dist(r.p[i] + hi * r.inward[i]) > hi) return std::nullopt;  // no opposite side within reach
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (dist(r.p[i] + mid * r.inward[i]) > mid ? lo : hi) = mid;
  }
  return r.p[i] + lo * r.inward[i];
}

// A camber line near an edge in the edge's frame: the point at depth x (from the edge circle's centre c
// inwards along -out) is c - x out + y(x) across, y a quadratic.
struct EdgeCamber {
  Eigen::Vector2d c, out, across;
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  Eigen::Vector2d at(double x) const { return c - x * out + (q(0) + x * (q(1) + x * q(2))) * across; }
  Eigen::Vector2d tangent(double x) const { return (-out + (q(1) + 2 * x * q(2)) * across).normalized(); }
  // Least squares through points given in the world frame.
  void fit(const std::vector<Eigen::Vector2d>& pts) {
    Eigen::MatrixXd A(static_cast<Eigen::Index>(pts.size()), 3);
    Eigen::VectorXd b(static_cast<Eigen::Index>(pts.size()));
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const double x = (c - pts[k]).dot(out);
      A.row(static_cast<Eigen::Index>(k)) << 1, x, x * x;
      b(static_cast<Eigen::Index>(k)) = (pts[k] - c).dot(across);
    }
    q = A.colPivHouseholderQr().solve(b);
  }
};

[[noreturn]] void not_followed(const char* name, const std::string& why) {
  throw InvalidGeometry(std::string("the camber line at the ") + name + " could not be followed: " + why);
}

// First estimate: the medial axis, the centres of the inscribed circles up to 3 radii deep.
EdgeCamber medial_camber(const Outline& outline, const Eigen::Vector2d& apex, const EdgeCircle& circle,
                         const Eigen::Vector2d& out, const char* name) {
  const double R = circle.radius;
  EdgeCamber cam{circle.centre, out, Eigen::Vector2d(-out.y(), out.x())};
  const EdgeRun run = edge_run(outline, apex, cam.c, 4 * R, R / 40);
  std::vector<Eigen::Vector2d> centres;
  double deepest = 0;
  for (std::size_t i = 0; i < run.p.size(); i += 4) {
    const std::optional<Eigen::Vector2d> m = inscribed_centre(run, i, R / 2, 4 * R);
    if (!m) continue;
    const double x = (cam.c - *m).dot(out);
    if (x >= -0.25 * R && x <= 3 * R) centres.push_back(*m), deepest = std::max(deepest, x);
  }
  if (centres.size() < 6 || deepest < 1.5 * R)
    not_followed(name, std::to_string(centres.size()) + " inscribed circles up to " + format_number(deepest) +
                           " mm deep behind the edge circle of radius " + format_number(R) + " mm");
  cam.fit(centres);
  return cam;
}

// The camber line as the midpoints of the profile's chords normal to it (a profile built as camber +-
// thickness along the camber's normal has exactly these), 12 chords from depth R / 8 to 1.5 R: six
// rounds, each casting the normals of the previous fit in a frame turned to its direction at depth 0.
void refine_by_normal_chords(const BSplineCurve<2>& curve, EdgeCamber& cam, double R, const char* name) {
  for (int round = 0; round < 6; ++round) {
    std::vector<Eigen::Vector2d> mids;
    for (int j = 1; j <= 12; ++j) {
      const double x = R * j / 8.0;
      const Eigen::Vector2d o = cam.at(x), t = cam.tangent(x), n(-t.y(), t.x());
      const std::vector<RayCurveHit<2>> hits = line_curve_intersections(curve, o, n, -4 * R, 4 * R);
      const RayCurveHit<2>* below = nullptr;
      const RayCurveHit<2>* above = nullptr;
      for (const auto& h : hits)
        if (h.ray_param < 0) below = &h;
        else if (!above) above = &h;
      if (below && above) mids.push_back(o + 0.5 * (below->ray_param + above->ray_param) * n);
    }
    if (mids.size() < 6)
      not_followed(name, "only " + std::to_string(mids.size()) + " of 12 chords normal to it up to " +
                             format_number(1.5 * R) + " mm deep cross the profile");
    cam.out = -cam.tangent(0);  // the frame follows the camber line (depth along it)
    cam.across = Eigen::Vector2d(-cam.out.y(), cam.out.x());
    cam.fit(mids);
  }
}

// The parameter where the camber line of the edge with circle `circle` and outward direction `out`
// meets the profile.
double camber_end(const BSplineCurve<2>& curve, const Outline& outline, double apex_param, const EdgeCircle& circle,
                  const Eigen::Vector2d& out, const char* name) {
  const double R = circle.radius;
  EdgeCamber cam = medial_camber(outline, curve.point(apex_param), circle, out, name);
  refine_by_normal_chords(curve, cam, R, name);
  // The line from cam.at(0) through cam.at(x) meets the profile at depth x' (< 0); at the fixed point
  // x' = x the hit is on the camber line itself.
  double x = -R, param = 0;
  for (int it = 0; it < 20; ++it) {
    const Eigen::Vector2d o = cam.at(0), d = (cam.at(x) - o).normalized();
    const std::vector<RayCurveHit<2>> hits = line_curve_intersections(curve, o, d, 0, 4 * R);
    if (hits.empty()) not_followed(name, "it does not meet the profile within " + format_number(4 * R) + " mm");
    param = hits.front().curve_param;
    const double next = (cam.c - curve.point(param)).dot(out);
    if (std::abs(next - x) < 1e-10 * R) break;
    x = next;
  }
  return curve.check_param(param);
}

}  // namespace

LeadingTrailingEdge camber_edge_points(const BSplineCurve<2>& curve, const LeadingTrailingEdge& centre_line) {
  const Outline outline = outline_of(curve);
  const Eigen::Vector2d out = (centre_line.le_circle.centre - centre_line.te_circle.centre).normalized();
  LeadingTrailingEdge r = centre_line;
  r.le_param = camber_end(curve, outline, centre_line.le_param, centre_line.le_circle, out, "LE");
  r.te_param = camber_end(curve, outline, centre_line.te_param, centre_line.te_circle, -out, "TE");
  return r;
}

}  // namespace cg::blade
