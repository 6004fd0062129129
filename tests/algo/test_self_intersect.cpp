// self_intersections and loop untangling.
// - Against OCCT's one-curve Geom2dAPI_InterCurveCurve(C, 1e-6) on 1000 random curves (polynomial
//   and rational, degrees 1..7, repeated knots): every OCCT crossing must have one of ours within
//   a bounded radius (small-angle crossings: along the curve) as in test_intersect_vs_occt; our extra points
//   must be true self-intersections (|C(s1) - C(s2)| < 1e-9 with s1 < s2 distinct).
// - Figure-eight (exact symmetric crossing at the origin), a symmetric looped cubic, a cusp without
//   a loop, a closed circle (its seam is no self-intersection), the offset of the parabola y = x^2 by
//   d = 1 toward its centre of curvature (swallowtail: crossing on the axis at x = +-sqrt(3)/2,
//   y = 5/4, two cusps), and a polyline with an inner loop nested in an outer one.
#define BOOST_TEST_MODULE self_intersect
#include <boost/test/unit_test.hpp>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2dInt_GInter.hxx>
#include <IntRes2d_IntersectionPoint.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/self_intersect.hpp"
#include "src/algo/self_intersect_loops.hpp"
#include "src/core/error.hpp"
#include "support/random_geometry.hpp"

using namespace cg;
using V2 = Eigen::Vector2d;

namespace {
double crossing_sine(const BSplineCurve<2>& c, double s, double t) {
  const auto da = c.derivatives(s, 1), db = c.derivatives(t, 1);
  return std::abs(da[1].x() * db[1].y() - da[1].y() * db[1].x()) / (da[1].norm() * db[1].norm());
}
}  // namespace

BOOST_AUTO_TEST_CASE(random_curves_vs_occt) {
  test::Rng r(21);
  int occt_total = 0, occt_loose = 0, missed = 0, extra = 0, false_extra = 0, ours_total = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    Geom2dAPI_InterCurveCurve inter(occt::to_occt(c), 1e-6);
    const Geom2dInt_GInter& g = inter.Intersector();
    const auto ours = self_intersections(c);
    ours_total += static_cast<int>(ours.points.size());
    std::vector<bool> matched(ours.points.size(), false);
    for (int k = 1; k <= g.NbPoints(); ++k) {
      const IntRes2d_IntersectionPoint& ip = g.Point(k);
      const double s = ip.ParamOnFirst(), t = ip.ParamOnSecond();
      const V2 p(ip.Value().X(), ip.Value().Y());
      const double gap = (c.point(s) - c.point(t)).norm();
      ++occt_total;
      if (gap > 1e-9) {  // a contact within OCCT's tolerance only (see test_intersect_vs_occt)
        ++occt_loose;
        continue;
      }
      // Bounded match, as in test_intersect_vs_occt: a transversal crossing (sine >= 1e-3) within the
      // Euclidean radius 1e-9 + (gap + 1e-13) / sine <= 2e-6; a small-angle one within that distance
      // along the curve at both parameters, capped at 1e-4.
      const double sine = crossing_sine(c, s, t);
      const bool transversal = sine >= 1e-3;
      const double radius = transversal ? 1e-9 + (gap + 1e-13) / sine : std::min(1e-9 + (gap + 1e-13) / sine, 1e-4);
      auto along = [&](double a, double b) { return std::abs(b - a) * c.derivatives(a, 1)[1].norm(); };
      bool found = false;
      for (std::size_t j = 0; j < ours.points.size(); ++j) {
        const auto& q = ours.points[j];
        // Our pair is ordered s1 < s2; OCCT's may come either way round.
        const bool near = transversal ? (q.point - p).norm() <= radius
                                      : std::min(std::max(along(s, q.s1), along(t, q.s2)),
                                                 std::max(along(s, q.s2), along(t, q.s1))) <= radius;
        if (near) found = matched[j] = true;
      }
      if (!found) {
        ++missed;
        std::printf("curve %d: missed OCCT self-intersection s=%.17g t=%.17g\n", i, s, t);
      }
    }
    for (std::size_t j = 0; j < ours.points.size(); ++j) {
      const auto& q = ours.points[j];
      BOOST_TEST(q.s1 < q.s2);
      if (matched[j]) continue;
      ++extra;
      if ((c.point(q.s1) - c.point(q.s2)).norm() >= 1e-9) ++false_extra;
    }
  }
  std::printf("self-intersections of 1000 random curves: OCCT %d points (%d within its tol only), ours %d; "
              "%d missed, %d extra (%d not true)\n",
              occt_total, occt_loose, ours_total, missed, extra, false_extra);
  BOOST_TEST(missed == 0);
  BOOST_TEST(false_extra == 0);
}

