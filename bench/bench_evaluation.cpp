// Evaluation speed: our batched span-cached evaluators against OCCT on the same geometry and the same
// parameters, in one run. Curve: cubic, 50 poles, 1e6 parameters, polynomial and rational, D0 and D2;
// ours = CurveEvaluator<3>::points / points_d2, OCCT = GeomAdaptor_Curve (span cache) and plain
// Geom_BSplineCurve. Surface: bicubic 30 x 30 poles on a 1000 x 1000 grid; ours =
// SurfaceEvaluator<3>::points, OCCT = GeomAdaptor_Surface::D0 and Geom_BSplineSurface::D0.
// Each case runs with sorted parameters and again with the same parameters in random order.
//
// Timing: best of several repetitions (the minimum is the least disturbed by the other jobs on this
// shared machine); every result feeds a checksum so nothing is optimised away. Checking: each timed
// routine runs once more with its outputs captured (the same code path: the batched evaluators for
// ours), and every point and derivative of ours is compared with Geom_BSplineCurve / _Surface's on
// all parameters: within 1e-12 of the largest |D^k| of the case (a few ulps of the terms summed; the
// measured worst is printed). Any disagreement makes the program exit with status 1.
//
// Usage: bench_evaluation [--quick]   (--quick: 1e4 curve parameters, 100 x 100 grid, 2 repetitions)
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
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
#include "src/core/curve_evaluator.hpp"
#include "src/core/knots.hpp"
#include "src/core/surface_evaluator.hpp"

namespace {

using Vec3 = Eigen::Vector3d;

struct Config {
  std::size_t curve_points = 1000000;
  int grid = 1000;
  int reps = 5;
};

// Results are written here so the compiler must compute them.
volatile double g_sink = 0.0;

// Best wall time in ns per point of `run` (which returns a checksum) over `reps` runs.
template <class Run>
double best_ns_per_point(int reps, std::size_t points, Run run) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const double sum = run();
    const auto t1 = std::chrono::steady_clock::now();
    g_sink = g_sink + sum;
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count());
  }
  return best / static_cast<double>(points);
}

// Every case writes its results into the same kind of small buffer (the typical use: tessellation,
// sampling), which keeps them in L1, and then runs the same checksum over the buffer. The checksum
// uses independent accumulators so its dependency chain does not dominate a 3 ns evaluation.
constexpr std::size_t kChunk = 1024;

double checksum(const Vec3* P, std::size_t n) {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  std::size_t k = 0;
  for (; k + 1 < n; k += 2) {
    a += P[k];
    b += P[k + 1];
  }
  if (k < n) a += P[k];
  return (a + b).sum();
}


// When set, chunked() also appends every output to these (the checking run; null while timing).
struct Capture {
  std::vector<Vec3> P, D1, D2;
};
Capture* g_capture = nullptr;

// Runs `eval(first, count, P, D1, D2)` chunk by chunk over n points and checksums the outputs.
template <int Order, class Eval>
double chunked(std::size_t n, Eval eval) {
  static Vec3 P[kChunk], D1[kChunk], D2[kChunk];
  double sum = 0;
  for (std::size_t i = 0; i < n; i += kChunk) {
    const std::size_t m = std::min(kChunk, n - i);
    eval(i, m, P, D1, D2);
    sum += checksum(P, m);
    if (Order >= 1) sum += checksum(D1, m);
    if (Order >= 2) sum += checksum(D2, m);
    if (g_capture) {
      g_capture->P.insert(g_capture->P.end(), P, P + m);
      if (Order >= 1) g_capture->D1.insert(g_capture->D1.end(), D1, D1 + m);
      if (Order >= 2) g_capture->D2.insert(g_capture->D2.end(), D2, D2 + m);
    }
  }
  return sum;
}

bench::Checker g_check;

// Runs ours and the reference once each with capture and compares every output (see the header).
template <class Ours, class Ref>
void check(const char* what, Ours ours, Ref ref) {
  Capture a, b;
  g_capture = &a;
  ours();
  g_capture = &b;
  ref();
  g_capture = nullptr;
  const std::vector<Vec3>* xa[3] = {&a.P, &a.D1, &a.D2};
  const std::vector<Vec3>* xb[3] = {&b.P, &b.D1, &b.D2};
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    if (xa[k]->size() != xb[k]->size()) {
      g_check.fail("%s: %zu outputs of order %d, OCCT %zu", what, xa[k]->size(), k, xb[k]->size());
      continue;
    }
    double scale = 1;
    for (const auto& v : *xb[k]) scale = std::max(scale, v.norm());
    for (std::size_t i = 0; i < xa[k]->size(); ++i) {
      const double e = ((*xa[k])[i] - (*xb[k])[i]).norm() / scale;
      worst = std::max(worst, e);
      if (!(e <= 1e-12)) g_check.fail("%s: point %zu, order %d differs by %.3e of the scale %.3e", what, i, k, e, scale);
    }
  }
  std::printf("  %-28s all %zu points checked against OCCT: worst %.1e of the scale\n", what, a.P.size(), worst);
}

