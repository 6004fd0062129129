// Ray-curve intersection: sphere tracing (RayCurveCaster, 2D and 3D) and the exact 2D line-curve
// roots (line_curve_intersections) against the textbook line-Bezier case, against OCCT's
// Geom2dAPI_InterCurveCurve with a Geom2d_Line on random curves and rays, and on misses and tangents.
//
// Tolerances: first hits agree with OCCT to 1e-9 in the ray parameter (OCCT's intersector refines to
// ~1e-15 residual; ours to 1e-12 of the curve size); rays within 1e-3 rad of tangency to the hit are
// not compared (the hit position is ill-conditioned there, ~ residual / sin(angle)).
#define BOOST_TEST_MODULE ray_curve
#include <boost/test/unit_test.hpp>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2d_Line.hxx>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/ray_curve.hpp"
#include "src/core/bezier_curve.hpp"
#include "src/core/error.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

BSplineCurve<2> nine_point_circle() {
  const double s = std::sqrt(0.5);
  return BSplineCurve<2>(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                         {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                         {1, s, 1, s, 1, s, 1, s, 1});
}

double sine_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(a.x() * b.y() - a.y() * b.x()) / (a.norm() * b.norm());
}

}  // namespace

BOOST_AUTO_TEST_CASE(textbook_line_bezier) {
  // kernel-references.md, Intersections: line (0,0)->(2,0) vs quadratic Bezier (0.5,0.5),(0.7,0),(0.5,-1.5).
  const std::vector<Eigen::Vector2d> poles = {{0.5, 0.5}, {0.7, 0.0}, {0.5, -1.5}};
  const auto c = BezierCurve<2>(poles).to_bspline();
  const double t = (std::sqrt(3.0) - 1) / 2, u = 0.2 * std::sqrt(3.0) - 0.05;
  const Eigen::Vector2d o(0, 0), d(2, 0);
  const auto hits = line_curve_intersections(c, o, d, 0.0, 1.0);
  BOOST_TEST_REQUIRE(hits.size() == 1u);
  BOOST_TEST(std::abs(hits[0].curve_param - t) <= 1e-14);
  BOOST_TEST(std::abs(hits[0].ray_param - u) <= 1e-14);
  const auto h = ray_curve_first_hit(c, o, d, 1.0);
  BOOST_TEST_REQUIRE(h.found);
  BOOST_TEST(std::abs(h.curve_param - t) <= 1e-12);
  BOOST_TEST(std::abs(h.ray_param - u) <= 1e-12);
  BOOST_TEST(!h.tangent);
}

BOOST_AUTO_TEST_CASE(random_rays_vs_occt_2d) {
  test::Rng r(31);
  int compared = 0, hits_seen = 0, misses = 0, occt_missed = 0;
  for (int i = 0; i < 400; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    const auto oc = occt::to_occt(c);
    RayCurveCaster<2> caster(c);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d o(r.uniform(-15, 15), r.uniform(-15, 15));
      // Aim at a curve point (a hit, usually not the first) or in a random direction.
      Eigen::Vector2d d = k < 2 ? Eigen::Vector2d(c.point(r.uniform(c.first_param(), c.last_param())) - o)
                                : Eigen::Vector2d(r.uniform(-1, 1), r.uniform(-1, 1));
      d *= r.uniform(0.5, 2.0);
      Handle(Geom2d_Line) line = new Geom2d_Line(gp_Pnt2d(o.x(), o.y()), gp_Dir2d(d.x(), d.y()));
      Geom2dAPI_InterCurveCurve inter(line, oc, 1e-9);
      double occt_first = 1e300;
      double occt_sine = 1.0;
      for (int j = 1; j <= inter.NbPoints(); ++j) {
        const gp_Pnt2d q = inter.Point(j);
        const Eigen::Vector2d Q(q.X(), q.Y());
        const double s = d.dot(Q - o) / d.squaredNorm();
        if (s >= 0 && s < occt_first) occt_first = s;
      }
      const auto ex = line_curve_intersections(c, o, d);
      const auto sp = caster.first_hit(o, d);
      if (occt_first < 1e300) {
        // Skip ill-conditioned near-tangent first hits.
        const auto proj = project_point_on_curve(c, Eigen::Vector2d(o + occt_first * d));
        occt_sine = sine_between(d, c.derivatives(proj.param, 1)[1]);
      }
      if (occt_sine < 1e-3 || (!ex.empty() && ex[0].tangent)) continue;
      ++compared;
      BOOST_TEST(sp.found == !ex.empty());
      if (occt_first < 1e300) BOOST_TEST_REQUIRE(sp.found);
      if (!sp.found) {
        ++misses;
        continue;
      }
      ++hits_seen;
      // Our first hit is never later than OCCT's; where it is earlier (or OCCT has none), OCCT missed a
      // crossing: the exact method finds it too, on the ray and on the curve.
      BOOST_TEST(sp.ray_param * d.norm() <= occt_first * d.norm() + 1e-9);
      BOOST_TEST(std::abs(ex.front().ray_param - sp.ray_param) * d.norm() <= 1e-9);
      if (sp.ray_param * d.norm() < occt_first * d.norm() - 1e-9) ++occt_missed;
      BOOST_TEST(sp.gap <= 1e-9 * (1 + test::pole_scale(c)));
      for (std::size_t j = 0; j < ex.size(); ++j) {
        BOOST_TEST(ex[j].gap <= 1e-11 * (1 + test::pole_scale(c)));
        if (j > 0) BOOST_TEST(ex[j].ray_param >= ex[j - 1].ray_param);
      }
    }
  }
  std::printf("2D rays: %d compared with OCCT (%d hits, %d misses); OCCT missed the first crossing in %d\n",
              compared, hits_seen, misses, occt_missed);
  BOOST_TEST(compared >= 1000);
  BOOST_TEST(misses >= 50);
}

