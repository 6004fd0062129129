#include "src/blade/planar_polyline.hpp"

#include <algorithm>
#include <cmath>

namespace cg::blade::detail {

bool segment_intersection(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                          const Eigen::Vector2d& b1, double eps, double& s, double& t) {
  const Eigen::Vector2d da = a1 - a0, db = b1 - b0, w = b0 - a0;
  const double den = da.x() * db.y() - da.y() * db.x();
  if (std::abs(den) <= 1e-300 || std::abs(den) <= 1e-14 * da.norm() * db.norm()) return false;
  s = (w.x() * db.y() - w.y() * db.x()) / den;
  t = (w.x() * da.y() - w.y() * da.x()) / den;
  return s >= -eps && s <= 1 + eps && t >= -eps && t <= 1 + eps;
}

std::vector<SegmentHit> polyline_crossings(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b,
                                           double eps) {
  std::vector<SegmentHit> hits;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const Eigen::Vector2d alo = a[i].cwiseMin(a[i + 1]), ahi = a[i].cwiseMax(a[i + 1]);
    const Eigen::Vector2d pad = (ahi - alo) * eps + Eigen::Vector2d::Constant(1e-300);
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      const Eigen::Vector2d blo = b[j].cwiseMin(b[j + 1]), bhi = b[j].cwiseMax(b[j + 1]);
      const Eigen::Vector2d bpad = (bhi - blo) * eps;
      if ((blo - bpad - ahi - pad).maxCoeff() > 0 || (alo - pad - bhi - bpad).maxCoeff() > 0) continue;
      double s, t;
      if (segment_intersection(a[i], a[i + 1], b[j], b[j + 1], eps, s, t))
        hits.push_back({static_cast<int>(i), static_cast<int>(j), s, t});
    }
  }
  return hits;
}

bool polygon_is_simple(const std::vector<Eigen::Vector2d>& points, int& edge_a, int& edge_b) {
  std::vector<Eigen::Vector2d> closed = points;
  closed.push_back(points.front());
  const int n = static_cast<int>(points.size());
  for (const auto& h : polyline_crossings(closed, closed, 0.0)) {
    const int d = std::abs(h.i - h.j);
    if (d <= 1 || d == n - 1) continue;  // the same or adjacent edges
    edge_a = h.i, edge_b = h.j;
    return false;
  }
  return true;
}

std::vector<double> sample_params(const BSplineCurve<2>& curve, int per_span) {
  std::vector<double> u;
  const auto& U = curve.knots();
  for (int i = curve.degree(); i < curve.num_poles(); ++i) {
    const double a = U[static_cast<std::size_t>(i)], b = U[static_cast<std::size_t>(i) + 1];
    if (b <= a) continue;
    for (int k = 0; k < per_span; ++k) u.push_back(a + (b - a) * k / per_span);
  }
  u.push_back(curve.last_param());
  return u;
}

double polygon_signed_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& q = p[(i + 1) % p.size()];
    a += p[i].x() * q.y() - q.x() * p[i].y();
  }
  return a / 2;
}

}  // namespace cg::blade::detail
