#include "src/algo/offset_exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

ExactOffset::ExactOffset(const Curve2& base, double distance) : d_(distance), ev_(base) {
  require(std::isfinite(distance), "offset distance must be finite");
}

ExactOffset::Local ExactOffset::eval(double u, int side) {
  // One ulp to the left selects the left knot span; the position moves by |C'| ulp(u) only.
  if (side < 0 && (base().is_periodic() || u > base().first_param()))
    u = std::nextafter(u, -std::numeric_limits<double>::infinity());
  Local L;
  ev_.d2(u, L.C, L.C1, L.C2);
  const double speed = L.C1.norm();
  if (!(speed > 1e-300) || !(speed > 1e-14 * L.C2.norm()))
    throw InvalidGeometry("offset: the base curve tangent vanishes at u = " + format_number(u) +
                          " (the normal is undefined; the base must be regular)");
  return L;
}

Eigen::Vector2d ExactOffset::normal(double u, int side) {
  const Local L = eval(u, side);
  return Eigen::Vector2d(-L.C1.y(), L.C1.x()) / L.C1.norm();
}

Eigen::Vector2d ExactOffset::point(double u, int side) {
  const Local L = eval(u, side);
  return L.C + d_ * Eigen::Vector2d(-L.C1.y(), L.C1.x()) / L.C1.norm();
}

void ExactOffset::d1(double u, Eigen::Vector2d& P, Eigen::Vector2d& D1, int side) {
  const Local L = eval(u, side);
  const double s = L.C1.norm();
  const double k = (L.C1.x() * L.C2.y() - L.C1.y() * L.C2.x()) / (s * s * s);
  P = L.C + d_ * Eigen::Vector2d(-L.C1.y(), L.C1.x()) / s;
  D1 = (1.0 - d_ * k) * L.C1;
}

double ExactOffset::speed_ratio(double u, int side) {
  const Local L = eval(u, side);
  const double s = L.C1.norm();
  return 1.0 - d_ * (L.C1.x() * L.C2.y() - L.C1.y() * L.C2.x()) / (s * s * s);
}

namespace {

double signed_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

}  // namespace

OffsetBreakpoints offset_breakpoints(const Curve2& base, double distance, double corner_angle) {
  require(base.num_poles() > 0, "offset of an empty curve");
  ExactOffset off(base, distance);
  OffsetBreakpoints bp;
  const double a = base.first_param(), b = base.last_param();
  double size = 0;
  for (int i = 0; i < base.num_poles(); ++i) size = std::max(size, base.pole(i).norm());
  bp.closed = base.is_periodic() || (base.point(a) - base.point(b)).norm() <= 1e-9 * (1.0 + size);

  std::vector<double> knots;  // distinct knots inside [a, b]
  for (double k : base.knots())
    if (k >= a && k <= b && (knots.empty() || k > knots.back())) knots.push_back(k);

  const int samples = 12 + 4 * base.degree();
  for (std::size_t s = 0; s + 1 < knots.size(); ++s) {
    const double lo = knots[s], hi = knots[s + 1];
    if (s == 0) {
      bp.params.push_back(lo);
    } else if ((off.speed_ratio(lo, -1) < 0) != (off.speed_ratio(lo, +1) < 0)) {
      // The curvature jumps across a knot of a C1 base: the offset reverses there (a cusp at the knot).
      bp.cusps.push_back(static_cast<int>(bp.params.size()) - 1);
    }
    const double min_gap = 1e-12 * (hi - lo);  // roots closer to a knot than this belong to the knot
    double u0 = lo, g0 = off.speed_ratio(lo, +1);
    for (int i = 1; i <= samples; ++i) {
      const double u1 = i == samples ? hi : lo + (hi - lo) * i / samples;
      const double g1 = off.speed_ratio(u1, i == samples ? -1 : +1);
      if ((g0 < 0) != (g1 < 0) && g0 != 0.0) {
        // Bisection to machine precision: g is smooth inside the span, and the cusp parameter
        // is the split point of the raw offset, so its accuracy bounds the kink position.
        double l = u0, r = u1, gl = g0;
        while (r - l > 4 * std::numeric_limits<double>::epsilon() * (std::abs(l) + std::abs(r))) {
          const double m = 0.5 * (l + r);
          if (m <= l || m >= r) break;
          const double gm = off.speed_ratio(m, +1);
          if ((gm < 0) == (gl < 0)) {
            l = m;
            gl = gm;
          } else {
            r = m;
          }
        }
        const double c = 0.5 * (l + r);
        if (c > bp.params.back() + min_gap && c < hi - min_gap) {
          bp.cusps.push_back(static_cast<int>(bp.params.size()));
          bp.params.push_back(c);
        }
      }
      u0 = u1;
      g0 = g1;
    }
    bp.params.push_back(hi);
  }

  // Corners: interior knots, and the seam of a closed curve (recorded at index 0).
  auto tangent = [&](double u, int side) {
    const Eigen::Vector2d n = off.normal(u, side);
    return Eigen::Vector2d(n.y(), -n.x());
  };
  for (std::size_t i = 0; i < bp.params.size(); ++i) {
    const double u = bp.params[i];
    const bool seam = (i == 0 && bp.closed);
    const bool interior = i > 0 && i + 1 < bp.params.size();
    if (!seam && !interior) continue;
    const Eigen::Vector2d tl = seam ? tangent(b, -1) : tangent(u, -1);
    const Eigen::Vector2d tr = tangent(u, +1);
    const double ang = signed_angle(tl, tr);
    if (std::abs(ang) > corner_angle) bp.corners.push_back({static_cast<int>(i), ang});
  }
  return bp;
}

}  // namespace cg