double ours_d0(cg::CurveEvaluator<3>& ev, const std::vector<double>& u) {
  return chunked<0>(u.size(), [&](std::size_t i, std::size_t m, Vec3* P, Vec3*, Vec3*) {
    ev.points(u.data() + i, m, P);
  });
}

double ours_d2(cg::CurveEvaluator<3>& ev, const std::vector<double>& u) {
  return chunked<2>(u.size(), [&](std::size_t i, std::size_t m, Vec3* P, Vec3* D1, Vec3* D2) {
    ev.points_d2(u.data() + i, m, P, D1, D2);
  });
}

template <class Curve>
double occt_d0(const Curve& c, const std::vector<double>& u) {
  return chunked<0>(u.size(), [&](std::size_t i, std::size_t m, Vec3* P, Vec3*, Vec3*) {
    gp_Pnt Q;
    for (std::size_t k = 0; k < m; ++k) {
      c.D0(u[i + k], Q);
      P[k] = cg::occt::to_eigen(Q.XYZ());
    }
  });
}

template <class Curve>
double occt_d2(const Curve& c, const std::vector<double>& u) {
  return chunked<2>(u.size(), [&](std::size_t i, std::size_t m, Vec3* P, Vec3* D1, Vec3* D2) {
    gp_Pnt Q;
    gp_Vec V1, V2;
    for (std::size_t k = 0; k < m; ++k) {
      c.D2(u[i + k], Q, V1, V2);
      P[k] = cg::occt::to_eigen(Q.XYZ());
      D1[k] = cg::occt::to_eigen(V1.XYZ());
      D2[k] = cg::occt::to_eigen(V2.XYZ());
    }
  });
}

double ours_surface(cg::SurfaceEvaluator<3>& ev, const std::vector<double>& uv) {
  return chunked<0>(uv.size() / 2, [&](std::size_t i, std::size_t m, Vec3* P, Vec3*, Vec3*) {
    ev.points(uv.data() + 2 * i, m, P);
  });
}

template <class Surface>
double occt_surface(const Surface& s, const std::vector<double>& uv) {
  return chunked<0>(uv.size() / 2, [&](std::size_t i, std::size_t m, Vec3* P, Vec3*, Vec3*) {
    gp_Pnt Q;
    for (std::size_t k = 0; k < m; ++k) {
      s.D0(uv[2 * (i + k)], uv[2 * (i + k) + 1], Q);
      P[k] = cg::occt::to_eigen(Q.XYZ());
    }
  });
}

cg::BSplineCurve<3> bench_curve(std::mt19937_64& gen, bool rational) {
  const int p = 3, n = 50;
  std::uniform_real_distribution<double> coord(-10, 10), weight(0.5, 2.0);
  std::vector<Vec3> P(n);
  std::vector<double> w;
  for (auto& q : P) q = Vec3(coord(gen), coord(gen), coord(gen));
  if (rational)
    for (int i = 0; i < n; ++i) w.push_back(weight(gen));
  return cg::BSplineCurve<3>(p, cg::uniform_clamped_knots(p, n, 0.0, 1.0), P, w);
}

cg::BSplineSurface<3> bench_surface(std::mt19937_64& gen) {
  const int p = 3, n = 30;
  std::uniform_real_distribution<double> coord(-10, 10);
  std::vector<std::vector<Vec3>> P(n, std::vector<Vec3>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) P[i][j] = Vec3(i + 0.3 * coord(gen), j + 0.3 * coord(gen), coord(gen));
  const auto K = cg::uniform_clamped_knots(p, n, 0.0, 1.0);
  return cg::BSplineSurface<3>(p, p, K, K, P);
}

void print_header(const char* what) {
  std::printf("\n%-34s %9s %12s %12s %10s %10s\n", what, "ours", "GeomAdaptor", "Geom_BSpl", "adapt/ours",
              "geom/ours");
  std::printf("%-34s %9s %12s %12s %10s %10s\n", "", "ns/pt", "ns/pt", "ns/pt", "ratio", "ratio");
}

void print_row(const char* name, double ours, double adaptor, double geom) {
  std::printf("%-34s %9.2f %12.2f %12.2f %9.2fx %9.2fx\n", name, ours, adaptor, geom, adaptor / ours, geom / ours);
}

