// Curve-curve intersection speed: intersect_curves against OCCT's Geom2dAPI_InterCurveCurve on the same
// pairs, at the SAME tolerance (kTol = 1e-9 for both), in one run. Two families:
//  - "waves": two planar cubic B-splines of 20 poles (uniform clamped knots), a wave
//    y = 3 sin(6 pi x / 19) and a gently sloped line-like curve, crossing about 6 times; the pairs
//    differ by a deterministic vertical shift and slope of the second curve;
//  - "hard": a rational quintic wave (40 poles, weights 0.5..1.5, 5 periods) against a second one of 7
//    periods (many crossings), and the same wave against a copy of itself moved by 1e-4 (near-tangent
//    crossings at tiny angles, where the tangent is parallel to the move).
// Checking, on the results of the timed runs: every OCCT point with gap |A(s) - B(t)| <= kTol must
// have one of our points within the crossing's conditioning (bounded: 1e-9 + (gap + 1e-13) /
// max(sine, 1e-3) for transversal crossings, the same distance along both curves capped at 1e-4 for
// small-angle ones, as in tests/algo/test_intersect_vs_occt.cpp), and every point of ours must be a
// true intersection (gap <= kTol) - an extra point of ours is a crossing OCCT missed. Any disagreement
// makes the program exit with status 1.
//
// Timing: best of several repetitions (least disturbed by the other jobs on this shared machine).
// Usage: bench_intersection [--quick]   (--quick: 100 + 12 pairs, 2 repetitions; else 400 + 60, best of 5
// and 3)
#include <Geom2dAPI_InterCurveCurve.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "bench_check.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/core/constants.hpp"
#include "src/core/knots.hpp"

