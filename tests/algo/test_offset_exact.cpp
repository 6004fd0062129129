// Exact pointwise offset (point, derivative, speed ratio) against OCCT's Geom2d_OffsetCurve on
// random polynomial and rational curves, and the rational arc construction by its properties.
#define BOOST_TEST_MODULE offset_exact
#include <boost/test/unit_test.hpp>

#include <Geom2d_OffsetCurve.hxx>

#include <algorithm>

#include "adaptors/occt_convert.hpp"
#include "src/algo/fillet_arc.hpp"
#include "src/algo/offset_exact.hpp"
#include "src/core/error.hpp"
#include "support/eval_scales.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

// Every one of the 6000 random points is compared. Geom2d_OffsetCurve rejects C0 bases, so a base with
// knots of multiplicity >= p is cut there (Geom2d_BSplineCurve::Segment) and the C1 piece containing u
// is offset. Tolerances: both sides build the unit normal from C' with a few roundings, 1e-12 of the
// size (pole scale + |d|) for the point; where |C'| is small the normal's direction is ill-conditioned:
// a rounding of C' of ~1e-13 of its scale (deriv_scale(c, 1)) turns it by that over |C'|, which moves
// the point by |d| times that angle. The derivative O' = (1 - d k) C' carries the curvature:
// 1e-10 of |C'| + |d| |C''| / |C'|, plus the same conditioning term times |C''| / |C'|.
BOOST_AUTO_TEST_CASE(offset_point_and_derivative_vs_geom2d_offset_curve) {
  test::Rng r(11);
  int compared = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    const double d = r.uniform(-3, 3);
    ExactOffset off(c, d);
    // Geom2d_OffsetCurve offsets along (T.y, -T.x), the right normal: our +d is its -d.
    Handle(Geom2d_BSplineCurve) ob = occt::to_occt(c);
    std::vector<double> cuts{c.first_param()};
    const auto dk = distinct_knots(c.knots());
    for (std::size_t k = 0; k < dk.values.size(); ++k)
      if (dk.values[k] > c.first_param() && dk.values[k] < c.last_param() && dk.mults[k] >= c.degree())
        cuts.push_back(dk.values[k]);
    cuts.push_back(c.last_param());
    for (int s = 0; s < 6; ++s) {
      const double u = r.uniform(c.first_param(), c.last_param());
      const std::size_t j = static_cast<std::size_t>(std::upper_bound(cuts.begin(), cuts.end(), u) - cuts.begin()) - 1;
      Handle(Geom2d_BSplineCurve) piece = Handle(Geom2d_BSplineCurve)::DownCast(ob->Copy());
      if (cuts.size() > 2) piece->Segment(cuts[j], cuts[std::min(j + 1, cuts.size() - 1)]);
      Handle(Geom2d_OffsetCurve) oc = new Geom2d_OffsetCurve(piece, -d);
      const auto D = c.derivatives(u, 2);
      gp_Pnt2d P;
      gp_Vec2d V;
      oc->D1(u, P, V);
      Eigen::Vector2d Q, Q1;
      off.d1(u, Q, Q1);
      const double speed = D[1].norm(), turn = std::abs(d) * 1e-13 * test::deriv_scale(c, 1) / speed;
      const double scale = test::pole_scale(c) + std::abs(d);
      BOOST_TEST((Q - Eigen::Vector2d(P.X(), P.Y())).norm() <= 1e-12 * scale + turn, "case " << i);
      const double dscale = speed + std::abs(d) * D[2].norm() / speed;
      BOOST_TEST((Q1 - Eigen::Vector2d(V.X(), V.Y())).norm() <= 1e-10 * dscale + turn * D[2].norm() / speed,
                 "case " << i);
      ++compared;
    }
  }
  BOOST_TEST(compared == 6000);
}

