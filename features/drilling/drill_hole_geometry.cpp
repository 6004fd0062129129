#include "features/drilling/drill_hole_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "src/blade/curve_integral.hpp"
#include "src/core/constants.hpp"
#include "src/core/newton.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::features {
namespace {

constexpr double kResidual = 1e-10;  // mm: a line/surface hit counts as exact below this
constexpr int kDegree = 5;          // quintic interpolants: error O(h^6), a third of the nodes of cubics at 1e-7 mm

}  // namespace

HoleCylinder HoleCylinder::from_axis(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double radius,
                                     double length) {
  HoleCylinder h;
  h.o = origin;
  h.d = axis.normalized();
  // e1: the coordinate axis least aligned with d, made perpendicular.
  Eigen::Index k;
  h.d.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d a = Eigen::Vector3d::Unit(k);
  h.e1 = (a - a.dot(h.d) * h.d).normalized();
  h.e2 = h.d.cross(h.e1);
  h.radius = radius;
  h.length = length;
  return h;
}

WallSurface::WallSurface(std::shared_ptr<const BSplineSurface<3>> surface)
    : surface_(std::move(surface)), ev_(surface_), caster_(*surface_) {}

bool WallSurface::solve(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double& t, double& u, double& v) {
  const BSplineSurface<3>& s = *surface_;
  newton::Domain<3> dom;
  dom.lo << -std::numeric_limits<double>::infinity(), s.first_u(), s.first_v();
  dom.hi << std::numeric_limits<double>::infinity(), s.last_u(), s.last_v();
  const newton::Vec<3> scale(1.0, s.last_u() - s.first_u(), s.last_v() - s.first_v());
  newton::SystemOptions opt;
  opt.residual_tol = 1e-12;
  Eigen::Vector3d P, Su, Sv;
  const auto f = [&](const newton::Vec<3>& x, newton::Vec<3>& F, newton::Mat<3>& J) {
    ev_.d1(x[1], x[2], P, Su, Sv);
    F = p + x[0] * d - P;
    J.col(0) = d;
    J.col(1) = -Su;
    J.col(2) = -Sv;
  };
  const newton::SystemResult<3> r = newton::solve_system<3>(f, newton::Vec<3>(t, u, v), dom, scale, opt);
  t = r.x[0], u = r.x[1], v = r.x[2];
  return (p + t * d - ev_.point(u, v)).norm() <= kResidual;
}

RaySurfaceHit WallSurface::first_hit(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double t_max) {
  return caster_.first_hit(p, d, t_max);
}

Eigen::Vector3d WallSurface::unit_normal(double u, double v) {
  Eigen::Vector3d P, Su, Sv;
  ev_.d1(u, v, P, Su, Sv);
  return Su.cross(Sv).normalized();
}

namespace {

// Solves the ruling at theta, radius rho, continuing from `x` (t, u, v).
bool solve_ruling(WallSurface& wall, const HoleCylinder& h, double theta, double rho, Eigen::Vector3d& x) {
  return wall.solve(h.ruling(theta, rho), h.d, x[0], x[1], x[2]);
}

// Walks from the axis hit out to radius rho along theta0 (small steps keep Newton in its basin).
bool walk_out(WallSurface& wall, const HoleCylinder& h, const AxisHit& a, double theta0, double rho,
              Eigen::Vector3d& x) {
  x = Eigen::Vector3d(a.t, a.u, a.v);
  constexpr int kSteps = 4;
  for (int j = 1; j <= kSteps; ++j)
    if (!solve_ruling(wall, h, theta0, rho * j / kSteps, x)) return false;
  return true;
}

// The loop's nodes at theta_k = 2 pi k / n: x_k = (t, u, v). False when a ruling is lost or the walk
// around does not come back to its start (it jumped to another sheet of the surface).
bool loop_nodes(WallSurface& wall, const HoleCylinder& h, const AxisHit& a, int n, std::vector<Eigen::Vector3d>& x) {
  x.resize(static_cast<std::size_t>(n));
  if (!walk_out(wall, h, a, 0, h.radius, x[0])) return false;
  Eigen::Vector3d y = x[0];
  for (int k = 1; k <= n; ++k) {
    if (!solve_ruling(wall, h, 2 * kPi * k / n, h.radius, y)) return false;
    if (k < n) x[static_cast<std::size_t>(k)] = y;
  }
  return (y - x[0]).norm() <= 1e-9;
}

BSplineCurve<2> closed_fit(const std::vector<Eigen::Vector2d>& p, const std::vector<double>& params,
                           const std::vector<double>& knots) {
  return interpolate_closed<2>(p, kDegree, params, knots);
}

}  // namespace

