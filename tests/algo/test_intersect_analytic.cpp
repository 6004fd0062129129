// intersect_curves on cases with exact answers: the ellipse-ellipse and line-Bezier cases of
// kernel-references.md "Intersections", circle-circle (two crossings, external and internal tangency,
// none), circle and parabola with tangent lines, a wave touching its translated copy, overlaps.
// Tolerances: transversal crossings are Newton-refined to rounding, so parameters and points must
// match the exact values to 1e-12 (1e-9 for the ellipse thetas, given to ~17 digits after a
// parameter conversion). Tangential contacts come from the tangency system, regular when the
// curvatures differ, so they too are checked to 1e-9 in parameters and 1e-12 in position.
#define BOOST_TEST_MODULE intersect_analytic
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "src/algo/intersect_curves.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"

using namespace cg;
using V2 = Eigen::Vector2d;

namespace {

using cg::kPi;

// Nine-point rational circle (The NURBS Book Ex. 7.2) mapped by x -> M x + c: an exact ellipse.
BSplineCurve<2> conic(const Eigen::Matrix2d& M, const V2& c) {
  const double s = std::sqrt(0.5);
  const std::vector<V2> P = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  std::vector<V2> Q;
  for (const auto& p : P) Q.push_back(M * p + c);
  return BSplineCurve<2>(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, Q, {1, s, 1, s, 1, s, 1, s, 1});
}
BSplineCurve<2> circle(const V2& c, double r) { return conic(r * Eigen::Matrix2d::Identity(), c); }
BSplineCurve<2> segment(const V2& a, const V2& b) { return BSplineCurve<2>(1, {0, 0, 1, 1}, {a, b}); }

}  // namespace

BOOST_AUTO_TEST_CASE(ellipse_ellipse_four_crossings) {
  Eigen::Matrix2d M1;
  M1 << 2, 0, 0, 1;
  const double c = std::sqrt(0.5);
  Eigen::Matrix2d R;
  R << c, -c, c, c;
  const auto e1 = conic(M1, V2::Zero());
  const auto e2 = conic(R * M1, V2(0.5, 0.5));
  const auto r = intersect_curves(e1, e2);
  BOOST_TEST_REQUIRE(r.points.size() == 4u);
  BOOST_TEST(r.overlaps.empty());
  std::vector<double> theta;
  for (const auto& p : r.points) {
    BOOST_TEST(p.kind == ContactKind::transversal);
    BOOST_TEST((e1.point(p.s) - e2.point(p.t)).norm() < 1e-14);
    double th = std::atan2(p.point.y(), p.point.x() / 2);
    if (th < 0) th += 2 * kPi;
    theta.push_back(th);
  }
  std::sort(theta.begin(), theta.end());
  const double expected[4] = {0.50180930656500048, 1.7819090457222602, 4.2207813972401171, 1.5 * kPi};
  for (int i = 0; i < 4; ++i) BOOST_TEST(std::abs(theta[static_cast<std::size_t>(i)] - expected[i]) < 1e-9);
}

BOOST_AUTO_TEST_CASE(line_bezier_textbook) {
  const auto line = segment({0, 0}, {2, 0});
  const BSplineCurve<2> bez(2, {0, 0, 0, 1, 1, 1}, {{0.5, 0.5}, {0.7, 0}, {0.5, -1.5}});
  const auto r = intersect_curves(line, bez);
  BOOST_TEST_REQUIRE(r.points.size() == 1u);
  BOOST_TEST(std::abs(r.points[0].t - (std::sqrt(3.0) - 1) / 2) < 1e-12);
  BOOST_TEST(std::abs(r.points[0].s - (0.2 * std::sqrt(3.0) - 0.05)) < 1e-12);
  BOOST_TEST(r.points[0].kind == ContactKind::transversal);
}