BOOST_AUTO_TEST_CASE(circle_offset_cusp_free_and_breakpoints) {
  // Nine-point unit circle (kernel-references.md): g = 1 - d for d < 1, no cusps.
  const double s = std::sqrt(0.5);
  const std::vector<Eigen::Vector2d> P{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  const Curve2 circle(2, {0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1}, P, {1, s, 1, s, 1, s, 1, s, 1});
  ExactOffset off(circle, 0.3);
  for (double u = 0; u <= 1; u += 0.01) {
    BOOST_TEST(std::abs(off.point(u).norm() - 0.7) <= 1e-14);
    BOOST_TEST(std::abs(off.speed_ratio(u) - 0.7) <= 1e-13);
  }
  const auto bp = offset_breakpoints(circle, 0.3);
  BOOST_TEST(bp.closed);
  BOOST_TEST(bp.cusps.empty());
  BOOST_TEST(bp.corners.empty());  // the double knots are G1 joins
  BOOST_TEST(bp.params.size() == 5u);
}

BOOST_AUTO_TEST_CASE(parabola_cusps_where_radius_of_curvature_equals_d) {
  // y = x^2 on [-1, 1] as a Bezier (poles (-1,1),(0,-1),(1,1)); radius of curvature
  // rho(x) = (1 + 4x^2)^(3/2) / 2 equals d at x = +-sqrt(((2d)^(2/3) - 1) / 4).
  const Curve2 parab(2, {-1, -1, -1, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});
  const double d = 1.0;  // toward the centre of curvature = left of travel for increasing x
  const auto bp = offset_breakpoints(parab, d);
  BOOST_TEST(bp.cusps.size() == 2u);
  const double xc = std::sqrt((std::pow(2 * d, 2.0 / 3.0) - 1) / 4);
  // x(u) = u for this Bezier, so the cusp parameters are the abscissae.
  BOOST_TEST(std::abs(bp.params[static_cast<std::size_t>(bp.cusps[0])] + xc) <= 1e-13);
  BOOST_TEST(std::abs(bp.params[static_cast<std::size_t>(bp.cusps[1])] - xc) <= 1e-13);
  BOOST_TEST(bp.corners.empty());
  BOOST_TEST(!bp.closed);
}

BOOST_AUTO_TEST_CASE(polyline_corners) {
  // Square (counter-clockwise, degree 1): four corners of +90 deg each, the seam included.
  const Curve2 sq(1, {0, 0, 1, 2, 3, 4, 4}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}});
  const auto bp = offset_breakpoints(sq, -0.1);
  BOOST_TEST(bp.closed);
  BOOST_TEST(bp.corners.size() == 4u);
  for (const auto& c : bp.corners) BOOST_TEST(std::abs(c.angle - M_PI / 2) <= 1e-14);
  ExactOffset off(sq, -0.1);
  BOOST_TEST((off.point(1.0, -1) - Eigen::Vector2d(1.0, -0.1)).norm() <= 1e-15);
  BOOST_TEST((off.point(1.0, +1) - Eigen::Vector2d(1.1, 0.0)).norm() <= 1e-15);
}

BOOST_AUTO_TEST_CASE(degenerate_tangent_throws) {
  const Curve2 c(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {0, 0}, {1, 1}});
  ExactOffset off(c, 0.5);
  BOOST_CHECK_THROW(off.point(0.0), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(rational_arcs_exact) {
  test::Rng r(5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector2d c(r.uniform(-5, 5), r.uniform(-5, 5));
    const double rad = r.uniform(0.01, 10), start = r.uniform(-7, 7);
    const double sweep = (r.coin() ? 1 : -1) * (i == 0 ? 2 * M_PI : r.uniform(1e-3, 2 * M_PI));
    const Curve2 arc = circular_arc(c, rad, start, sweep, 1.0, 3.0);
    BOOST_TEST(arc.num_poles() == 1 + 2 * static_cast<int>(std::ceil(std::abs(sweep) / (M_PI / 2) - 1e-12)));
    BOOST_TEST((arc.point(1.0) - c - rad * Eigen::Vector2d(std::cos(start), std::sin(start))).norm() <= 1e-14 * (1 + c.norm() + rad));
    BOOST_TEST((arc.point(3.0) - c - rad * Eigen::Vector2d(std::cos(start + sweep), std::sin(start + sweep))).norm() <=
               1e-14 * (1 + c.norm() + rad));
    for (int k = 0; k <= 50; ++k) {
      const auto D = arc.derivatives(1.0 + 2.0 * k / 50, 2);
      const Eigen::Vector2d v = D[0] - c;
      BOOST_TEST(std::abs(v.norm() - rad) <= 1e-14 * (1 + c.norm() + rad));       // on the circle
      BOOST_TEST(std::abs(v.dot(D[1])) <= 1e-13 * rad * D[1].norm());             // tangent _|_ radius
      BOOST_TEST((v.x() * D[1].y() - v.y() * D[1].x()) * sweep > 0);             // turns with the sweep
    }
  }
  BOOST_CHECK_THROW(circular_arc({0, 0}, -1, 0, 1), InvalidGeometry);
  BOOST_CHECK_THROW(circular_arc({0, 0}, 1, 0, 7), InvalidGeometry);
}