BOOST_AUTO_TEST_CASE(figure_eight) {
  // Periodic cubic: symmetric under x -> -x with a half-period shift, so C(u) = C(u + T/2) on x = 0,
  // and under the point reflection, so that point is the origin.
  const std::vector<V2> P = {{1, 1}, {2, 0}, {1, -1}, {-1, 1}, {-2, 0}, {-1, -1}};
  const auto c = BSplineCurve<2>::periodic(3, {0, 1, 2, 3, 4, 5}, 6, P);
  const auto r = self_intersections(c);
  BOOST_TEST_REQUIRE(r.points.size() == 1u);
  BOOST_TEST(r.points[0].point.norm() < 1e-12);
  BOOST_TEST(std::abs(r.points[0].s2 - r.points[0].s1 - 3.0) < 1e-12);
  BOOST_TEST(r.points[0].kind == ContactKind::transversal);
}

BOOST_AUTO_TEST_CASE(looped_cubic_cusp_and_closed_circle) {
  {  // symmetric cubic (-1,0),(3,2),(-3,2),(1,0): x(u) is odd about u = 1/2, so the loop closes at
     // the root u* < 1/2 of x, with C(u*) = C(1 - u*)
    const BSplineCurve<2> c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{-1, 0}, {3, 2}, {-3, 2}, {1, 0}});
    double lo = 0.0, hi = 0.45;  // x(0) = -1 < 0, x(0.45) > 0
    for (int i = 0; i < 200; ++i) {
      const double m = 0.5 * (lo + hi);
      (c.point(m).x() < 0 ? lo : hi) = m;
    }
    const auto r = self_intersections(c);
    BOOST_TEST_REQUIRE(r.points.size() == 1u);
    BOOST_TEST(std::abs(r.points[0].s1 - lo) < 1e-12);
    BOOST_TEST(std::abs(r.points[0].s2 - (1 - lo)) < 1e-12);
  }
  {  // (0,0),(1,1),(0,1),(1,0): x' = 3(1-2u)^2 >= 0 and y' = 3 - 6u vanish together at u = 1/2 (a cusp),
     // x is monotone: no self-intersection
    const BSplineCurve<2> c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {0, 1}, {1, 0}});
    BOOST_TEST(self_intersections(c).points.empty());
    BOOST_TEST(self_intersections(c, 1e-6).points.empty());
  }
  {  // nine-point circle: start = end is the seam, not a self-intersection
    const double s = std::sqrt(0.5);
    const BSplineCurve<2> c(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                            {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
                            {1, s, 1, s, 1, s, 1, s, 1});
    BOOST_TEST(self_intersections(c).points.empty());
  }
}

BOOST_AUTO_TEST_CASE(parabola_offset_swallowtail) {
  // O(x) = (x, x^2) + d N(x), N = (-2x, 1) / r, r = sqrt(1 + 4x^2), d = 1, as a C1 cubic Hermite
  // B-spline on the parameter x: Bezier segments joined at the samples (triple interior knots). The
  // offset has cusps where the curvature 2 / r^3 equals 1/d, at x = +-sqrt((2d)^(2/3) - 1) / 2; they
  // are samples, where O' = 0, so the spline has true cusps there (a sample grid straddling them
  // would give the spline tiny real loops instead). The grid is symmetric, so the spline is exactly
  // mirror-symmetric and its crossing lies on the axis; Hermite sampling with h <= 0.05 is accurate
  // to ~1e-6, the tolerance on the crossing's position.
  const double d = 1.0, xc = std::sqrt(std::cbrt(4 * d * d) - 1) / 2;
  auto O = [&](double x) {
    const double r = std::sqrt(1 + 4 * x * x);
    return V2(x - 2 * d * x / r, x * x + d / r);
  };
  auto dO = [&](double x) {
    const double r = std::sqrt(1 + 4 * x * x), r3 = r * r * r;
    return V2(1 - 2 * d / r + 8 * d * x * x / r3, 2 * x - 4 * d * x / r3);
  };
  std::vector<double> xs = {-xc, xc};
  for (int i = 0; i <= 60; ++i) {
    const double x = -1.5 + 0.05 * i;
    if (std::abs(std::abs(x) - xc) > 0.01) xs.push_back(i == 30 ? 0.0 : x);
  }
  std::sort(xs.begin(), xs.end());
  std::vector<double> U = {xs.front(), xs.front(), xs.front(), xs.front()};
  std::vector<V2> P = {O(xs.front())};
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double x0 = xs[i], x1 = xs[i + 1], h = x1 - x0;
    P.push_back(O(x0) + h / 3 * dO(x0));
    P.push_back(O(x1) - h / 3 * dO(x1));
    P.push_back(O(x1));
    for (int k = 0; k < (i + 2 < xs.size() ? 3 : 4); ++k) U.push_back(x1);
  }
  const BSplineCurve<2> c(3, U, P);
  const auto r = self_intersections(c);
  BOOST_TEST_REQUIRE(r.points.size() == 1u);  // the two cusps are not self-intersections
  const auto& q = r.points[0];
  BOOST_TEST(std::abs(q.point.x()) < 1e-12);
  BOOST_TEST(std::abs(q.point.y() - 1.25) < 1e-6);
  BOOST_TEST(std::abs(q.s1 + std::sqrt(3.0) / 2) < 1e-5);
  BOOST_TEST(std::abs(q.s2 - std::sqrt(3.0) / 2) < 1e-5);
  BOOST_TEST(std::abs(q.s1 + q.s2) < 1e-12);
  const auto kept = kept_intervals(c.first_param(), c.last_param(), r.points);
  BOOST_TEST_REQUIRE(kept.size() == 2u);
  BOOST_TEST(kept[0].lo == -1.5);
  BOOST_TEST(kept[0].hi == q.s1);
  BOOST_TEST(kept[1].lo == q.s2);
  BOOST_TEST(kept[1].hi == 1.5);
}

