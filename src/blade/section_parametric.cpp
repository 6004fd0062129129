// Parametric section: Bezier camber line + thickness with rounded LE/TE (see section.hpp for the model).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/blade/planar_polyline.hpp"
#include "src/blade/section.hpp"
#include "src/core/bezier_curve.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade {
namespace {

double rad(double deg) { return deg * kPi / 180.0; }


// Half-thickness h(t) = L g(t) q(t), g = sqrt(t (1 - t)). q is cubic on each side of the maximum tm:
// q = q_e + a s + b s^2 + c s^3 with s = t - t_e, t_e = 0 (front) or 1 (rear); q_e fixes the tip radius
// and (a, b, c) make h(tm) = T/2, h'(tm) = 0 and h''(tm) = kappa_m on both pieces (C2 at tm).
struct ThicknessPiece {
  double L = 0, te = 0, qe = 0, a = 0, b = 0, c = 0;
  // h, h', h'' at t (0 < t < 1).
  Eigen::Vector3d h(double t) const {
    const double s = t - te;
    const double q = qe + s * (a + s * (b + s * c)), dq = a + s * (2 * b + 3 * c * s), ddq = 2 * b + 6 * c * s;
    return L * with_g(t, q, dq, ddq);
  }
  // (g q, (g q)', (g q)'') with g' = (1 - 2t) / (2g), g'' = -(1 + g'^2) / g (from g^2 = t - t^2).
  static Eigen::Vector3d with_g(double t, double q, double dq, double ddq) {
    const double g = std::sqrt(t * (1 - t)), dg = (1 - 2 * t) / (2 * g), ddg = -(1 + dg * dg) / g;
    return {g * q, dg * q + g * dq, ddg * q + 2 * dg * dq + g * ddq};
  }
};

ThicknessPiece thickness_piece(double L, double te, double qe, double tm, double half_t, double kappa_m) {
  ThicknessPiece p{L, te, qe};
  const double s = tm - te;
  // Columns: the contribution of a, b, c (q = s, s^2, s^3) to (h, h', h'') at tm.
  Eigen::Matrix3d M;
  M.col(0) = L * ThicknessPiece::with_g(tm, s, 1, 0);
  M.col(1) = L * ThicknessPiece::with_g(tm, s * s, 2 * s, 2);
  M.col(2) = L * ThicknessPiece::with_g(tm, s * s * s, 3 * s * s, 6 * s);
  const Eigen::Vector3d rhs = Eigen::Vector3d(half_t, 0, kappa_m) - L * ThicknessPiece::with_g(tm, qe, 0, 0);
  const Eigen::Vector3d abc = M.fullPivLu().solve(rhs);
  p.a = abc.x(), p.b = abc.y(), p.c = abc.z();
  return p;
}

}  // namespace

