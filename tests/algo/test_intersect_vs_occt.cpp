// intersect_curves against OCCT's Geom2dAPI_InterCurveCurve (tolerance 1e-6, its default) on random
// curve pairs (polynomial and rational, degrees 1..7, repeated interior knots) and on constructed
// tangent, near-tangent and overlapping pairs.
// Tolerances (see compare()): an OCCT crossing at an angle with sine >= 1e-3 must have one of our points
// within 1e-9 + (its gap + 1e-13) / 1e-3 (<= 2e-6; the curves live in [-10, 10]^2); a smaller-angle or
// tangential one must have one of our points within a distance along BOTH curves of
// min(1e-9 + (gap + 1e-13) / sine, 1e-4). Points only we find must be true intersections.
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
  int occt_loose = 0, loose_missed = 0;  // OCCT points that are tolerance contacts (gap > 1e-9)
  void print(const char* what) const {
    std::printf("%s: %d pairs, %d OCCT points (%d of them contacts within OCCT's tol only, %d of those "
                "outside the tolerance zone of every point of ours), %d missed, %d extra (%d not true intersections)\n",
                what, pairs, occt_points, occt_loose, loose_missed, missed, extra, false_extra);
  }
};

// Sine of the angle between the tangents at A(s), B(t).
double crossing_sine(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double s, double t) {
  const auto da = a.derivatives(s, 1), db = b.derivatives(t, 1);
  return std::abs(da[1].x() * db[1].y() - da[1].y() * db[1].x()) / (da[1].norm() * db[1].norm());
}

// True when the straight parameter path from (s0, t0) to (s1, t1) keeps the curves within `gap`.
bool within_zone(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double s0, double t0, double s1, double t1,
                 double gap) {
  for (int k = 0; k <= 64; ++k) {
    const double f = k / 64.0;
    if ((a.point(s0 + f * (s1 - s0)) - b.point(t0 + f * (t1 - t0))).norm() > gap) return false;
  }
  return true;
}

// Arc length between parameters a and b of c (|b - a| |c'| to first order: a and b are close).
double along(const BSplineCurve<2>& c, double a, double b) { return std::abs(b - a) * c.derivatives(a, 1)[1].norm(); }

