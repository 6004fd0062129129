// intersect_curves against OCCT's Geom2dAPI_InterCurveCurve (tolerance 1e-6, its default) on random
// curve pairs (polynomial and rational, degrees 1..7, repeated interior knots) and on constructed
// tangent, near-tangent and overlapping pairs.
// Tolerances: OCCT refines its points to a residual ~1e-15, so every OCCT point must have one of ours
// within 1e-9 (absolute; the curves live in [-10, 10]^2). Points only we find must be true
// intersections: |A(s) - B(t)| < 1e-9.
#define BOOST_TEST_MODULE intersect_vs_occt
#include <boost/test/unit_test.hpp>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2dInt_GInter.hxx>
#include <IntRes2d_IntersectionPoint.hxx>

#include <cstdio>

#include "adaptors/occt_convert.hpp"
#include "src/algo/intersect_curves.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

struct OcctPoint {
  double s, t;
  Eigen::Vector2d p;
};

std::vector<OcctPoint> occt_points(const BSplineCurve<2>& a, const BSplineCurve<2>& b, int& segments) {
  Geom2dAPI_InterCurveCurve inter(occt::to_occt(a), occt::to_occt(b), 1e-6);
  std::vector<OcctPoint> out;
  const Geom2dInt_GInter& g = inter.Intersector();
  for (int i = 1; i <= g.NbPoints(); ++i) {
    const IntRes2d_IntersectionPoint& ip = g.Point(i);
    out.push_back({ip.ParamOnFirst(), ip.ParamOnSecond(), {ip.Value().X(), ip.Value().Y()}});
  }
  segments = g.NbSegments();
  return out;
}

struct Tally {
  int pairs = 0, occt_points = 0, missed = 0, extra = 0, false_extra = 0;
};

// Compares one pair; returns our result for further checks.
CurveCurveIntersections compare(const BSplineCurve<2>& a, const BSplineCurve<2>& b, Tally& tally, double tol = 1e-9) {
  int segments = 0;
  const auto ref = occt_points(a, b, segments);
  const auto ours = intersect_curves(a, b, tol);
  ++tally.pairs;
  tally.occt_points += static_cast<int>(ref.size());
  std::vector<bool> matched(ours.points.size(), false);
  for (const auto& r : ref) {
    bool found = false;
    for (std::size_t i = 0; i < ours.points.size(); ++i)
      if ((ours.points[i].point - r.p).norm() <= 1e-9) {
        found = true;
        matched[i] = true;
      }
    // A point of OCCT inside one of our overlaps is covered by it.
    for (const auto& o : ours.overlaps)
      if (r.s >= o.s0 - 1e-9 && r.s <= o.s1 + 1e-9) found = true;
    if (!found) {
      ++tally.missed;
      double best = 1e300;
      for (const auto& q : ours.points) best = std::min(best, (q.point - r.p).norm());
      std::printf("missed OCCT point s=%.17g t=%.17g nearest %g occt gap %g\n", r.s, r.t, best, (a.point(r.s)-b.point(r.t)).norm());
    }
    BOOST_TEST(found);
  }
  for (std::size_t i = 0; i < ours.points.size(); ++i) {
    const auto& p = ours.points[i];
    const double gap = (a.point(p.s) - b.point(p.t)).norm();
    if (matched[i]) continue;
    ++tally.extra;
    if (getenv("VERBOSE")) { double best = 1e300;
      for (const auto& q : ref) best = std::min(best, (q.p - p.point).norm());
      std::printf("extra s=%.17g t=%.17g nearest occt %g gap %g kind %d\n", p.s, p.t, best, gap, (int)p.kind); }
    // Tangential contacts are accepted up to tol; crossings must be exact.
    if (gap >= (p.kind == ContactKind::tangent ? std::max(tol, 1e-9) : 1e-9)) ++tally.false_extra;
  }
  BOOST_TEST(tally.false_extra == 0);
  return ours;
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_pairs) {
  test::Rng r(11);
  Tally tally;
  for (int i = 0; i < 1000; ++i) {
    const auto a = test::random_curve<2>(r, i % 2 == 1);
    const auto b = test::random_curve<2>(r, i % 4 >= 2);
    compare(a, b, tally);
  }
  std::printf("random pairs: %d pairs, %d OCCT points, %d missed, %d extra (%d not true intersections)\n",
              tally.pairs, tally.occt_points, tally.missed, tally.extra, tally.false_extra);
  BOOST_TEST(tally.missed == 0);
}
