// Point projection speed: our CurveProjector / SurfaceProjector against OCCT on the same geometry and
// the same points, in one run.
//  Curve: rational cubic, 32 poles (3D), points scattered around the curve (within 5% of its size);
//         OCCT = GeomAPI_ProjectPointOnCurve, both per point (constructor) and initialised once
//         (Init(curve, first, last) + Perform(P)); the faster is the reference.
//  Surface: rational bicubic, 12 x 12 poles, points scattered around it; OCCT =
//         GeomAPI_ProjectPointOnSurf initialised once on the bounds (Init + Perform).
// Checking, on the results of the timed runs: ours must never be farther than OCCT's + 1e-9 (both
// converge Newton to rounding; the distance is stationary at a foot); where ours is strictly smaller
// (OCCT returned a local minimum, or no extremum with the foot on the boundary) our point is verified
// independently: it is the curve's / surface's point at our parameters and at our distance from P.
// Any disagreement makes the program exit with status 1.
// Timing: best of several repetitions (least disturbed on this shared machine).
//
// Usage: bench_projection [--quick]
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "bench_check.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/knots.hpp"

namespace {

using Vec3 = Eigen::Vector3d;
volatile double g_sink = 0.0;

bench::Checker g_check;


void bench_curve(int npoints, int reps) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> U(-1, 1), Wt(0.5, 2.0);
  const int n = 32, p = 3;
  std::vector<Vec3> poles;
  std::vector<double> w;
  for (int i = 0; i < n; ++i) {
    poles.emplace_back(10.0 * i, 20.0 * std::sin(0.4 * i) + 3 * U(gen), 15.0 * std::cos(0.3 * i) + 3 * U(gen));
    w.push_back(Wt(gen));
  }
  const cg::BSplineCurve<3> curve(p, cg::uniform_clamped_knots(p, n), poles, w);
  const auto oc = cg::occt::to_occt(curve);
  std::vector<Vec3> pts;
  for (int i = 0; i < npoints; ++i) {
    const double u = 0.5 * (U(gen) + 1.0);
    pts.push_back(curve.point(u) + 15.0 * Vec3(U(gen), U(gen), U(gen)));
  }
  cg::CurveProjector<3> proj(curve);
  GeomAPI_ProjectPointOnCurve api;
  api.Init(oc, curve.first_param(), curve.last_param());
  std::vector<cg::CurveProjection<3>> ours(pts.size());
  std::vector<double> occt(pts.size());
  const double t_ours = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pts.size(); ++i) ours[i] = proj.project(pts[i]);
  });
  const double t_occt_init = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      api.Perform(cg::occt::to_pnt(pts[i]));
      occt[i] = api.NbPoints() > 0 ? api.LowerDistance() : 1e300;
    }
  });
  const double t_occt_ctor = bench::best_seconds(std::max(1, reps / 2), [&](int) {
    double s = 0;
    for (const auto& P : pts) {
      GeomAPI_ProjectPointOnCurve a(cg::occt::to_pnt(P), oc);
      if (a.NbPoints() > 0) s += a.LowerDistance();
    }
    g_sink = g_sink + s;
  });
  int ours_smaller = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    // OCCT reports interior extrema: the curve ends complete its answer.
    const double o = std::min({occt[i], (curve.point(curve.first_param()) - pts[i]).norm(),
                               (curve.point(curve.last_param()) - pts[i]).norm()});
    const auto& r = ours[i];
    if (r.distance > o + 1e-9) g_check.fail("curve point %zu: ours %.17g, OCCT %.17g", i, r.distance, o);
    if (r.distance < o - 1e-9) {
      ++ours_smaller;
      if ((curve.point(r.param) - r.point).norm() > 1e-12 * (1 + r.point.norm()) ||
          std::abs((r.point - pts[i]).norm() - r.distance) > 1e-12 * (1 + r.distance))
        g_check.fail("curve point %zu: our closer point %.17g is not on the curve at that distance", i, r.distance);
    }
  }
  std::printf("curve: %d points, ours strictly closer than OCCT (verified on the curve): %d\n", npoints, ours_smaller);
  const double t_occt = std::min(t_occt_init, t_occt_ctor);
  std::printf("curve projection (rational cubic, 32 poles): ours %.0f /s, OCCT Init+Perform %.0f /s, "
              "OCCT per-point ctor %.0f /s, ratio %.1fx\n",
              npoints / t_ours, npoints / t_occt_init, npoints / t_occt_ctor, t_occt / t_ours);
}

void bench_surface(int npoints, int reps) {
  std::mt19937_64 gen(9);
  std::uniform_real_distribution<double> U(-1, 1), Wt(0.5, 2.0);
  const int n = 12, p = 3;
  std::vector<std::vector<Vec3>> poles(n, std::vector<Vec3>(n));
  std::vector<std::vector<double>> w(n, std::vector<double>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      poles[i][j] = Vec3(10.0 * i, 10.0 * j, 8.0 * std::sin(0.5 * i) * std::cos(0.4 * j) + 2 * U(gen));
      w[i][j] = Wt(gen);
    }
  const cg::BSplineSurface<3> surf(p, p, cg::uniform_clamped_knots(p, n), cg::uniform_clamped_knots(p, n), poles, w);
  const auto os = cg::occt::to_occt(surf);
  std::vector<Vec3> pts;
  for (int i = 0; i < npoints; ++i)
    pts.push_back(surf.point(0.5 * (U(gen) + 1), 0.5 * (U(gen) + 1)) + 6.0 * Vec3(U(gen), U(gen), U(gen)));
  cg::SurfaceProjector proj(surf);
  GeomAPI_ProjectPointOnSurf api;
  api.Init(os, surf.first_u(), surf.last_u(), surf.first_v(), surf.last_v());
  std::vector<cg::SurfaceProjection> ours(pts.size());
  std::vector<double> occt(pts.size());
  const double t_ours = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pts.size(); ++i) ours[i] = proj.project(pts[i]);
  });
  const double t_occt = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      api.Perform(cg::occt::to_pnt(pts[i]));
      occt[i] = api.NbPoints() > 0 ? api.LowerDistance() : 1e300;  // none: the foot is on the boundary
    }
  });
  int ours_smaller = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& r = ours[i];
    if (r.distance > occt[i] + 1e-9) g_check.fail("surface point %zu: ours %.17g, OCCT %.17g", i, r.distance, occt[i]);
    if (r.distance < occt[i] - 1e-9) {
      ++ours_smaller;
      if ((surf.point(r.u, r.v) - r.point).norm() > 1e-12 * (1 + r.point.norm()) ||
          std::abs((r.point - pts[i]).norm() - r.distance) > 1e-12 * (1 + r.distance))
        g_check.fail("surface point %zu: our closer point %.17g is not on the surface at that distance", i, r.distance);
    }
  }
  std::printf("surface: %d points, ours strictly closer than OCCT (OCCT local minimum or boundary foot, verified "
              "on the surface): %d\n", npoints, ours_smaller);
  std::printf("surface projection (rational bicubic, 12 x 12 poles): ours %.0f /s, OCCT Init+Perform %.0f /s, "
              "ratio %.1fx\n",
              npoints / t_ours, npoints / t_occt, t_occt / t_ours);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  bench_curve(quick ? 500 : 20000, quick ? 1 : 3);
  bench_surface(quick ? 100 : 2000, quick ? 1 : 3);
  return g_check.finish("bench_projection");
}