HoleLoop hole_loop(WallSurface& wall, const HoleCylinder& h, const AxisHit& a, double fit_tolerance) {
  HoleLoop L;
  std::vector<Eigen::Vector3d> x;
  for (int n = 16; n <= 512; n *= 2) {
    if (!loop_nodes(wall, h, a, n, x)) {
      L.failure = "the loop on the wall could not be followed (Newton lost a ruling line)";
      return L;
    }
    std::vector<double> params(static_cast<std::size_t>(n));
    PointList<3> pts(static_cast<std::size_t>(n));
    PointList<2> uv(static_cast<std::size_t>(n)), tc(static_cast<std::size_t>(n));
    L.min_sin_incidence = 1;
    L.t_min = HUGE_VAL, L.t_max = -HUGE_VAL;
    for (int k = 0; k < n; ++k) {
      const std::size_t i = static_cast<std::size_t>(k);
      params[i] = static_cast<double>(k) / n;
      pts[i] = h.ruling(2 * kPi * params[i], h.radius) + x[i][0] * h.d;
      uv[i] = Eigen::Vector2d(x[i][1], x[i][2]);
      tc[i] = Eigen::Vector2d(0, x[i][0]);
      L.min_sin_incidence = std::min(L.min_sin_incidence, std::abs(h.d.dot(wall.unit_normal(x[i][1], x[i][2]))));
      L.t_min = std::min(L.t_min, x[i][0]);
      L.t_max = std::max(L.t_max, x[i][0]);
    }
    const std::vector<double> knots = periodic_interpolation_knots(params, kDegree);
    L.nodes = n;
    L.curve = interpolate_closed<3>(pts, kDegree, params, knots);
    L.pcurve = closed_fit(uv, params, knots);
    L.cylinder_pcurve = closed_fit(tc, params, knots);
    L.start = pts[0];
    // Deviation between the nodes: the exact loop point there against each curve's point.
    L.deviation = 0;
    bool lost = false;
    for (int k = 0; k < n && !lost; ++k) {
      const double s = (k + 0.5) / n, theta = 2 * kPi * s;
      Eigen::Vector3d y = x[static_cast<std::size_t>(k)];
      if (!solve_ruling(wall, h, theta, h.radius, y)) {
        lost = true;
        break;
      }
      const Eigen::Vector3d exact = h.ruling(theta, h.radius) + y[0] * h.d;
      const Eigen::Vector2d q = L.pcurve.point(s);
      const double tc_s = L.cylinder_pcurve.point(s)[1];
      L.deviation = std::max({L.deviation, (L.curve.point(s) - exact).norm(), (wall.point(q[0], q[1]) - exact).norm(),
                              (h.ruling(theta, h.radius) + tc_s * h.d - exact).norm()});
    }
    if (lost) {
      L.failure = "the loop on the wall could not be followed between the nodes";
      return L;
    }
    if (L.deviation <= fit_tolerance) break;
  }
  L.ok = true;
  return L;
}

bool ring_parameters(WallSurface& wall, const HoleCylinder& h, const AxisHit& a, double rho, int count,
                     std::vector<Eigen::Vector2d>& uv) {
  uv.clear();
  Eigen::Vector3d y;
  if (!walk_out(wall, h, a, 0, rho, y)) return false;
  for (int k = 0; k < count; ++k) {
    if (k > 0 && !solve_ruling(wall, h, 2 * kPi * k / count, rho, y)) return false;
    uv.emplace_back(y[1], y[2]);
  }
  return true;
}

double quadrature_volume(WallSurface& entry, const AxisHit& ea, WallSurface& exit, const AxisHit& xa,
                         const HoleCylinder& h, int angles) {
  using blade::detail::kGaussLegendre8Nodes;
  using blade::detail::kGaussLegendre8Weights;
  // Radius nodes on [0, r] in increasing order (the rule's nodes on [-1, 1] are mapped to [0, 1]).
  std::vector<std::pair<double, double>> rings;
  for (int q = 0; q < 8; ++q) rings.emplace_back(0.5 * (kGaussLegendre8Nodes[q] + 1), 0.5 * kGaussLegendre8Weights[q]);
  std::sort(rings.begin(), rings.end());
  double sum = 0;
  for (int p = 0; p < angles; ++p) {
    const double phi = 2 * kPi * p / angles;
    Eigen::Vector3d yi(ea.t, ea.u, ea.v), yo(xa.t, xa.u, xa.v);
    for (const auto& [xq, wq] : rings) {
      const double rho = h.radius * xq;
      if (!solve_ruling(entry, h, phi, rho, yi) || !solve_ruling(exit, h, phi, rho, yo))
        return std::numeric_limits<double>::quiet_NaN();
      sum += wq * rho * h.radius * (yo[0] - yi[0]);
    }
  }
  return sum * 2 * kPi / angles;
}

}  // namespace cg::features
