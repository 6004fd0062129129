// Parametric section: Bezier camber line + thickness with rounded LE/TE (see section.hpp for the model).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/blade/planar_polyline.hpp"
#include "src/blade/section.hpp"
#include "src/core/bezier_curve.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Half-thickness h(t) = L g(t) q(t), g = sqrt(t (1 - t)), q(t) = q0 (1 - t) + q1 t + t (1 - t)(alpha + beta t).
struct Thickness {
  double L, q0, q1, alpha = 0, beta = 0;
  double q(double t) const { return q0 * (1 - t) + q1 * t + t * (1 - t) * (alpha + beta * t); }
  double dq(double t) const { return q1 - q0 + (1 - 2 * t) * (alpha + beta * t) + t * (1 - t) * beta; }
  double h(double t) const { return L * std::sqrt(t * (1 - t)) * q(t); }
  double dh(double t) const {
    const double g = std::sqrt(t * (1 - t)), dg = (1 - 2 * t) / (2 * g);
    return L * (dg * q(t) + g * dq(t));
  }
};

}  // namespace

SectionProfile section_from_parameters(const ParametricSectionDefinition& d) {
  const std::string what = "parametric section";
  require(d.chord > 0, what + ": chord must be > 0 mm, got " + fmt(d.chord));
  require(d.max_thickness > 0 && d.max_thickness < d.chord,
          what + ": max_thickness must be in (0, chord) mm, got " + fmt(d.max_thickness));
  require(d.max_thickness_position >= 0.1 && d.max_thickness_position <= 0.9,
          what + ": max_thickness_position must be in [0.1, 0.9] of chord, got " + fmt(d.max_thickness_position));
  require(d.le_radius > 0 && d.le_radius < 0.5 * d.max_thickness,
          what + ": le_radius must be in (0, max_thickness / 2) mm, got " + fmt(d.le_radius));
  require(d.te_radius > 0 && d.te_radius < 0.5 * d.max_thickness,
          what + ": te_radius must be in (0, max_thickness / 2) mm, got " + fmt(d.te_radius));
  require(d.points_per_side >= 8 && d.points_per_side <= 5000,
          what + ": points_per_side must be in [8, 5000], got " + std::to_string(d.points_per_side));
  auto angle_ok = [](double a) { return a > -90 && a < 90; };
  require(angle_ok(d.stagger_deg), what + ": stagger_deg must be in (-90, 90), got " + fmt(d.stagger_deg));
  require(angle_ok(d.inlet_angle_deg) && std::abs(d.inlet_angle_deg - d.stagger_deg) < 90,
          what + ": inlet_angle_deg must be in (-90, 90) and within 90 deg of the stagger, got " + fmt(d.inlet_angle_deg));
  require(angle_ok(d.outlet_angle_deg) && std::abs(d.outlet_angle_deg - d.stagger_deg) < 90,
          what + ": outlet_angle_deg must be in (-90, 90) and within 90 deg of the stagger, got " +
              fmt(d.outlet_angle_deg));

  // Camber line.
  const Eigen::Vector2d P0(0, 0), P3 = d.chord * Eigen::Vector2d(std::cos(rad(d.stagger_deg)), std::sin(rad(d.stagger_deg)));
  const Eigen::Vector2d d0(std::cos(rad(d.inlet_angle_deg)), std::sin(rad(d.inlet_angle_deg)));
  const Eigen::Vector2d d3(std::cos(rad(d.outlet_angle_deg)), std::sin(rad(d.outlet_angle_deg)));
  Eigen::Matrix2d A;
  A.col(0) = d0;
  A.col(1) = d3;
  Eigen::Vector2d st(-1, -1);
  if (std::abs(A.determinant()) > 1e-9) st = A.inverse() * (P3 - P0);
  Eigen::Vector2d P1, P2;
  if (st.x() > 0 && st.y() > 0 && st.x() < 2 * d.chord && st.y() < 2 * d.chord) {
    P1 = P0 + (2.0 / 3.0) * st.x() * d0;  // the parabola through the tangent intersection, degree-elevated
    P2 = P3 - (2.0 / 3.0) * st.y() * d3;
  } else {
    P1 = P0 + d.chord / 3 * d0;
    P2 = P3 - d.chord / 3 * d3;
  }
  const BezierCurve<2> camber(std::vector<Eigen::Vector2d>{P0, P1, P2, P3});

  // Camber parameter where the chordwise position is max_thickness_position (bisection: monotone when
  // the camber line does not turn back, checked on the way).
  const Eigen::Vector2d chord_dir = (P3 - P0).normalized();
  double prev = -1;
  for (int k = 0; k <= 200; ++k) {
    const double x = (camber.point(k / 200.0) - P0).dot(chord_dir);
    require(x > prev, what + ": the camber line turns back along the chord; reduce the inlet/outlet angle difference");
    prev = x;
  }
  double lo = 0, hi = 1;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((camber.point(mid) - P0).dot(chord_dir) < d.max_thickness_position * d.chord ? lo : hi) = mid;
  }
  const double tm = 0.5 * (lo + hi);

  // Thickness: q0, q1 from the tip radii (h^2 ~ 2 r xi near a tip, xi ~ |B'(end)| t), alpha/beta from
  // h(tm) = max_thickness / 2 and h'(tm) = 0 (linear in alpha, beta).
  const double s0 = camber.derivatives(0.0, 1)[1].norm(), s1 = camber.derivatives(1.0, 1)[1].norm();
  Thickness th{d.chord, std::sqrt(2 * d.le_radius * s0) / d.chord, std::sqrt(2 * d.te_radius * s1) / d.chord};
  {
    Thickness ta = th, tb = th;
    ta.alpha = 1, tb.beta = 1;
    Eigen::Matrix2d M;
    M << ta.h(tm) - th.h(tm), tb.h(tm) - th.h(tm), ta.dh(tm) - th.dh(tm), tb.dh(tm) - th.dh(tm);
    const Eigen::Vector2d rhs(0.5 * d.max_thickness - th.h(tm), -th.dh(tm));
    const Eigen::Vector2d ab = M.fullPivLu().solve(rhs);
    th.alpha = ab.x(), th.beta = ab.y();
  }
  // Validity: h > 0 inside, maximum at tm, and each side a regular offset (1 -+ h kappa > 0).
  const double turn = d.inlet_angle_deg - d.outlet_angle_deg;
  const double side = turn >= 0 ? 1.0 : -1.0;  // suction (convex) side: left of the camber when it turns right
  for (int k = 1; k < 2000; ++k) {
    const double t = k / 2000.0;
    const double h = th.h(t);
    require(h > 0, what + ": the thickness distribution becomes non-positive at " + fmt(t) +
                       " of the camber line; adjust max_thickness, its position or the LE/TE radii");
    require(h <= 0.5 * d.max_thickness * (1 + 1e-6),
            what + ": the thickness exceeds max_thickness away from max_thickness_position (the LE/TE radii are too "
                   "large for this position)");
    const auto cd = camber.derivatives(t, 2);
    const double kappa = (cd[1].x() * cd[2].y() - cd[1].y() * cd[2].x()) / std::pow(cd[1].norm(), 3);
    require(1 - h * std::abs(kappa) > 0, what + ": the thickness exceeds the camber line's radius of curvature at " +
                                             fmt(t) + " of the camber line (the surface would fold)");
  }

  // Sample phi uniformly (t = (1 - cos phi) / 2 clusters points at both tips), suction side phi in [0, pi].
  const int n = d.points_per_side;
  std::vector<Eigen::Vector2d> pts(static_cast<std::size_t>(2 * n));
  for (int k = 0; k < 2 * n; ++k) {
    const double phi = kPi * k / n;
    const double t = 0.5 * (1 - std::cos(phi));
    const auto cd = camber.derivatives(t, 1);
    const Eigen::Vector2d normal = Eigen::Vector2d(-cd[1].y(), cd[1].x()).normalized();
    pts[static_cast<std::size_t>(k)] = cd[0] + side * th.L * 0.5 * std::sin(phi) * th.q(t) * normal;
  }
  std::vector<Eigen::Vector2d> check = pts;
  for (const auto& h : detail::polyline_crossings(check, check, 0.0)) {
    const int dd = std::abs(h.i - h.j);
    require(dd <= 1 || dd == 2 * n - 2, what + ": the outline intersects itself");
  }
  const std::vector<double> params = interpolation_parameters<2>(pts, ParamMethod::Centripetal, true);
  const BSplineCurve<2> curve =
      interpolate_closed<2>(pts, 3, params, periodic_interpolation_knots(params, 3));
  SectionProfile s;
  s.curve = curve;
  s.le_param = curve.check_param(params[0]);
  s.te_param = params[static_cast<std::size_t>(n)];
  while (s.te_param <= s.le_param) s.te_param += curve.period();
  s.le = curve.point(s.le_param);
  s.te = curve.point(s.te_param);
  return s;
}

}  // namespace cg::blade
