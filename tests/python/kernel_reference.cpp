// The C++ side of tests/python/test_kernel.py and bench/bench_python_kernel.py: the same kernel calls
// the Python bindings make, on the geometry and parameters the Python side wrote, so their results can
// be compared with == and their per-point cost timed on the same machine in the same run.
//
//   kernel_reference values INPUT OUTPUT   reads INPUT (text, see read_input), writes every result as raw
//                                          doubles to OUTPUT in the order of main's comments
//   kernel_reference time INPUT REPS       best-of-REPS time of CurveEvaluator<3>::points over INPUT's
//                                          parameters (one batch per call), printed as "ns_per_point X"
//   kernel_reference time_surface INPUT REPS   the same for SurfaceEvaluator<3>::points
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/algo/intersect_curves.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/surface_evaluator.hpp"

using namespace cg;

namespace {

struct Reader {
  std::ifstream in;
  double number() {
    std::string s;
    if (!(in >> s)) throw std::runtime_error("input ends early");
    return std::stod(s);  // the shortest round-trip text Python's repr wrote: the same double
  }
  int count() { return static_cast<int>(number()); }
  std::vector<double> list() {
    std::vector<double> v(static_cast<std::size_t>(count()));
    for (double& x : v) x = number();
    return v;
  }
  template <int Dim>
  BSplineCurve<Dim> curve() {
    const int degree = count();
    const std::vector<double> knots = list(), flat = list(), weights = list();
    std::vector<Eigen::Matrix<double, Dim, 1>> poles(flat.size() / Dim);
    for (std::size_t i = 0; i < poles.size(); ++i)
      for (int d = 0; d < Dim; ++d) poles[i][d] = flat[i * Dim + static_cast<std::size_t>(d)];
    return BSplineCurve<Dim>(degree, knots, poles, weights);
  }
  BSplineSurface<3> surface() {
    const int pu = count(), pv = count();
    const std::vector<double> ku = list(), kv = list();
    const int nu = count(), nv = count();
    const std::vector<double> flat = list(), w = list();
    std::vector<std::vector<Eigen::Vector3d>> poles(static_cast<std::size_t>(nu));
    std::vector<std::vector<double>> weights;
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        const std::size_t k = static_cast<std::size_t>(i * nv + j);
        poles[static_cast<std::size_t>(i)].emplace_back(flat[3 * k], flat[3 * k + 1], flat[3 * k + 2]);
      }
      if (!w.empty()) weights.emplace_back(w.begin() + i * nv, w.begin() + (i + 1) * nv);
    }
    return BSplineSurface<3>(pu, pv, ku, kv, poles, weights);
  }
};

struct Writer {
  std::vector<double> out;
  template <class P>
  void points(const std::vector<P>& p) {
    for (const P& x : p)
      for (int d = 0; d < x.size(); ++d) out.push_back(x[d]);
  }
  /// CurveProjector on each point of `flat` (Dim values each): all parameters, all feet, all distances.
  template <int Dim>
  void projections(const BSplineCurve<Dim>& c, const std::vector<double>& flat) {
    CurveProjector<Dim> proj(c);
    std::vector<double> pu, pd;
    std::vector<Eigen::Matrix<double, Dim, 1>> pf;
    for (std::size_t i = 0; i < flat.size(); i += Dim) {
      const CurveProjection<Dim> q = proj.project(Eigen::Map<const Eigen::Matrix<double, Dim, 1>>(flat.data() + i));
      pu.push_back(q.param);
      pf.push_back(q.point);
      pd.push_back(q.distance);
    }
    out.insert(out.end(), pu.begin(), pu.end());
    points(pf);
    out.insert(out.end(), pd.begin(), pd.end());
  }
};

