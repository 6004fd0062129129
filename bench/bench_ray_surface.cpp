// Ray-surface first hit speed: RaySurfaceCaster::first_hit against OCCT's GeomAPI_IntCS (a Geom_Line
// against the converted surface, the crossing nearest the origin ahead of it) on the same rays, in one
// run. Surfaces: a wavy rational bicubic (12 x 12 poles, weights 0.5..2) and a blade-like loop (periodic
// cubic in u, a thin cambered airfoil of 20 poles lofted through 6 twisted sections). Rays: from random
// points of the surface's box grown by half, aimed at a random surface point (half of them) or in a random
// direction.
// Checking, on the results of the timed runs: every hit of ours lies on the line and on the surface as
// OCCT evaluates it at our (u, v) (1e-9 mm); where OCCT's first crossing ahead is transversal
// (|cos(line, normal)| >= 0.01) ours must not lie beyond it (1e-7 mm); a hit of ours before OCCT's first
// is counted (a crossing OCCT missed, or a touching line). Any disagreement: exit status 1.
// Timing: best of several repetitions (least disturbed on this shared machine).
//
// Usage: bench_ray_surface [--quick]   (--quick: 300 rays per surface, 2 repetitions; else 3000, best of 3)
#include <GeomAPI_IntCS.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Line.hxx>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "bench_check.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/core/constants.hpp"
#include "src/core/knots.hpp"

namespace {

using cg::BSplineSurface;
using V3 = Eigen::Vector3d;

BSplineSurface<3> wavy() {
  std::vector<std::vector<V3>> P(12, std::vector<V3>(12));
  std::vector<std::vector<double>> W(12, std::vector<double>(12));
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      P[i][j] = V3(i * 3.0, j * 3.0, 4 * std::sin(0.9 * i) * std::cos(0.7 * j));
      W[i][j] = 1.25 + 0.75 * std::sin(1.3 * i + 0.4 * j);
    }
  return BSplineSurface<3>(3, 3, cg::uniform_clamped_knots(3, 12), cg::uniform_clamped_knots(3, 12), P, W);
}

BSplineSurface<3> blade() {
  const int du = 20, p = 3, sections = 6;
  std::vector<double> period;
  for (int i = 0; i < du; ++i) period.push_back(i);
  std::vector<double> U = cg::unwrap_periodic_knots(p, period, du);
  std::vector<std::vector<V3>> P(du + p, std::vector<V3>(sections));
  for (int j = 0; j < sections; ++j) {
    const double twist = 0.15 * j, z = 10.0 * j;
    for (int i = 0; i < du; ++i) {
      const double th = 2 * cg::kPi * i / du, x = 20 * std::cos(th);
      const double y = 1.5 * std::sin(th) * (1 + 0.4 * std::cos(th)) + 3 * (1 - x * x / 400);
      P[i][j] = V3(std::cos(twist) * x - std::sin(twist) * y, std::sin(twist) * x + std::cos(twist) * y, z);
    }
    for (int i = du; i < du + p; ++i) P[i][j] = P[i - du][j];
  }
  return BSplineSurface<3>::from_poles(p, 3, U, cg::uniform_clamped_knots(3, sections), P, {}, true, false);
}

struct Ray {
  V3 o, d;
};

std::vector<Ray> rays(const BSplineSurface<3>& s, int n, unsigned seed) {
  std::mt19937_64 g(seed);
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  V3 lo = V3::Constant(1e300), hi = V3::Constant(-1e300);
  for (int i = 0; i < s.num_poles_u(); ++i)
    for (int j = 0; j < s.num_poles_v(); ++j) lo = lo.cwiseMin(s.pole(i, j)), hi = hi.cwiseMax(s.pole(i, j));
  const V3 mid = 0.5 * (lo + hi), half = 0.75 * (hi - lo);
  std::vector<Ray> out;
  for (int k = 0; k < n; ++k) {
    const V3 o = mid + V3(uni(-1, 1) * half.x(), uni(-1, 1) * half.y(), uni(-1, 1) * half.z());
    V3 d = k % 2 == 0 ? V3(s.point(uni(s.first_u(), s.last_u()), uni(s.first_v(), s.last_v())) - o)
                      : V3(uni(-1, 1), uni(-1, 1), uni(-1, 1));
    if (!(d.norm() > 1e-9)) d = V3(0, 0, 1);
    out.push_back({o, d.normalized()});
  }
  return out;
}