SectionProfile section_from_parameters(const ParametricSectionDefinition& d) {
  const std::string what = "parametric section";
  require(d.chord > 0, what + ": chord must be > 0 mm, got " + format_number(d.chord));
  require(d.max_thickness > 0 && d.max_thickness < d.chord,
          what + ": max_thickness must be in (0, chord) mm, got " + format_number(d.max_thickness));
  require(d.max_thickness_position >= 0.1 && d.max_thickness_position <= 0.9,
          what + ": max_thickness_position must be in [0.1, 0.9] of chord, got " + format_number(d.max_thickness_position));
  require(d.le_radius > 0 && d.le_radius <= 0.5 * d.max_thickness,
          what + ": le_radius must be in (0, max_thickness / 2] mm, got " + format_number(d.le_radius));
  require(d.te_radius > 0 && d.te_radius <= 0.5 * d.max_thickness,
          what + ": te_radius must be in (0, max_thickness / 2] mm, got " + format_number(d.te_radius));
  require(d.points_per_side >= 8 && d.points_per_side <= 2000,
          what + ": points_per_side must be in [8, 2000], got " + std::to_string(d.points_per_side));
  auto angle_ok = [](double a) { return a > -90 && a < 90; };
  require(angle_ok(d.stagger_deg), what + ": stagger_deg must be in (-90, 90), got " + format_number(d.stagger_deg));
  require(angle_ok(d.inlet_angle_deg) && std::abs(d.inlet_angle_deg - d.stagger_deg) < 90,
          what + ": inlet_angle_deg must be in (-90, 90) and within 90 deg of the stagger, got " + format_number(d.inlet_angle_deg));
  require(angle_ok(d.outlet_angle_deg) && std::abs(d.outlet_angle_deg - d.stagger_deg) < 90,
          what + ": outlet_angle_deg must be in (-90, 90) and within 90 deg of the stagger, got " +
              format_number(d.outlet_angle_deg));

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
    if (!(x > prev))
      throw InvalidGeometry(what + ": the camber line turns back along the chord; reduce the inlet/outlet angle difference");
    prev = x;
  }
  double lo = 0, hi = 1;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((camber.point(mid) - P0).dot(chord_dir) < d.max_thickness_position * d.chord ? lo : hi) = mid;
  }
  const double tm = 0.5 * (lo + hi);

  // Thickness: q at the tips from the radii (h^2 ~ 2 r xi near a tip, xi ~ |B'(end)| t, h ~ L q sqrt(t)); the
  // curvature at the maximum is that of an ellipse with semi-axes T/2 and the geometric mean of the
  // front and rear lengths tm, 1 - tm (in t).
  const double s0 = camber.derivatives(0.0, 1)[1].norm(), s1 = camber.derivatives(1.0, 1)[1].norm();
  const double L = d.chord, half_t = 0.5 * d.max_thickness, kappa_m = -half_t / (tm * (1 - tm));
  const ThicknessPiece front = thickness_piece(L, 0, std::sqrt(2 * d.le_radius * s0) / L, tm, half_t, kappa_m);
  const ThicknessPiece rear = thickness_piece(L, 1, std::sqrt(2 * d.te_radius * s1) / L, tm, half_t, kappa_m);
  auto half_thickness = [&](double t) { return (t <= tm ? front : rear).h(t).x(); };
  // q(t) = h / (L g): the smooth factor used to build the outline (h = L g q with g = sin(phi) / 2).
  auto q_of = [&](double t) {
    const ThicknessPiece& p = t <= tm ? front : rear;
    const double s = t - p.te;
    return p.qe + s * (p.a + s * (p.b + s * p.c));
  };
  // Validity: h > 0 inside, maximum at tm, and each side a regular offset (1 -+ h kappa > 0).
  const double turn = d.inlet_angle_deg - d.outlet_angle_deg;
  const double side = turn >= 0 ? 1.0 : -1.0;  // suction (convex) side: left of the camber when it turns right
  for (int k = 1; k < 2000; ++k) {
    const double t = k / 2000.0;
    const double h = half_thickness(t);
    // (messages built only on failure: this loop runs for every section of the blade)
    if (!(h > 0))
      throw InvalidGeometry(what + ": the thickness distribution becomes non-positive at " + format_number(t) +
                            " of the camber line; adjust max_thickness, its position or the LE/TE radii");
    if (!(h <= 0.5 * d.max_thickness * (1 + 1e-6)))
      throw InvalidGeometry(what + ": the thickness exceeds max_thickness away from max_thickness_position (the "
                                   "LE/TE radii are too large for this position)");
    const auto cd = camber.derivatives(t, 2);
    const double kappa = (cd[1].x() * cd[2].y() - cd[1].y() * cd[2].x()) / std::pow(cd[1].norm(), 3);
    if (!(1 - h * std::abs(kappa) > 0))
      throw InvalidGeometry(what + ": the thickness exceeds the camber line's radius of curvature at " + format_number(t) +
                            " of the camber line (the surface would fold)");
  }

  // Sample phi uniformly (t = (1 - cos phi) / 2 clusters points at both tips), suction side phi in [0, pi].
  const int n = d.points_per_side;
  std::vector<Eigen::Vector2d> pts(static_cast<std::size_t>(2 * n));
  for (int k = 0; k < 2 * n; ++k) {
    const double phi = kPi * k / n;
    const double t = 0.5 * (1 - std::cos(phi));
    const auto cd = camber.derivatives(t, 1);
    const Eigen::Vector2d normal = Eigen::Vector2d(-cd[1].y(), cd[1].x()).normalized();
    pts[static_cast<std::size_t>(k)] = cd[0] + side * L * 0.5 * std::sin(phi) * q_of(t) * normal;
  }
  int ea = 0, eb = 0;
  require(detail::polygon_is_simple(pts, ea, eb), what + ": the outline intersects itself");
  // Parameter phi / (2 pi): the profile is a smooth periodic function of phi, so this is its natural
  // parametrisation, and it puts the LE at 0 and the TE at 0.5 on every parametric section.
  std::vector<double> params(pts.size());
  for (std::size_t k = 0; k < params.size(); ++k) params[k] = static_cast<double>(k) / static_cast<double>(2 * n);
  const BSplineCurve<2> curve = interpolate_closed<2>(pts, 3, params, periodic_interpolation_knots(params, 3));
  SectionProfile s;
  s.curve = curve;
  s.le_param = 0;
  s.te_param = 0.5;
  s.le = curve.point(s.le_param);
  s.te = curve.point(s.te_param);
  s.chord_direction = (s.te - s.le).normalized();
  // The tip circles of the construction: radius le_radius / te_radius, centred on the camber line's end
  // tangent (exact for a straight camber line, to leading order otherwise; see section.hpp).
  s.le_circle = {s.le + d.le_radius * d0, d.le_radius};
  s.te_circle = {s.te - d.te_radius * d3, d.te_radius};
  return s;
}

}  // namespace cg::blade