BOOST_AUTO_TEST_CASE(nested_loops_polyline) {
  // Unit-speed segments on [i, i+1]: the outer crossing (4, 2) at u = 0.4 and 7.75, the inner one
  // (8, 10) at u = 2.5 and 5.5, nested inside the outer loop.
  const std::vector<V2> P = {{0, 2}, {10, 2}, {10, 10}, {6, 10}, {6, 12}, {8, 12}, {8, 8}, {4, 8}, {4, 0}};
  std::vector<double> U = {0, 0};
  for (int i = 1; i < 8; ++i) U.push_back(i);
  U.insert(U.end(), {8, 8});
  const BSplineCurve<2> c(1, U, P);
  const auto r = self_intersections(c);
  BOOST_TEST_REQUIRE(r.points.size() == 2u);
  BOOST_TEST(std::abs(r.points[0].s1 - 0.4) < 1e-12);
  BOOST_TEST(std::abs(r.points[0].s2 - 7.75) < 1e-12);
  BOOST_TEST(std::abs(r.points[1].s1 - 2.5) < 1e-12);
  BOOST_TEST(std::abs(r.points[1].s2 - 5.5) < 1e-12);
  const auto loops = loop_intervals(r.points);
  BOOST_TEST_REQUIRE(loops.size() == 1u);
  BOOST_TEST(loops[0].lo == r.points[0].s1);
  BOOST_TEST(loops[0].hi == r.points[0].s2);
  const auto kept = kept_intervals(0, 8, r.points);
  BOOST_TEST_REQUIRE(kept.size() == 2u);
  BOOST_TEST(kept[0].hi == r.points[0].s1);
  BOOST_TEST(kept[1].lo == r.points[0].s2);
}

BOOST_AUTO_TEST_CASE(loop_interval_rules) {
  auto si = [](double a, double b) { return SelfIntersection{a, b, V2::Zero(), ContactKind::transversal}; };
  // Two disjoint loops, one nested loop, one interleaved with the first (starts inside it).
  const std::vector<SelfIntersection> pts = {si(6, 8), si(1, 4), si(2, 3), si(3.5, 5), si(6.5, 7)};
  const auto loops = loop_intervals(pts);
  BOOST_TEST_REQUIRE(loops.size() == 2u);
  BOOST_TEST(loops[0].lo == 1);
  BOOST_TEST(loops[0].hi == 4);
  BOOST_TEST(loops[1].lo == 6);
  BOOST_TEST(loops[1].hi == 8);
  const auto kept = kept_intervals(0, 10, pts);
  BOOST_TEST_REQUIRE(kept.size() == 3u);
  BOOST_TEST(kept[0].lo == 0);
  BOOST_TEST(kept[0].hi == 1);
  BOOST_TEST(kept[1].lo == 4);
  BOOST_TEST(kept[1].hi == 6);
  BOOST_TEST(kept[2].lo == 8);
  BOOST_TEST(kept[2].hi == 10);
  BOOST_TEST(kept_intervals(0, 10, {}).size() == 1u);
  BOOST_CHECK_THROW(kept_intervals(1, 1, pts), InvalidGeometry);
}