void bench_curves(const Config& cfg, std::mt19937_64& gen) {
  std::vector<double> sorted(cfg.curve_points);
  for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = static_cast<double>(i) / (sorted.size() - 1);
  std::vector<double> shuffled = sorted;
  std::shuffle(shuffled.begin(), shuffled.end(), gen);

  for (const bool rational : {false, true}) {
    const cg::BSplineCurve<3> c = bench_curve(gen, rational);
    const Handle(Geom_BSplineCurve) oc = cg::occt::to_occt(c);
    const GeomAdaptor_Curve adaptor(oc);
    cg::CurveEvaluator<3> ev(c);
    char title[128];
    std::snprintf(title, sizeof title, "curve p=3, 50 poles, %s", rational ? "rational" : "polynomial");
    print_header(title);
    for (const bool random : {false, true}) {
      const std::vector<double>& u = random ? shuffled : sorted;
      const std::size_t n = u.size();
      char name[64];
      std::snprintf(name, sizeof name, "D0 %s", random ? "random" : "sorted");
      check(name, [&] { ours_d0(ev, u); }, [&] { occt_d0(*oc, u); });
      std::snprintf(name, sizeof name, "D2 %s", random ? "random" : "sorted");
      check(name, [&] { ours_d2(ev, u); }, [&] { occt_d2(*oc, u); });
      std::snprintf(name, sizeof name, "D0 %s", random ? "random order" : "sorted");
      print_row(name, best_ns_per_point(cfg.reps, n, [&] { return ours_d0(ev, u); }),
                best_ns_per_point(cfg.reps, n, [&] { return occt_d0(adaptor, u); }),
                best_ns_per_point(cfg.reps, n, [&] { return occt_d0(*oc, u); }));
      std::snprintf(name, sizeof name, "D2 %s", random ? "random order" : "sorted");
      print_row(name, best_ns_per_point(cfg.reps, n, [&] { return ours_d2(ev, u); }),
                best_ns_per_point(cfg.reps, n, [&] { return occt_d2(adaptor, u); }),
                best_ns_per_point(cfg.reps, n, [&] { return occt_d2(*oc, u); }));
    }
  }
}

void bench_surfaces(const Config& cfg, std::mt19937_64& gen) {
  const cg::BSplineSurface<3> s = bench_surface(gen);
  const Handle(Geom_BSplineSurface) os = cg::occt::to_occt(s);
  const GeomAdaptor_Surface adaptor(os);
  cg::SurfaceEvaluator<3> ev(s);
  const int g = cfg.grid;
  // Sorted: row by row (u outer, v inner), as a tessellator walks a grid.
  std::vector<double> sorted(2 * static_cast<std::size_t>(g) * g);
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      const std::size_t k = 2 * (static_cast<std::size_t>(i) * g + j);
      sorted[k] = static_cast<double>(i) / (g - 1);
      sorted[k + 1] = static_cast<double>(j) / (g - 1);
    }
  std::vector<std::size_t> order(static_cast<std::size_t>(g) * g);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), gen);
  std::vector<double> shuffled(sorted.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    shuffled[2 * i] = sorted[2 * order[i]];
    shuffled[2 * i + 1] = sorted[2 * order[i] + 1];
  }
  char title[128];
  std::snprintf(title, sizeof title, "surface bicubic 30x30, %dx%d grid", g, g);
  print_header(title);
  for (const bool random : {false, true}) {
    const std::vector<double>& uv = random ? shuffled : sorted;
    const std::size_t n = uv.size() / 2;
    check(random ? "D0 random" : "D0 sorted", [&] { ours_surface(ev, uv); }, [&] { occt_surface(*os, uv); });
    print_row(random ? "D0 random order" : "D0 sorted (row by row)",
              best_ns_per_point(cfg.reps, n, [&] { return ours_surface(ev, uv); }),
              best_ns_per_point(cfg.reps, n, [&] { return occt_surface(adaptor, uv); }),
              best_ns_per_point(cfg.reps, n, [&] { return occt_surface(*os, uv); }));
  }
}

}  // namespace

int main(int argc, char** argv) {
  Config cfg;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      cfg.curve_points = 10000;
      cfg.grid = 100;
      cfg.reps = 2;
    } else {
      std::fprintf(stderr, "usage: %s [--quick]\n", argv[0]);
      return 2;
    }
  }
  std::mt19937_64 gen(20240607);
  std::printf("bench_evaluation: %zu curve parameters, %dx%d surface grid, best of %d runs, single thread\n",
              cfg.curve_points, cfg.grid, cfg.grid, cfg.reps);
  bench_curves(cfg, gen);
  bench_surfaces(cfg, gen);
  std::printf("\nchecksum %.6e\n", static_cast<double>(g_sink));
  return g_check.finish("bench_evaluation");
}