// Compares one pair; returns our result (at tol) for further checks.
// - An OCCT point with gap |A(s) - B(t)| <= 1e-9 is a crossing. A residual g moves a crossing of
//   tangent angle theta by g / sin(theta) along the curves (1e-13: rounding of our residual at this
//   model size). Transversal (sine >= 1e-3): one of our points within the bounded Euclidean radius
//   1e-9 + (g + 1e-13) / max(sine, 1e-3) <= 2e-6. Small-angle or tangential (sine < 1e-3): Euclidean
//   distance cannot tell two neighbouring contacts of nearly parallel curves apart, so one of our
//   points must be that close along BOTH curves, within min(1e-9 + (g + 1e-13) / sine, 1e-4): the
//   conditioning bound, capped at 1e-4 of length (5e-6 of the model size; measured: <= 7e-9).
// - An OCCT point with a larger gap is a contact within OCCT's tolerance 1e-6 only (OCCT lists several
//   along the zone where small-angle crossings stay within 1e-6). It is matched when a straight
//   parameter path to one of our points (at the same tolerance) stays within 2e-6 (linear paths
//   deviate slightly from the true correspondence); otherwise it counts as a loose miss.
CurveCurveIntersections compare(const BSplineCurve<2>& a, const BSplineCurve<2>& b, Tally& tally, double tol = 1e-9) {
  int segments = 0;
  const auto ref = occt_points(a, b, segments);
  const auto ours = intersect_curves(a, b, tol);
  CurveCurveIntersections loose;
  bool loose_done = false;
  ++tally.pairs;
  tally.occt_points += static_cast<int>(ref.size());
  std::vector<bool> matched(ours.points.size(), false);
  for (const auto& r : ref) {
    const double occt_gap = (a.point(r.s) - b.point(r.t)).norm();
    if (occt_gap > 1e-9) {
      ++tally.occt_loose;
      if (!loose_done) loose = intersect_curves(a, b, 1e-6);
      loose_done = true;
      bool near = false;
      for (const auto& q : loose.points) near = near || within_zone(a, b, r.s, r.t, q.s, q.t, 2e-6);
      for (const auto& o : loose.overlaps) near = near || (r.s >= o.s0 - 1e-6 && r.s <= o.s1 + 1e-6);
      tally.loose_missed += !near;
      if (!near) std::printf("loose OCCT point s=%.17g t=%.17g gap %.2e unmatched\n", r.s, r.t, occt_gap);
      continue;
    }
    const double sine = crossing_sine(a, b, r.s, r.t);
    const bool transversal = sine >= 1e-3;
    const double radius = transversal ? 1e-9 + (occt_gap + 1e-13) / sine
                                      : std::min(1e-9 + (occt_gap + 1e-13) / std::max(sine, 1e-300), 1e-4);
    bool found = false;
    for (std::size_t i = 0; i < ours.points.size(); ++i) {
      const auto& q = ours.points[i];
      const bool near = transversal ? (q.point - r.p).norm() <= radius
                                    : along(a, r.s, q.s) <= radius && along(b, r.t, q.t) <= radius;
      if (near) {
        found = true;
        matched[i] = true;
      }
    }
    // A point of OCCT inside one of our overlaps is covered by it.
    for (const auto& o : ours.overlaps)
      if (r.s >= o.s0 - 1e-9 && r.s <= o.s1 + 1e-9) found = true;
    if (!found) {
      ++tally.missed;
      std::printf("missed OCCT point s=%.17g t=%.17g\n", r.s, r.t);
    }
    BOOST_TEST(found);
  }
  for (std::size_t i = 0; i < ours.points.size(); ++i) {
    if (matched[i]) continue;
    const auto& p = ours.points[i];
    ++tally.extra;
    // Tangential contacts are accepted up to tol; crossings must be exact.
    const double gap = (a.point(p.s) - b.point(p.t)).norm();
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
  tally.print("random pairs");
  BOOST_TEST(tally.missed == 0);
  BOOST_TEST(tally.loose_missed == 0);
}

// Periodic curves (seams inside the domain of the other curve's crossings) against random curves.
BOOST_AUTO_TEST_CASE(periodic_random_pairs) {
  test::Rng r(14);
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    const int p = r.integer(1, 5), n = r.integer(p + 1, p + 8);
    std::vector<double> knots;
    for (int k = 0; k < n; ++k) knots.push_back(k + r.uniform(-0.3, 0.3));
    std::vector<Eigen::Vector2d> P;
    std::vector<double> w;
    for (int k = 0; k < n; ++k) {
      P.emplace_back(r.uniform(-10, 10), r.uniform(-10, 10));
      w.push_back(i % 2 ? r.uniform(0.2, 5) : 1.0);
    }
    const auto a = BSplineCurve<2>::periodic(p, knots, n, P, w);
    const auto b = test::random_curve<2>(r, i % 4 >= 2);
    const auto res = compare(a, b, tally);
    for (const auto& q : res.points) BOOST_TEST((q.s >= a.first_param() && q.s < a.last_param()));
  }
  tally.print("periodic pairs");
  BOOST_TEST(tally.missed == 0);
  BOOST_TEST(tally.loose_missed == 0);
}

namespace {
BSplineCurve<2> moved(const BSplineCurve<2>& c, const Eigen::Vector2d& v) {
  std::vector<Eigen::Vector2d> P;
  for (const auto& p : c.poles()) P.push_back(p + v);
  return BSplineCurve<2>(c.degree(), c.knots(), P, c.is_rational() ? c.weights() : std::vector<double>{});
}
}  // namespace

