// Solid-level check of the blade model: the volume of the B-rep solid built by src/brep/blade_solid
// (BRepGProp::VolumeProperties, relative accuracy 1e-9) against an independent integration of section
// areas over the span, for the straight C3X vane and the HPT rotor on its curved flow path.
#define BOOST_TEST_MODULE blade_volume
#include <boost/test/unit_test.hpp>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "blade/blade_fixtures.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/blade_solid.hpp"

using namespace cg;
using namespace cg::blade;
using namespace cg::blade::test;

namespace {

double solid_volume(const BladeModel& m) {
  const brep::BladeSolid solid = brep::build_blade_solid(m);
  BOOST_TEST(solid.warnings.empty());
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid.solid, props, 1e-9, /*OnlyClosed=*/true);
  return std::abs(props.Mass());
}

// The closed polygon clipped to the strip lo <= x <= hi (Sutherland-Hodgman against both lines; the
// strip is convex, so the clipped area is exact for any simple polygon).
std::vector<Eigen::Vector2d> clip_to_strip(std::vector<Eigen::Vector2d> p, double lo, double hi) {
  auto clip = [](const std::vector<Eigen::Vector2d>& in, double c, double sign) {
    std::vector<Eigen::Vector2d> out;
    auto inside = [&](const Eigen::Vector2d& q) { return sign * (q.x() - c) >= 0; };
    for (std::size_t i = 0; i < in.size(); ++i) {
      const Eigen::Vector2d& a = in[i];
      const Eigen::Vector2d& b = in[(i + 1) % in.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) out.push_back(a + (b - a) * (c - a.x()) / (b.x() - a.x()));
    }
    return out;
  };
  p = clip(p, lo, 1.0);
  return p.empty() ? p : clip(p, hi, -1.0);
}

// x values where the meridional curve (x(t), r(t)) reaches radius R (sampling + bisection).
std::vector<double> crossings(const BSplineCurve<2>& c, double R) {
  std::vector<double> xs;
  const int n = 4000;
  auto f = [&](double t) { return c.point(t).y() - R; };
  for (int i = 0; i < n; ++i) {
    double a = c.first_param() + (c.last_param() - c.first_param()) * i / n;
    double b = c.first_param() + (c.last_param() - c.first_param()) * (i + 1) / n;
    if ((f(a) < 0) == (f(b) < 0)) continue;
    for (int k = 0; k < 100; ++k) {
      const double m = 0.5 * (a + b);
      ((f(a) < 0) == (f(m) < 0) ? a : b) = m;
    }
    xs.push_back(c.point(0.5 * (a + b)).x());
  }
  return xs;
}

// r of the meridional curve at axial position x (x(t) increasing along the contour: bisection).
double radius_at(const BSplineCurve<2>& c, double x) {
  double a = c.first_param(), b = c.last_param();
  for (int k = 0; k < 100; ++k) {
    const double m = 0.5 * (a + b);
    (c.point(m).x() < x ? a : b) = m;
  }
  return c.point(0.5 * (a + b)).y();
}

}  // namespace

BOOST_AUTO_TEST_CASE(c3x_vane_volume_is_area_times_span) {
  const BladeDefinition d = c3x_vane();
  const BladeModel m = build_blade(d);
  const double V = solid_volume(m);
  // Prismatic vane between the planes z = 0 and z = span: V = A * span, with A by Green's theorem on the
  // section curve (Gauss-Legendre, exact for the cubic). Both sides are exact up to the integration
  // accuracies: BRepGProp integrates adaptively to 1e-9 relative (solid_volume), the area rule is exact;
  // 1e-7 leaves 100x that (measured: 1e-15, see the message).
  const double expected = std::abs(section_properties(m.profiles[0].curve).area) * 144.93;
  BOOST_TEST_MESSAGE("C3X volume: solid " << V << " mm^3, area * span " << expected << " mm^3, relative difference "
                                          << std::abs(V - expected) / expected);
  BOOST_TEST(std::abs(V - expected) < 1e-7 * expected);
}