// Input: curve3, u, points3 (for the 3D curve); curve2 a, curve2 b, points2; surface, us, vs, points3s.
int values(const char* input, const char* output) {
  Reader r{std::ifstream(input)};
  const BSplineCurve<3> c3 = r.curve<3>();
  const std::vector<double> u = r.list(), p3 = r.list();
  const BSplineCurve<2> a = r.curve<2>(), b = r.curve<2>();
  const std::vector<double> p2 = r.list();
  const BSplineSurface<3> s = r.surface();
  const std::vector<double> us = r.list(), vs = r.list(), ps = r.list();
  Writer w;
  const std::size_t n = u.size();
  {  // 1. c3.evaluate(u); 2. c3.derivatives(u, 2); 3. c3.derivatives(u, 4)
    CurveEvaluator<3> ev(c3);
    std::vector<Eigen::Vector3d> P(n), D1(n), D2(n);
    ev.points(u.data(), n, P.data());
    w.points(P);
    ev.points_d2(u.data(), n, P.data(), D1.data(), D2.data());
    for (std::size_t i = 0; i < n; ++i) w.points(std::vector<Eigen::Vector3d>{P[i], D1[i], D2[i]});
    for (double x : u) w.points(c3.derivatives(x, 4));
  }
  {  // 4. c3.project(points3): u, foot, distance
    w.projections(c3, p3);
  }
  {  // 5. a.evaluate(u scaled into a's domain by the caller: the same u); 6. a.project(points2)
    CurveEvaluator<2> ev(a);
    std::vector<Eigen::Vector2d> P(n);
    ev.points(u.data(), n, P.data());
    w.points(P);
    w.projections(a, p2);
  }
  {  // 7. a.intersect(b): count, then s, t, x, y, tangent per point; overlap count, s0 s1 t0 t1 each
    const CurveCurveIntersections x = intersect_curves(a, b);
    w.out.push_back(static_cast<double>(x.points.size()));
    for (const CurveCurvePoint& p : x.points)
      w.out.insert(w.out.end(), {p.s, p.t, p.point.x(), p.point.y(), p.kind == ContactKind::tangent ? 1.0 : 0.0});
    w.out.push_back(static_cast<double>(x.overlaps.size()));
    for (const CurveCurveOverlap& o : x.overlaps) w.out.insert(w.out.end(), {o.s0, o.s1, o.t0, o.t1});
  }
  {  // 8. s.evaluate(us, vs); 9. s.derivatives(us, vs, 2); 10. s.project(points3s): u, v, foot, distance
    SurfaceEvaluator<3> ev(s);
    std::vector<double> uv;
    for (std::size_t i = 0; i < us.size(); ++i) uv.insert(uv.end(), {us[i], vs[i]});
    std::vector<Eigen::Vector3d> P(us.size());
    ev.points(uv.data(), us.size(), P.data());
    w.points(P);
    Eigen::Vector3d D[9];
    for (std::size_t i = 0; i < us.size(); ++i) {
      s.derivatives(us[i], vs[i], 2, D);
      w.points(std::vector<Eigen::Vector3d>(D, D + 9));
    }
    SurfaceProjector proj(s);
    std::vector<double> qu, qv, qd;
    std::vector<Eigen::Vector3d> qf;
    for (std::size_t i = 0; i < ps.size(); i += 3) {
      const SurfaceProjection q = proj.project(Eigen::Vector3d(ps[i], ps[i + 1], ps[i + 2]));
      qu.push_back(q.u);
      qv.push_back(q.v);
      qf.push_back(q.point);
      qd.push_back(q.distance);
    }
    for (const auto* v : {&qu, &qv}) w.out.insert(w.out.end(), v->begin(), v->end());
    w.points(qf);
    w.out.insert(w.out.end(), qd.begin(), qd.end());
  }
  std::FILE* f = std::fopen(output, "wb");
  if (!f || std::fwrite(w.out.data(), sizeof(double), w.out.size(), f) != w.out.size()) return 1;
  return std::fclose(f) == 0 ? 0 : 1;
}

// Prints the best-of-`reps` wall time of eval(P) per point of P ("ns_per_point X") and a checksum.
template <class Eval>
int print_best_time(int reps, std::vector<Eigen::Vector3d>& P, Eval eval) {
  double best = 1e300, sum = 0;
  for (int k = 0; k < reps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    eval(P.data());
    const auto t1 = std::chrono::steady_clock::now();
    sum += P[P.size() / 2].sum();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count());
  }
  std::printf("ns_per_point %.6g\nchecksum %.17g\n", best / static_cast<double>(P.size()), sum);
  return 0;
}

// Input: curve3, u. The loop the Python evaluate() wraps: one batch of all parameters per call into a
// preallocated buffer.
int time_points(const char* input, int reps) {
  Reader r{std::ifstream(input)};
  const BSplineCurve<3> c3 = r.curve<3>();
  const std::vector<double> u = r.list();
  CurveEvaluator<3> ev(c3);
  std::vector<Eigen::Vector3d> P(u.size());
  return print_best_time(reps, P, [&](Eigen::Vector3d* out) { ev.points(u.data(), u.size(), out); });
}

// Input: surface, us, vs. The loop the Python evaluate(u, v) wraps: SurfaceEvaluator::points over the
// (u, v) pairs (interleaved once, outside the timing) into a preallocated buffer.
int time_surface_points(const char* input, int reps) {
  Reader r{std::ifstream(input)};
  const BSplineSurface<3> s = r.surface();
  const std::vector<double> us = r.list(), vs = r.list();
  std::vector<double> uv;
  for (std::size_t i = 0; i < us.size(); ++i) uv.insert(uv.end(), {us[i], vs[i]});
  SurfaceEvaluator<3> ev(s);
  std::vector<Eigen::Vector3d> P(us.size());
  return print_best_time(reps, P, [&](Eigen::Vector3d* out) { ev.points(uv.data(), us.size(), out); });
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "values" && argc == 4) return values(argv[2], argv[3]);
    if (mode == "time" && argc == 4) return time_points(argv[2], std::stoi(argv[3]));
    if (mode == "time_surface" && argc == 4) return time_surface_points(argv[2], std::stoi(argv[3]));
    std::fprintf(stderr, "usage: kernel_reference values INPUT OUTPUT | time INPUT REPS | time_surface INPUT REPS\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kernel_reference: %s\n", e.what());
    return 1;
  }
}
