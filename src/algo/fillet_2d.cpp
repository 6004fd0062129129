#include "src/algo/fillet_2d.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "src/algo/fillet_arc.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/algo/offset_approximate.hpp"
#include "src/algo/offset_exact.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/newton.hpp"
#include "src/modify/split.hpp"

namespace cg {

namespace {

double curve_size(const Curve2& c) {
  double s = 0;
  for (int i = 0; i < c.num_poles(); ++i) s = std::max(s, c.pole(i).norm());
  return s;
}

// Newton's method on E1(u1) - E2(u2) = 0 with the exact offset derivatives (newton::solve_system;
// periodic bases wrap, others are clamped); returns false when it does not converge to the rounding
// level of the coordinates.
bool refine_centre(ExactOffset& e1, ExactOffset& e2, double& u1, double& u2, double scale) {
  newton::Domain<2> dom;
  const Curve2* base[2] = {&e1.base(), &e2.base()};
  for (int i = 0; i < 2; ++i) {
    dom.lo[i] = base[i]->first_param();
    dom.hi[i] = base[i]->last_param();
    dom.periodic[static_cast<std::size_t>(i)] = base[i]->is_periodic();
  }
  newton::SystemOptions opt;
  opt.max_iterations = 60;
  Eigen::Vector2d P1, D1, P2, D2;
  const auto r = newton::solve_system<2>(
      [&](const Eigen::Vector2d& x, Eigen::Vector2d& F, Eigen::Matrix2d& J) {
        e1.d1(x[0], P1, D1);
        e2.d1(x[1], P2, D2);
        F = P1 - P2;
        J << D1.x(), -D2.x(), D1.y(), -D2.y();
      },
      Eigen::Vector2d(u1, u2), dom, dom.hi - dom.lo, opt);
  u1 = r.x[0];
  u2 = r.x[1];
  return (e1.point(u1) - e2.point(u2)).norm() <= 1e-11 * scale;
}

bool at_end(const Curve2& c, double u) {
  if (c.is_periodic()) return false;
  const double eps = 1e-12 * (c.last_param() - c.first_param());
  return u <= c.first_param() + eps || u >= c.last_param() - eps;
}

Curve2 keep_away_from(const Curve2& c, double u, double corner_u) {
  return u < corner_u ? segment(c, c.first_param(), u) : segment(c, u, c.last_param());
}

}  // namespace

Fillet2d fillet_2d(const Curve2& c1, const Curve2& c2, double radius, int side1, int side2,
                   const Eigen::Vector2d& corner) {
  require(std::isfinite(radius) && radius > 0, "fillet radius must be > 0");
  require((side1 == 1 || side1 == -1) && (side2 == 1 || side2 == -1), "fillet sides must be +1 or -1");
  require(c1.num_poles() > 0 && c2.num_poles() > 0, "fillet of an empty curve");
  Fillet2d out;
  out.radius = radius;
  const double scale = 1.0 + std::max(curve_size(c1), curve_size(c2)) + radius;

  // Offsets only seed Newton, so a loose fit suffices; 1e-6 of the scale keeps their crossings
  // apart from each other for any fillet worth making.
  const double fit_tol = 1e-6 * scale;
  const RawOffset o1 = approximate_raw_offset(c1, side1 * radius, fit_tol);
  const RawOffset o2 = approximate_raw_offset(c2, side2 * radius, fit_tol);
  ExactOffset e1(c1, side1 * radius), e2(c2, side2 * radius);

  struct Candidate {
    double u1, u2, dist;
    Eigen::Vector2d centre;
  };
  std::vector<Candidate> cands;
  for (const auto& a : o1.pieces) {
    if (a.kind != RawOffsetPiece::Kind::offset) continue;  // corner arcs touch a vertex, not a tangent
    for (const auto& b : o2.pieces) {
      if (b.kind != RawOffsetPiece::Kind::offset) continue;
      const auto ints = intersect_curves(a.curve, b.curve, 10 * fit_tol);
      for (const auto& x : ints.points) {
        double u1 = x.s, u2 = x.t;  // offset pieces are parametrised by the base parameter
        if (!refine_centre(e1, e2, u1, u2, scale)) continue;
        const Eigen::Vector2d X = e1.point(u1);
        cands.push_back({u1, u2, (X - corner).norm(), X});
      }
    }
  }
  if (cands.empty()) {
    out.reason = "no fillet of radius " + format_number(radius) +
                 ": the offset curves do not meet (radius too large for the curves, or parallel curves)";
    return out;
  }
  std::sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) { return a.dist < b.dist; });

  CurveProjector<2> pr1(c1), pr2(c2);
  const double x1 = pr1.project(corner).param, x2 = pr2.project(corner).param;
  // The circle may touch but not cut a curve: its global distance to each must be r (to rounding).
  const double touch_tol = 1e-10 * scale;
  std::string why = "no fillet of radius " + format_number(radius) + ": ";
  for (const auto& c : cands) {
    if (at_end(c1, c.u1) || at_end(c2, c.u2)) {
      why += "the circle would touch a curve beyond its end (radius too large for the curves)";
      continue;
    }
    if (pr1.project(c.centre).distance < radius - touch_tol || pr2.project(c.centre).distance < radius - touch_tol) {
      why += "every circle of this radius on the corner side cuts one of the curves";
      continue;
    }
    if (std::abs(c.u1 - x1) <= 1e-12 * scale || std::abs(c.u2 - x2) <= 1e-12 * scale) {
      why += "a tangent point coincides with the corner (the curves are tangent there)";
      continue;
    }
    out.found = true;
    out.reason.clear();
    out.centre = c.centre;
    out.param1 = c1.check_param(c.u1);
    out.param2 = c2.check_param(c.u2);
    out.point1 = c1.point(out.param1);
    out.point2 = c2.point(out.param2);
    const Eigen::Vector2d a = out.point1 - c.centre, b = out.point2 - c.centre;
    const double sweep = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    out.arc = circular_arc(c.centre, radius, std::atan2(a.y(), a.x()), sweep);
    out.trimmed1 = keep_away_from(c1, out.param1, x1);
    out.trimmed2 = keep_away_from(c2, out.param2, x2);
    return out;
  }
  out.reason = why;
  return out;
}

Fillet2d fillet_corner_2d(const Curve2& c1, const Curve2& c2, double radius) {
  require(std::isfinite(radius) && radius > 0, "fillet radius must be > 0");
  require(c1.num_poles() > 0 && c2.num_poles() > 0, "fillet of an empty curve");
  const Eigen::Vector2d corner = c1.point(c1.last_param());
  const double scale = 1.0 + std::max(curve_size(c1), curve_size(c2));
  require((corner - c2.point(c2.first_param())).norm() <= 1e-9 * scale,
          "fillet_corner_2d: c1 must end where c2 starts (gap above 1e-9 of the curve size)");
  const Eigen::Vector2d t1 = c1.derivatives(c1.last_param(), 1)[1].normalized();
  const Eigen::Vector2d t2 = c2.derivatives(c2.first_param(), 1)[1].normalized();
  const double turn = t1.x() * t2.y() - t1.y() * t2.x();
  if (std::abs(turn) <= 1e-12 && t1.dot(t2) > 0) {
    Fillet2d out;
    out.radius = radius;
    out.reason = "no fillet: the curves join tangentially (no corner)";
    return out;
  }
  const int side = turn > 0 ? 1 : -1;  // inside of the corner: the side toward which the chain turns
  return fillet_2d(c1, c2, radius, side, side, corner);
}

}  // namespace cg