struct OcctFirst {
  bool found = false;
  double s = 0, u = 0, v = 0;
};

void run(const char* name, const BSplineSurface<3>& s, int n, int reps, bench::Checker& check) {
  const std::vector<Ray> rs = rays(s, n, 7);
  const Handle(Geom_BSplineSurface) os = cg::occt::to_occt(s);
  cg::RaySurfaceCaster caster(s);
  std::vector<cg::RaySurfaceHit> ours(rs.size());
  std::vector<OcctFirst> occt(rs.size());
  const double t_ours = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < rs.size(); ++i) ours[i] = caster.first_hit(rs[i].o, rs[i].d);
  });
  const double t_occt = bench::best_seconds(reps, [&](int) {
    for (std::size_t i = 0; i < rs.size(); ++i) {
      Handle(Geom_Line) line = new Geom_Line(gp_Pnt(rs[i].o.x(), rs[i].o.y(), rs[i].o.z()), gp_Dir(rs[i].d.x(), rs[i].d.y(), rs[i].d.z()));
      GeomAPI_IntCS inter(line, os);
      OcctFirst f;
      for (int j = 1; inter.IsDone() && j <= inter.NbPoints(); ++j) {
        double u, v, w;
        inter.Parameters(j, u, v, w);
        if (w >= 0 && (!f.found || w < f.s)) f = {true, w, u, v};
      }
      occt[i] = f;
    }
  });
  int hits = 0, occt_hits = 0, earlier = 0;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const auto& h = ours[i];
    const auto& f = occt[i];
    occt_hits += f.found;
    if (h.found) {
      ++hits;
      const gp_Pnt q = os->Value(h.u, h.v);
      const double gap = (V3(q.X(), q.Y(), q.Z()) - (rs[i].o + h.ray_param * rs[i].d)).norm();
      if (!(gap <= 1e-9)) check.fail("%s ray %zu: our hit is %.2e mm off the surface", name, i, gap);
    }
    if (!f.found) {
      earlier += h.found;
      continue;
    }
    gp_Pnt P;
    gp_Vec Du, Dv;
    os->D1(f.u, f.v, P, Du, Dv);
    const gp_Vec nv = Du.Crossed(Dv);
    const double c = nv.Magnitude() > 0 ? std::abs(nv.Dot(gp_Vec(rs[i].d.x(), rs[i].d.y(), rs[i].d.z()))) / nv.Magnitude() : 0;
    if (c >= 0.01 && (!h.found || h.ray_param > f.s + 1e-7))
      check.fail("%s ray %zu: OCCT's first crossing at %.12g (|cos| %.3f), ours %s %.12g", name, i, f.s, c,
                 h.found ? "at" : "none", h.found ? h.ray_param : 0.0);
    if (h.found && h.ray_param < f.s - 1e-7) ++earlier;
  }
  const double nr = static_cast<double>(rs.size());
  std::printf("%-6s %5zu rays: %d hits (ours), %d (OCCT); %d of ours before OCCT's first\n", name, rs.size(), hits,
              occt_hits, earlier);
  std::printf("       ours %.0f rays/s   OCCT GeomAPI_IntCS %.0f rays/s   ratio %.1fx\n", nr / t_ours, nr / t_occt,
              t_occt / t_ours);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int n = quick ? 300 : 3000, reps = quick ? 2 : 3;
  bench::Checker check;
  run("wavy", wavy(), n, reps, check);
  run("blade", blade(), n, reps, check);
  return check.finish("bench_ray_surface");
}