namespace {

using cg::BSplineCurve;
using V2 = Eigen::Vector2d;
using cg::kPi;
constexpr double kTol = 1e-9;

struct Pair {
  BSplineCurve<2> a, b;
  Handle(Geom2d_Curve) oa, ob;
};

Pair make_pair(BSplineCurve<2> a, BSplineCurve<2> b) {
  Pair p{std::move(a), std::move(b), nullptr, nullptr};
  p.oa = cg::occt::to_occt(p.a);
  p.ob = cg::occt::to_occt(p.b);
  return p;
}

BSplineCurve<2> curve(int p, const std::vector<V2>& poles, const std::vector<double>& w = {}) {
  return BSplineCurve<2>(p, cg::uniform_clamped_knots(p, static_cast<int>(poles.size())), poles, w);
}

std::vector<Pair> waves(int n) {
  std::vector<Pair> pairs;
  for (int k = 0; k < n; ++k) {
    const double shift = 0.8 * std::sin(0.37 * k), slope = 0.02 * std::cos(0.53 * k);
    std::vector<V2> pa, pb;
    for (int i = 0; i < 20; ++i) {
      pa.emplace_back(i, 3.0 * std::sin(6.0 * kPi * i / 19.0));
      pb.emplace_back(i + 0.3, shift + slope * (i - 9.5) + 0.2 * std::cos(0.9 * i));
    }
    pairs.push_back(make_pair(curve(3, pa), curve(3, pb)));
  }
  return pairs;
}

std::vector<Pair> hard(int n) {
  std::vector<Pair> pairs;
  for (int k = 0; k < n; ++k) {
    std::vector<V2> pa, pb, pc;
    std::vector<double> wa, wb;
    for (int i = 0; i < 40; ++i) {
      pa.emplace_back(0.5 * i, 3.0 * std::sin(10.0 * kPi * i / 39.0 + 0.1 * k));
      pb.emplace_back(0.5 * i + 0.2, 2.5 * std::sin(14.0 * kPi * i / 39.0 - 0.2 * k) + 0.3 * std::cos(0.7 * i));
      wa.push_back(1.0 + 0.5 * std::sin(1.3 * i + k));
      wb.push_back(1.0 + 0.5 * std::cos(0.9 * i - k));
    }
    const BSplineCurve<2> a = curve(5, pa, wa);
    pairs.push_back(make_pair(a, curve(5, pb, wb)));
    // The same wave moved by 1e-4 in a direction depending on k: near-tangent crossings.
    const V2 move = 1e-4 * V2(std::cos(0.7 * k), std::sin(0.7 * k));
    for (const auto& q : pa) pc.push_back(q + move);
    pairs.push_back(make_pair(a, curve(5, pc, wa)));
  }
  return pairs;
}

double sine(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double s, double t) {
  const V2 da = a.derivatives(s, 1)[1], db = b.derivatives(t, 1)[1];
  return std::abs(da.x() * db.y() - da.y() * db.x()) / (da.norm() * db.norm());
}

double along(const BSplineCurve<2>& c, double a, double b) { return std::abs(b - a) * c.derivatives(a, 1)[1].norm(); }

struct OcctPoint {
  double s, t;
  V2 p;
};

void run_family(const char* name, const std::vector<Pair>& pairs, int reps, bench::Checker& check) {
  std::vector<cg::CurveCurveIntersections> ours(pairs.size());
  std::vector<std::vector<OcctPoint>> occt(pairs.size());
  const double t_ours = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pairs.size(); ++i) ours[i] = cg::intersect_curves(pairs[i].a, pairs[i].b, kTol);
  });
  const double t_occt = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      Geom2dAPI_InterCurveCurve o(pairs[i].oa, pairs[i].ob, kTol);
      const auto& g = o.Intersector();
      occt[i].clear();
      for (int k = 1; k <= g.NbPoints(); ++k)
        occt[i].push_back({g.Point(k).ParamOnFirst(), g.Point(k).ParamOnSecond(), V2(g.Point(k).Value().X(), g.Point(k).Value().Y())});
    }
  });
  long n_ours = 0, n_occt = 0, extra = 0;
  double worst = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto& a = pairs[i].a;
    const auto& b = pairs[i].b;
    n_ours += static_cast<long>(ours[i].points.size());
    n_occt += static_cast<long>(occt[i].size());
    std::vector<bool> matched(ours[i].points.size(), false);
    for (const auto& r : occt[i]) {
      const double gap = (a.point(r.s) - b.point(r.t)).norm();
      if (gap > kTol) continue;  // a contact within OCCT's tolerance only, no crossing
      const double sn = sine(a, b, r.s, r.t);
      const bool transversal = sn >= 1e-3;
      const double radius = transversal ? 1e-9 + (gap + 1e-13) / sn : std::min(1e-9 + (gap + 1e-13) / sn, 1e-4);
      double best = 1e300;
      for (std::size_t j = 0; j < ours[i].points.size(); ++j) {
        const auto& q = ours[i].points[j];
        const double d = transversal ? (q.point - r.p).norm() : std::max(along(a, r.s, q.s), along(b, r.t, q.t));
        best = std::min(best, d);
        if (d <= radius) matched[j] = true;
      }
      worst = std::max(worst, best);
      if (!(best <= radius))
        check.fail("%s pair %zu: OCCT crossing (s %.17g, t %.17g) has no point of ours within %.2e", name, i, r.s, r.t, radius);
    }
    for (std::size_t j = 0; j < ours[i].points.size(); ++j) {
      const auto& q = ours[i].points[j];
      const double gap = (a.point(q.s) - b.point(q.t)).norm();
      if (gap > kTol) check.fail("%s pair %zu: our point (s %.17g, t %.17g) has gap %.2e", name, i, q.s, q.t, gap);
      if (!matched[j]) ++extra;
    }
  }
  const double np = static_cast<double>(pairs.size());
  std::printf("%-6s %4zu pairs: %.2f crossings/pair (ours), %.2f (OCCT); %ld of ours are crossings OCCT "
              "missed; worst distance OCCT point to ours %.1e\n",
              name, pairs.size(), n_ours / np, n_occt / np, extra, worst);
  std::printf("       ours %.0f pairs/s   OCCT Geom2dAPI_InterCurveCurve %.0f pairs/s   ratio %.1fx   (tolerance %g "
              "both)\n",
              np / t_ours, np / t_occt, t_occt / t_ours, kTol);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 2 : 5;
  bench::Checker check;
  run_family("waves", waves(quick ? 100 : 400), reps, check);
  run_family("hard", hard(quick ? 6 : 30), quick ? 2 : 3, check);
  return check.finish("bench_intersection");
}