// A random curve against a slightly moved copy of itself: many crossings at small angles.
BOOST_AUTO_TEST_CASE(near_tangent_copies) {
  test::Rng r(12);
  Tally tally;
  for (int i = 0; i < 160; ++i) {
    const auto a = test::random_curve<2>(r, i % 2 == 1);
    const double len = i < 80 ? 1e-2 : 1e-4, ang = r.uniform(0, 6.283185307179586);
    compare(a, moved(a, len * Eigen::Vector2d(std::cos(ang), std::sin(ang))), tally);
  }
  tally.print("near-tangent copies");
  BOOST_TEST(tally.missed == 0);
  BOOST_TEST(tally.loose_missed == 0);
}

// A random curve and a sub-segment of itself (OCCT's Segment: re-knotted, same geometry): one overlap
// on [u1, u2] of the first curve, covering the whole second; OCCT reports a segment too.
BOOST_AUTO_TEST_CASE(curve_and_its_subsegment_overlap) {
  test::Rng r(13);
  int occt_segments = 0;
  for (int i = 0; i < 100; ++i) {
    const auto a = test::random_curve<2>(r, i % 2 == 1);
    const double f = a.first_param(), l = a.last_param();
    double u1 = r.uniform(f, l), u2 = r.uniform(f, l);
    if (u1 > u2) std::swap(u1, u2);
    if (u2 - u1 < 0.05 * (l - f)) u2 = std::min(l, u1 + 0.05 * (l - f));
    Handle(Geom2d_BSplineCurve) seg = occt::to_occt(a);
    seg->Segment(u1, u2);
    const auto b = occt::from_occt(*seg);
    Geom2dAPI_InterCurveCurve inter(occt::to_occt(a), seg, 1e-6);
    occt_segments += inter.NbSegments() > 0;
    const auto res = intersect_curves(a, b);
    BOOST_TEST_REQUIRE(!res.overlaps.empty());
    // The sub-segment may also cross other parts of the curve: those are points, not overlaps.
    bool whole = false;
    for (const auto& o : res.overlaps)
      whole = whole || (std::abs(o.s0 - u1) <= 1e-9 * (l - f) && std::abs(o.s1 - u2) <= 1e-9 * (l - f) &&
                        std::abs(o.t0 - u1) <= 1e-9 * (l - f) && std::abs(o.t1 - u2) <= 1e-9 * (l - f));
    BOOST_TEST(whole);
    if (!whole)
      for (const auto& o : res.overlaps)
        std::printf("case %d: [%g %g] expected [%g %g] t [%g %g]\n", i, o.s0, o.s1, u1, u2, o.t0, o.t1);
    for (const auto& p : res.points) BOOST_TEST((a.point(p.s) - b.point(p.t)).norm() < 1e-9);
  }
  BOOST_TEST(occt_segments >= 90);
}

