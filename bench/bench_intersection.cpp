// Curve-curve intersection speed: intersect_curves against OCCT's Geom2dAPI_InterCurveCurve (tolerance
// 1e-6, its default) on the same pairs in one run. Each pair: two planar cubic B-splines of 20 poles
// (uniform clamped knots), a wave y = 3 sin(6 pi x / 19) and a gently sloped line-like curve, which
// cross about 6 times; the pairs differ by a deterministic vertical shift and slope of the second curve.
// Before timing, the two results are compared on every pair (point counts and the largest distance
// from an OCCT point to our nearest point are printed) so a fast wrong answer shows up.
//
// Timing: best of several repetitions (least disturbed by the other jobs on this shared machine).
// Usage: bench_intersection [--quick]   (--quick: 50 pairs, 2 repetitions)
#include <Geom2dAPI_InterCurveCurve.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/core/knots.hpp"

namespace {

using cg::BSplineCurve;
using V2 = Eigen::Vector2d;
constexpr double kPi = 3.14159265358979323846;

BSplineCurve<2> cubic(const std::vector<V2>& poles) {
  return BSplineCurve<2>(3, cg::uniform_clamped_knots(3, static_cast<int>(poles.size())), poles);
}

struct Pair {
  BSplineCurve<2> a, b;
  Handle(Geom2d_Curve) oa, ob;
};

std::vector<Pair> make_pairs(int n) {
  std::vector<Pair> pairs;
  for (int k = 0; k < n; ++k) {
    const double shift = 0.8 * std::sin(0.37 * k), slope = 0.02 * std::cos(0.53 * k);
    std::vector<V2> pa, pb;
    for (int i = 0; i < 20; ++i) {
      pa.emplace_back(i, 3.0 * std::sin(6.0 * kPi * i / 19.0));
      pb.emplace_back(i + 0.3, shift + slope * (i - 9.5) + 0.2 * std::cos(0.9 * i));
    }
    Pair p{cubic(pa), cubic(pb), nullptr, nullptr};
    p.oa = cg::occt::to_occt(p.a);
    p.ob = cg::occt::to_occt(p.b);
    pairs.push_back(std::move(p));
  }
  return pairs;
}

template <class Run>
double best_seconds(int reps, Run run) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int n = quick ? 50 : 400, reps = quick ? 2 : 5;
  const auto pairs = make_pairs(n);

  // Agreement check on every pair.
  long ours_total = 0, occt_total = 0;
  double worst = 0.0;
  for (const auto& p : pairs) {
    const auto r = cg::intersect_curves(p.a, p.b, 1e-9);
    Geom2dAPI_InterCurveCurve o(p.oa, p.ob, 1e-6);
    ours_total += static_cast<long>(r.points.size());
    occt_total += o.NbPoints();
    for (int i = 1; i <= o.NbPoints(); ++i) {
      const V2 q(o.Point(i).X(), o.Point(i).Y());
      double best = 1e300;
      for (const auto& x : r.points) best = std::min(best, (x.point - q).norm());
      worst = std::max(worst, best);
    }
  }
  std::printf("%d pairs: %.2f crossings/pair (ours), %.2f (OCCT); worst OCCT point to ours: %.2e\n", n,
              static_cast<double>(ours_total) / n, static_cast<double>(occt_total) / n, worst);

  long sink = 0;
  const double t_ours = best_seconds(reps, [&] {
    for (const auto& p : pairs) sink += static_cast<long>(cg::intersect_curves(p.a, p.b, 1e-9).points.size());
  });
  const double t_occt = best_seconds(reps, [&] {
    for (const auto& p : pairs) {
      Geom2dAPI_InterCurveCurve o(p.oa, p.ob, 1e-6);
      sink += o.NbPoints();
    }
  });
  std::printf("ours: %.0f pairs/s   OCCT Geom2dAPI_InterCurveCurve: %.0f pairs/s   ratio %.1fx   (checksum %ld)\n",
              n / t_ours, n / t_occt, t_occt / t_ours, sink);
  return 0;
}