BOOST_AUTO_TEST_CASE(hpt_rotor_volume_by_cylindrical_cuts) {
  const BladeDefinition d = hpt_rotor();
  const BladeModel m = build_blade(d);
  const double V = solid_volume(m);

  // Independent volume: V = integral over R of R * A(R) dR, where A(R) is the (x, theta) area of the
  // blade's cut with the cylinder r = R, restricted to the flow path (hub r <= R <= casing r at that x).
  // The cut: on each iso-u curve of the surface r(v) increases from hub to casing, so r(S(u, v)) = R is
  // solved for v by Newton (bracketed by bisection); 2000 u give a polygon in (x, theta). Simpson over
  // 160 radii.
  const BSplineSurface<3>& S = m.surface;
  const int nu = 2000;
  auto r_of = [&](double u, double v) {
    const Eigen::Vector3d q = S.point(u, v);
    return std::hypot(q.y(), q.z());
  };
  auto area_at = [&](double R) {
    std::vector<Eigen::Vector2d> cut(nu);
    double v = 0.5;
    for (int i = 0; i < nu; ++i) {
      const double u = static_cast<double>(i) / nu;
      double a = S.first_v(), b = S.last_v();
      // Where R lies below the over-build's lower end (or above its upper end) at this u, the cut point
      // stays on that end: it lies where the hub is above R (the casing below R), outside the flow path,
      // and is clipped away below.
      if (r_of(u, a) >= R) v = a;
      else if (r_of(u, b) <= R) v = b;
      else for (int k = 0; k < 100; ++k) {
        Eigen::Vector3d q[4];
        S.derivatives(u, v, 1, q);  // S, S_v, S_u, S_uv
        const double r = std::hypot(q[0].y(), q[0].z()), g = r - R;
        (g < 0 ? a : b) = v;
        const double dr = (q[0].y() * q[1].y() + q[0].z() * q[1].z()) / r;
        double next = dr > 0 ? v - g / dr : 0.5 * (a + b);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        const bool done = std::abs(next - v) < 1e-14;
        v = next;
        if (done) break;
      }
      const Eigen::Vector3d q = S.point(u, v);
      cut[static_cast<std::size_t>(i)] = Eigen::Vector2d(q.x(), std::atan2(q.z(), q.y()));
    }
    // Flow-path strips in x: between the x where hub or casing reach R, keep the pieces with
    // hub r <= R <= casing r.
    double xmin = 1e300, xmax = -1e300;
    for (const auto& q : cut) xmin = std::min(xmin, q.x()), xmax = std::max(xmax, q.x());
    std::vector<double> xs{xmin - 1, xmax + 1};
    for (double x : crossings(m.trim.hub, R)) xs.push_back(x);
    for (double x : crossings(m.trim.casing, R)) xs.push_back(x);
    std::sort(xs.begin(), xs.end());
    double area = 0;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
      const double lo = std::max(xs[k], xmin - 1), hi = std::min(xs[k + 1], xmax + 1);
      if (hi <= lo) continue;
      const double xm = 0.5 * (lo + hi);
      if (radius_at(m.trim.hub, xm) <= R && R <= radius_at(m.trim.casing, xm))
        area += std::abs(polygon_area(clip_to_strip(cut, lo, hi)));
    }
    return area;
  };
  const double r_lo = 274, r_hi = 332;  // below the hub and above the casing over the blade's x range
  const int n = 160;                    // even
  const double h = (r_hi - r_lo) / n;
  double simpson = 0;
  for (int k = 0; k <= n; ++k) {
    const double R = r_lo + k * h;
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    simpson += w * R * area_at(R);
  }
  simpson *= h / 3;
  BOOST_TEST_MESSAGE("HPT volume: solid " << V << " mm^3, cylindrical cuts " << simpson
                                          << " mm^3, relative difference " << std::abs(V - simpson) / simpson);
  // Brief: 0.1 %. The cut areas change slope where the hub/casing lines enter the cut (kinks Simpson
  // resolves to O(h^2)) and the polygon loses O((1/nu)^2) of each cut.
  BOOST_TEST(std::abs(V - simpson) < 1e-3 * simpson);
}