BOOST_AUTO_TEST_CASE(misses_and_tangents) {
  const auto c = nine_point_circle();
  RayCurveCaster<2> caster(c);
  // Pointing away, and passing by at distance 0.5 outside the circle.
  BOOST_TEST(!caster.first_hit(Eigen::Vector2d(3, 0), Eigen::Vector2d(1, 0)).found);
  BOOST_TEST(!caster.first_hit(Eigen::Vector2d(-3, 1.5), Eigen::Vector2d(1, 0)).found);
  BOOST_TEST(line_curve_intersections(c, Eigen::Vector2d(-3, 1.5), Eigen::Vector2d(1, 0)).empty());
  // Near miss (gap 1e-6 > hit tolerance): no hit, and the march gets past the approach.
  BOOST_TEST(!caster.first_hit(Eigen::Vector2d(-3, 1 + 1e-6), Eigen::Vector2d(1, 0)).found);
  // Tangent at (0, 1).
  const auto t = caster.first_hit(Eigen::Vector2d(-3, 1), Eigen::Vector2d(1, 0));
  BOOST_TEST_REQUIRE(t.found);
  BOOST_TEST(t.tangent);
  BOOST_TEST(std::abs(t.ray_param - 3.0) <= 1e-6);  // a tangent contact is located to ~sqrt(tolerance)
  const auto te = line_curve_intersections(c, Eigen::Vector2d(-3, 1), Eigen::Vector2d(1, 0));
  BOOST_TEST_REQUIRE(te.size() == 1u);
  BOOST_TEST(te[0].tangent);
  BOOST_TEST(std::abs(te[0].ray_param - 3.0) <= 1e-5);
  // Through the centre: two crossings, first at s = 2 (from (-3, 0)), the line also behind.
  const auto h = caster.first_hit(Eigen::Vector2d(-3, 0), Eigen::Vector2d(1, 0));
  BOOST_TEST(std::abs(h.ray_param - 2.0) <= 1e-12);
  const auto all = line_curve_intersections(c, Eigen::Vector2d(-3, 0), Eigen::Vector2d(1, 0));
  BOOST_TEST_REQUIRE(all.size() == 2u);
  BOOST_TEST(std::abs(all[1].ray_param - 4.0) <= 1e-12);
  // From inside: the first hit is the exit point.
  BOOST_TEST(std::abs(caster.first_hit(Eigen::Vector2d(0.5, 0), Eigen::Vector2d(0, 2)).ray_param -
                      std::sqrt(0.75) / 2) <= 1e-12);
  BOOST_TEST(line_curve_intersections(c, Eigen::Vector2d(0.5, 0), Eigen::Vector2d(0, 2), -INFINITY, INFINITY).size() ==
             2u);
  BOOST_CHECK_THROW(caster.first_hit(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0)), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(rays_3d) {
  // A ray aimed at a point of a random 3D curve hits it there (or earlier, which in 3D happens only
  // if the ray meets the curve twice: checked by the gap of the hit).
  test::Rng r(33);
  int exact = 0;
  for (int i = 0; i < 200; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 0);
    RayCurveCaster<3> caster(c);
    const Eigen::Vector3d target = c.point(r.uniform(c.first_param(), c.last_param()));
    const Eigen::Vector3d o(r.uniform(-20, 20), r.uniform(-20, 20), r.uniform(-20, 20));
    const Eigen::Vector3d d = target - o;
    const auto h = caster.first_hit(o, d, 2.0);
    BOOST_TEST_REQUIRE(h.found);
    BOOST_TEST(h.ray_param <= 1.0 + 1e-9);
    BOOST_TEST(h.gap <= caster.hit_tolerance());
    if (std::abs(h.ray_param - 1.0) <= 1e-9) ++exact;
    // A ray offset sideways by 1e-3 of the curve size misses (the curve is hit with probability 0).
    const Eigen::Vector3d side = d.cross(Eigen::Vector3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1))).normalized();
    const auto m = caster.first_hit(o + 0.05 * side, d, 2.0);
    if (m.found) BOOST_TEST(m.gap <= caster.hit_tolerance());
  }
  BOOST_TEST(exact >= 190);
}
