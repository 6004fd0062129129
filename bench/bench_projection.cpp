// Point projection speed: our CurveProjector / SurfaceProjector against OCCT on the same geometry and
// the same points, in one run.
//  Curve: rational cubic, 32 poles (3D), points scattered around the curve (within 5% of its size);
//         OCCT = GeomAPI_ProjectPointOnCurve, both per point (constructor) and initialised once
//         (Init(curve, first, last) + Perform(P)); the faster is the reference.
//  Surface: rational bicubic, 12 x 12 poles, points scattered around it; OCCT =
//         GeomAPI_ProjectPointOnSurf initialised once on the bounds (Init + Perform).
// Before timing, the distances are compared (ours must never be larger than OCCT's + 1e-9; the count
// of points where ours is strictly smaller, i.e. OCCT returned a local minimum, is printed).
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
#include "src/algo/project_point_curve.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/knots.hpp"

namespace {

using Vec3 = Eigen::Vector3d;
volatile double g_sink = 0.0;

template <class Run>
double best_seconds(int reps, Run run) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    g_sink = g_sink + run();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  return best;
}

gp_Pnt to_gp(const Vec3& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

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

  // Agreement first.
  int ours_smaller = 0, ours_larger = 0;
  GeomAPI_ProjectPointOnCurve api;
  api.Init(oc, curve.first_param(), curve.last_param());
  for (const auto& P : pts) {
    const double d = proj.project(P).distance;
    api.Perform(to_gp(P));
    double o = std::min((curve.point(0) - P).norm(), (curve.point(1) - P).norm());
    if (api.NbPoints() > 0) o = std::min(o, api.LowerDistance());
    if (d > o + 1e-9) ++ours_larger;
    if (d < o - 1e-9) ++ours_smaller;
  }
  std::printf("curve: %d points, ours larger than OCCT: %d, ours strictly smaller (OCCT local min): %d\n",
              npoints, ours_larger, ours_smaller);

  const double t_ours = best_seconds(reps, [&] {
    double s = 0;
    for (const auto& P : pts) s += proj.project(P).distance;
    return s;
  });
  const double t_occt_init = best_seconds(reps, [&] {
    double s = 0;
    for (const auto& P : pts) {
      api.Perform(to_gp(P));
      if (api.NbPoints() > 0) s += api.LowerDistance();
    }
    return s;
  });
  const double t_occt_ctor = best_seconds(std::max(1, reps / 2), [&] {
    double s = 0;
    for (const auto& P : pts) {
      GeomAPI_ProjectPointOnCurve a(to_gp(P), oc);
      if (a.NbPoints() > 0) s += a.LowerDistance();
    }
    return s;
  });
  const double occt = std::min(t_occt_init, t_occt_ctor);
  std::printf("curve projection (rational cubic, 32 poles): ours %.0f /s, OCCT Init+Perform %.0f /s, "
              "OCCT per-point ctor %.0f /s, ratio %.1fx\n",
              npoints / t_ours, npoints / t_occt_init, npoints / t_occt_ctor, occt / t_ours);
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
  int ours_smaller = 0, ours_larger = 0;
  for (const auto& P : pts) {
    const double d = proj.project(P).distance;
    api.Perform(to_gp(P));
    if (api.NbPoints() == 0) continue;
    const double o = api.LowerDistance();
    if (d > o + 1e-9) ++ours_larger;
    if (d < o - 1e-9) ++ours_smaller;
  }
  std::printf("surface: %d points, ours larger than OCCT: %d, ours strictly smaller (OCCT local min or "
              "boundary): %d\n",
              npoints, ours_larger, ours_smaller);
  const double t_ours = best_seconds(reps, [&] {
    double s = 0;
    for (const auto& P : pts) s += proj.project(P).distance;
    return s;
  });
  const double t_occt = best_seconds(reps, [&] {
    double s = 0;
    for (const auto& P : pts) {
      api.Perform(to_gp(P));
      if (api.NbPoints() > 0) s += api.LowerDistance();
    }
    return s;
  });
  std::printf("surface projection (rational bicubic, 12 x 12 poles): ours %.0f /s, OCCT Init+Perform %.0f /s, "
              "ratio %.1fx\n",
              npoints / t_ours, npoints / t_occt, t_occt / t_ours);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  bench_curve(quick ? 500 : 20000, quick ? 1 : 3);
  bench_surface(quick ? 100 : 2000, quick ? 1 : 3);
  return 0;
}