BOOST_AUTO_TEST_CASE(circle_circle) {
  const auto c0 = circle({0, 0}, 1);
  {  // two crossings at (1/2, +-sqrt(3)/2)
    const auto r = intersect_curves(c0, circle({1, 0}, 1));
    BOOST_TEST_REQUIRE(r.points.size() == 2u);
    for (const auto& p : r.points) {
      BOOST_TEST(std::abs(p.point.x() - 0.5) < 1e-12);
      BOOST_TEST(std::abs(std::abs(p.point.y()) - std::sqrt(3.0) / 2) < 1e-12);
      BOOST_TEST(p.kind == ContactKind::transversal);
    }
  }
  {  // external tangency at (1, 0): the seam of both circles lies elsewhere only for the second
    const auto r = intersect_curves(c0, circle({2, 0}, 1));
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST((r.points[0].point - V2(1, 0)).norm() < 1e-12);
    BOOST_TEST(r.points[0].kind == ContactKind::tangent);
    BOOST_TEST(std::abs(r.points[0].t - 0.5) < 1e-9);  // (1, 0) is the second circle's u = 1/2
  }
  {  // internal tangency at (-1, 0)
    const auto r = intersect_curves(c0, circle({1, 0}, 2));
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST((r.points[0].point - V2(-1, 0)).norm() < 1e-12);
    BOOST_TEST(std::abs(r.points[0].s - 0.5) < 1e-9);
    BOOST_TEST(r.points[0].kind == ContactKind::tangent);
  }
  {  // apart, and a near miss 1e-7 wide: nothing at tol 1e-9, a tangent contact at tol 1e-6
    BOOST_TEST(intersect_curves(c0, circle({3, 0}, 1)).points.empty());
    const auto near = circle({2 + 1e-7, 0}, 1);
    BOOST_TEST(intersect_curves(c0, near).points.empty());
    const auto r = intersect_curves(c0, near, 1e-6);
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST(r.points[0].kind == ContactKind::tangent);
    BOOST_TEST(std::abs(r.points[0].s) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(tangent_lines) {
  {  // circle and the line y = 1 touch at (0, 1), u = 1/4
    const auto r = intersect_curves(circle({0, 0}, 1), segment({-2, 1}, {2, 1}));
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST(r.points[0].kind == ContactKind::tangent);
    BOOST_TEST(std::abs(r.points[0].s - 0.25) < 1e-9);
    BOOST_TEST((r.points[0].point - V2(0, 1)).norm() < 1e-12);
  }
  {  // parabola y = x^2 on [-1, 1] and its tangent y = x - 1/4 at x = 1/2
    const BSplineCurve<2> par(2, {0, 0, 0, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});
    const auto r = intersect_curves(par, segment({-1, -1.25}, {2, 1.75}));
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST(r.points[0].kind == ContactKind::tangent);
    BOOST_TEST(std::abs(r.points[0].s - 0.75) < 1e-9);  // x = 2u - 1
    BOOST_TEST(std::abs(r.points[0].t - 0.5) < 1e-9);
    BOOST_TEST((r.points[0].point - V2(0.5, 0.25)).norm() < 1e-12);
  }
  {  // a line 1e-7 below the tangent crosses twice, 2 * sqrt(1e-7) apart
    const BSplineCurve<2> par(2, {0, 0, 0, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});
    const auto r = intersect_curves(par, segment({-1, -1.25 + 1e-7}, {2, 1.75 + 1e-7}));
    BOOST_TEST_REQUIRE(r.points.size() == 2u);
    for (const auto& p : r.points) {
      BOOST_TEST(std::abs(std::abs(p.point.x() - 0.5) - std::sqrt(1e-7)) < 1e-12);
      BOOST_TEST(p.kind == ContactKind::transversal);
    }
  }
}

BOOST_AUTO_TEST_CASE(wave_touching_its_translated_copy) {
  // A cubic wave with a crest and a trough of horizontal tangent; the copy translated so that its
  // trough sits on the crest touches there (curvatures of opposite sign), tangentially.
  const BSplineCurve<2> w(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 3}, {2, -3}, {3, 0}});
  auto extremum = [&](double u) {  // y'(u) = 0 by Newton
    for (int i = 0; i < 50; ++i) {
      const auto d = w.derivatives(u, 2);
      u -= d[1].y() / d[2].y();
    }
    return u;
  };
  const double crest = extremum(0.2), trough = extremum(0.8);
  const V2 v = w.point(crest) - w.point(trough);
  std::vector<V2> moved;
  for (const auto& p : w.poles()) moved.push_back(p + v);
  const BSplineCurve<2> copy(3, w.knots(), moved);
  const auto r = intersect_curves(w, copy);
  bool touch = false;
  for (const auto& p : r.points) {
    BOOST_TEST((w.point(p.s) - copy.point(p.t)).norm() < 1e-12);
    if (std::abs(p.s - crest) < 1e-9 && std::abs(p.t - trough) < 1e-9) {
      touch = true;
      BOOST_TEST(p.kind == ContactKind::tangent);
    }
  }
  BOOST_TEST(touch);
}

BOOST_AUTO_TEST_CASE(overlaps) {
  {  // a circle and an arc of it (different parametrisation): one overlap, no points
    const auto c0 = circle({0, 0}, 1);
    const BSplineCurve<2> arc(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
    const auto r = intersect_curves(c0, arc);
    BOOST_TEST(r.points.empty());
    BOOST_TEST_REQUIRE(r.overlaps.size() == 1u);
    BOOST_TEST(std::abs(r.overlaps[0].s0) < 1e-9);
    BOOST_TEST(std::abs(r.overlaps[0].s1 - 0.25) < 1e-9);
    BOOST_TEST(std::abs(r.overlaps[0].t0) < 1e-9);
    BOOST_TEST(std::abs(r.overlaps[0].t1 - 1) < 1e-9);
  }
  {  // collinear segments sharing [1, 2], in opposite senses
    const auto r = intersect_curves(segment({0, 0}, {2, 0}), segment({3, 0}, {1, 0}));
    BOOST_TEST(r.points.empty());
    BOOST_TEST_REQUIRE(r.overlaps.size() == 1u);
    BOOST_TEST(std::abs(r.overlaps[0].s0 - 0.5) < 1e-12);
    BOOST_TEST(std::abs(r.overlaps[0].s1 - 1.0) < 1e-12);
    BOOST_TEST(std::abs(r.overlaps[0].t0 - 1.0) < 1e-12);
    BOOST_TEST(std::abs(r.overlaps[0].t1 - 0.5) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(curve_with_itself) {
  // Identical curves: one overlap over the whole domain; the reversed copy (u -> -u): t runs backwards.
  const auto c = circle({0, 0}, 1);
  auto r = intersect_curves(c, c);
  BOOST_TEST(r.points.empty());
  BOOST_TEST_REQUIRE(r.overlaps.size() == 1u);
  BOOST_TEST(r.overlaps[0].s0 == 0.0);
  BOOST_TEST(r.overlaps[0].s1 == 1.0);
  const BSplineCurve<2> w(3, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, {{0, 0}, {1, 2}, {2, -1}, {3, 1}, {4, 0}, {5, 2}},
                          {1, 2, 0.5, 1, 3, 1});
  std::vector<V2> P = w.poles();
  std::vector<double> wt = w.weights();
  std::reverse(P.begin(), P.end());
  std::reverse(wt.begin(), wt.end());
  const BSplineCurve<2> rev(3, {-1, -1, -1, -1, -0.6, -0.3, 0, 0, 0, 0}, P, wt);
  r = intersect_curves(w, rev);
  BOOST_TEST(r.points.empty());
  BOOST_TEST_REQUIRE(r.overlaps.size() == 1u);
  BOOST_TEST(std::abs(r.overlaps[0].s0) < 1e-12);
  BOOST_TEST(std::abs(r.overlaps[0].s1 - 1) < 1e-12);
  BOOST_TEST(std::abs(r.overlaps[0].t0) < 1e-12);
  BOOST_TEST(std::abs(r.overlaps[0].t1 + 1) < 1e-12);
}

BOOST_AUTO_TEST_CASE(bad_input) {
  BOOST_CHECK_THROW(intersect_curves(circle({0, 0}, 1), circle({1, 0}, 1), 0.0), InvalidGeometry);
  BOOST_CHECK_THROW(intersect_curves(BSplineCurve<2>(), circle({1, 0}, 1)), InvalidGeometry);
}