// Constructed tangencies: OCCT must report the contact, and ours must be at the exact point.
BOOST_AUTO_TEST_CASE(constructed_tangencies) {
  const double s = std::sqrt(0.5);
  const std::vector<Eigen::Vector2d> P = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  const BSplineCurve<2> circle(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P, {1, s, 1, s, 1, s, 1, s, 1});
  const BSplineCurve<2> parabola(2, {0, 0, 0, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});
  struct Case {
    BSplineCurve<2> a, b;
    Eigen::Vector2d contact;
  };
  const std::vector<Case> cases = {
      {circle, BSplineCurve<2>(1, {0, 0, 1, 1}, {{-2, 1}, {2, 1}}), {0, 1}},
      {circle, BSplineCurve<2>(1, {0, 0, 1, 1}, {{1.2, -2}, {std::sqrt(0.5) * 2 - 1.2, 2 - 2 * 0}}), {0, 0}},
      {parabola, BSplineCurve<2>(1, {0, 0, 1, 1}, {{-1, -1.25}, {2, 1.75}}), {0.5, 0.25}},
      {circle, moved(circle, {2, 0}), {1, 0}},
      {circle, moved(circle, {std::sqrt(2.0), std::sqrt(2.0)}), {s, s}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& c = cases[k];
    int segments = 0;
    const auto ref = occt_points(c.a, c.b, segments);
    const auto ours = intersect_curves(c.a, c.b);
    if (k == 1) {
      // Not a tangency: the line crosses the unit circle where |P0 + l (P1 - P0)| = 1, l in [0, 1]
      // (a quadratic in l). Both tools must find exactly these crossings; ours to rounding (1e-12).
      const Eigen::Vector2d P0 = c.b.point(0.0), d = c.b.point(1.0) - P0;
      const double qa = d.squaredNorm(), qb = 2 * P0.dot(d), qc = P0.squaredNorm() - 1;
      const double disc = std::sqrt(qb * qb - 4 * qa * qc);
      std::vector<Eigen::Vector2d> exact;
      for (double l : {(-qb - disc) / (2 * qa), (-qb + disc) / (2 * qa)})
        if (l >= 0 && l <= 1) exact.push_back(P0 + l * d);
      BOOST_TEST_REQUIRE(exact.size() == 2u);  // a secant
      BOOST_TEST_REQUIRE(ours.points.size() == exact.size());
      BOOST_TEST_REQUIRE(ref.size() == exact.size());
      for (const auto& x : exact) {
        double ours_best = 1e300, occt_best = 1e300;
        for (const auto& q : ours.points) ours_best = std::min(ours_best, (q.point - x).norm());
        for (const auto& q : ref) occt_best = std::min(occt_best, (q.p - x).norm());
        BOOST_TEST(ours_best <= 1e-12);
        BOOST_TEST(occt_best <= 1e-9);
      }
      for (const auto& q : ours.points) BOOST_TEST(q.kind == ContactKind::transversal);
      continue;
    }
    bool occt_found = false;
    for (const auto& p : ref) occt_found = occt_found || (p.p - c.contact).norm() < 1e-6;
    std::printf("tangency %zu: OCCT %s the contact\n", k, occt_found ? "finds" : "misses");
    BOOST_TEST_REQUIRE(ours.points.size() == 1u);
    BOOST_TEST((ours.points[0].point - c.contact).norm() < 1e-12);
    BOOST_TEST(ours.points[0].kind == ContactKind::tangent);
    for (const auto& p : ref) std::printf("tangency %zu: OCCT point off by %.2e\n", k, (p.p - c.contact).norm());
  }
}

// Near tangencies: a line 1e-7 below the parabola's tangent crosses twice (both tools must agree);
// 1e-7 above it, nothing at tol 1e-9, and at tol 1e-6 (OCCT's) a tangential contact 1e-7 wide.
BOOST_AUTO_TEST_CASE(near_tangencies) {
  const BSplineCurve<2> parabola(2, {0, 0, 0, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});
  for (double d : {1e-7, -1e-7, 1e-5, -1e-5}) {
    const BSplineCurve<2> line(1, {0, 0, 1, 1}, {{-1, -1.25 + d}, {2, 1.75 + d}});
    Tally tally;
    const auto ours = compare(parabola, line, tally, 1e-9);
    BOOST_TEST(tally.missed == 0);
    BOOST_TEST(ours.points.size() == (d > 0 ? 2u : 0u));
    int segments = 0;
    const auto ref = occt_points(parabola, line, segments);
    const auto loose = intersect_curves(parabola, line, 1e-6);
    std::printf("near tangency d=%g: OCCT %zu points, ours %zu (tol 1e-9), %zu (tol 1e-6)\n", d, ref.size(),
                ours.points.size(), loose.points.size());
    if (d == -1e-7) BOOST_TEST(loose.points.size() == 1u);
  }
}
