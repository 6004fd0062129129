// The NURBS kernel on NumPy arrays: BSplineCurve (2D, 3D) and BSplineSurface (3D) from arrays, batched
// evaluation, derivatives and point inversion in C++ loops with the GIL released, and the
// intersection of 2D curves. Values are the library's to the last bit (tests/python/test_kernel.py):
//   BSplineCurve.evaluate(u), derivatives(u, n <= 2)  CurveEvaluator (span-cached, batched)
//   BSplineCurve.derivatives(u, n > 2)                BSplineCurve::derivatives (The NURBS Book A3.2/A4.2)
//   BSplineSurface.evaluate(u, v)                     SurfaceEvaluator::points (patch-cached, batched)
//   BSplineSurface.derivatives(u, v, n)               BSplineSurface::derivatives
//   project(points)                                   CurveProjector / SurfaceProjector (global minimum)
//   BSplineCurve.intersect(other, tol)                intersect_curves (2D)
// Each object keeps its evaluator and projector (whose caches make repeated batches cheap) behind a
// mutex: calls on one object from several Python threads run one after the other.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <vector>

#include "python/src/bind.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/core/surface_evaluator.hpp"

namespace py = pybind11;

namespace cg::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<py::ssize_t> shape_of(const py::array& a) { return {a.shape(), a.shape() + a.ndim()}; }

template <class... T>
std::vector<py::ssize_t> with(std::vector<py::ssize_t> s, T... extra) {
  (s.push_back(static_cast<py::ssize_t>(extra)), ...);
  return s;
}

std::vector<double> to_vector(const Array& a, const char* what) {
  if (a.ndim() != 1) throw InvalidGeometry(std::string(what) + ": must be a 1-D array, got " + std::to_string(a.ndim()) + " dimensions");
  return {a.data(), a.data() + a.size()};
}

// Writes n points through `eval(first, count, out)` into `out` (n * Dim doubles): directly when the
// buffer is aligned for Eigen's fixed-size vectors, else through a small aligned chunk.
template <int Dim, class Eval>
void write_points(double* out, std::size_t n, Eval eval) {
  using Point = Eigen::Matrix<double, Dim, 1>;
  if (reinterpret_cast<std::uintptr_t>(out) % alignof(Point) == 0) {
    eval(std::size_t{0}, n, reinterpret_cast<Point*>(out));
    return;
  }
  std::vector<Point, Eigen::aligned_allocator<Point>> chunk(1024);
  for (std::size_t i = 0; i < n; i += chunk.size()) {
    const std::size_t m = std::min(chunk.size(), n - i);
    eval(i, m, chunk.data());
    for (std::size_t k = 0; k < m; ++k)
      for (int d = 0; d < Dim; ++d) out[(i + k) * Dim + d] = chunk[k][d];
  }
}

template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> points_of(const Array& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != Dim)
    throw InvalidGeometry(std::string(what) + ": must be an array of shape (n, " + std::to_string(Dim) + ")");
  std::vector<Eigen::Matrix<double, Dim, 1>> p(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < Dim; ++d) p[i][d] = a.at(static_cast<py::ssize_t>(i), d);
  return p;
}

// Runs `work` with the GIL released and `mutex` (the object's caches) locked. Results are returned
// after it, with the GIL held again.
template <class Work>
void released(std::mutex& mutex, Work work) {
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex);
  work();
}

// ---- curves ------------------------------------------------------------------------------------

class AnyCurve {
 public:
  virtual ~AnyCurve() = default;
  virtual int dim() const = 0;
  virtual py::array evaluate(const Array& u) = 0;
  virtual py::array derivatives(const Array& u, int n) = 0;
  virtual py::tuple project(const Array& points) = 0;
  virtual int degree() const = 0;
  virtual py::array knots() const = 0;
  virtual py::array poles() const = 0;
  virtual py::object weights() const = 0;
  virtual std::pair<double, double> domain() const = 0;
};

template <int Dim>
class CurveOf : public AnyCurve {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  explicit CurveOf(BSplineCurve<Dim> c) : curve_(std::make_shared<const BSplineCurve<Dim>>(std::move(c))), ev_(curve_) {}
  const BSplineCurve<Dim>& curve() const { return *curve_; }

  int dim() const override { return Dim; }
  int degree() const override { return curve_->degree(); }
  py::array knots() const override { return py::array_t<double>(static_cast<py::ssize_t>(curve_->knots().size()), curve_->knots().data()); }
  py::array poles() const override {
    py::array_t<double> a({static_cast<py::ssize_t>(curve_->num_poles()), static_cast<py::ssize_t>(Dim)});
    for (int i = 0; i < curve_->num_poles(); ++i)
      for (int d = 0; d < Dim; ++d) a.mutable_at(i, d) = curve_->pole(i)[d];
    return a;
  }
  py::object weights() const override {
    if (!curve_->is_rational()) return py::none();
    const std::vector<double> w = curve_->weights();
    return py::array_t<double>(static_cast<py::ssize_t>(w.size()), w.data());
  }
  std::pair<double, double> domain() const override { return {curve_->first_param(), curve_->last_param()}; }

  py::array evaluate(const Array& u) override {
    py::array_t<double> out(with(shape_of(u), Dim));
    const double* in = u.data();
    double* o = out.mutable_data();
    const std::size_t n = static_cast<std::size_t>(u.size());
    released(mutex_, [&] {
      write_points<Dim>(o, n, [&](std::size_t first, std::size_t count, Point* P) { ev_.points(in + first, count, P); });
    });
    return out;
  }

  py::array derivatives(const Array& u, int n) override {
    check_derivative_order(n, "derivatives: n");
    py::array_t<double> out(with(shape_of(u), n + 1, Dim));
    const double* in = u.data();
    double* o = out.mutable_data();
    const std::size_t count = static_cast<std::size_t>(u.size());
    released(mutex_, [&] { fill_derivatives(in, count, n, o); });
    return out;
  }

  // derivatives(): n <= 2 on the evaluator, in chunks; higher orders by BSplineCurve::derivatives.
  void fill_derivatives(const double* in, std::size_t count, int n, double* o) {
    if (n <= 2) {
      std::vector<Point> D[3];
      for (int k = 0; k <= n; ++k) D[k].resize(std::min<std::size_t>(count, 1024));
      for (std::size_t i = 0; i < count; i += 1024) {
        const std::size_t m = std::min<std::size_t>(1024, count - i);
        if (n == 0) ev_.points(in + i, m, D[0].data());
        if (n == 1) ev_.points_d1(in + i, m, D[0].data(), D[1].data());
        if (n == 2) ev_.points_d2(in + i, m, D[0].data(), D[1].data(), D[2].data());
        for (std::size_t j = 0; j < m; ++j)
          for (int k = 0; k <= n; ++k)
            for (int d = 0; d < Dim; ++d) o[((i + j) * (n + 1) + k) * Dim + d] = D[k][j][d];
      }
    } else {
      std::vector<Point> D(static_cast<std::size_t>(n + 1));
      for (std::size_t i = 0; i < count; ++i) {
        curve_->derivatives(in[i], n, D.data());
        for (int k = 0; k <= n; ++k)
          for (int d = 0; d < Dim; ++d) o[(i * (n + 1) + k) * Dim + d] = D[k][d];
      }
    }
  }

  py::tuple project(const Array& points) override {
    const std::vector<Point> P = points_of<Dim>(points, "project: points");
    const py::ssize_t n = static_cast<py::ssize_t>(P.size());
    py::array_t<double> u(n), foot({n, static_cast<py::ssize_t>(Dim)}), dist(n);
    double *pu = u.mutable_data(), *pf = foot.mutable_data(), *pd = dist.mutable_data();
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      for (const Point& p : P)
        if (!p.allFinite()) throw InvalidGeometry("project: points must be finite");
      if (!projector_) projector_ = std::make_unique<CurveProjector<Dim>>(*curve_);
      for (std::size_t i = 0; i < P.size(); ++i) {
        const CurveProjection<Dim> r = projector_->project(P[i]);
        pu[i] = r.param;
        pd[i] = r.distance;
        for (int d = 0; d < Dim; ++d) pf[i * Dim + d] = r.point[d];
      }
    }
    return py::make_tuple(u, foot, dist);
  }

 private:
  std::shared_ptr<const BSplineCurve<Dim>> curve_;
  std::mutex mutex_;
  CurveEvaluator<Dim> ev_;
  std::unique_ptr<CurveProjector<Dim>> projector_;
};

std::shared_ptr<AnyCurve> make_curve(int degree, const Array& knots, const Array& poles, const py::object& weights) {
  std::vector<double> w;
  if (!weights.is_none()) w = to_vector(Array::ensure(weights), "weights");
  if (poles.ndim() != 2 || (poles.shape(1) != 2 && poles.shape(1) != 3))
    throw InvalidGeometry("poles: must be an array of shape (n, 2) or (n, 3)");
  const std::vector<double> k = to_vector(knots, "knots");
  if (poles.shape(1) == 2) return std::make_shared<CurveOf<2>>(BSplineCurve<2>(degree, k, points_of<2>(poles, "poles"), w));
  return std::make_shared<CurveOf<3>>(BSplineCurve<3>(degree, k, points_of<3>(poles, "poles"), w));
}

py::dict intersect(AnyCurve& a, AnyCurve& b, double tol) {
  auto* a2 = dynamic_cast<CurveOf<2>*>(&a);
  auto* b2 = dynamic_cast<CurveOf<2>*>(&b);
  if (!a2 || !b2) throw InvalidGeometry("intersect: both curves must be 2D");
  CurveCurveIntersections r;
  {
    py::gil_scoped_release release;
    r = intersect_curves(a2->curve(), b2->curve(), tol);  // reads the immutable curves only
  }
  const py::ssize_t n = static_cast<py::ssize_t>(r.points.size()), m = static_cast<py::ssize_t>(r.overlaps.size());
  py::array_t<double> s(n), t(n), pts({n, py::ssize_t{2}}), ov({m, py::ssize_t{4}});
  py::array_t<bool> tangent(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const CurveCurvePoint& p = r.points[static_cast<std::size_t>(i)];
    s.mutable_at(i) = p.s;
    t.mutable_at(i) = p.t;
    pts.mutable_at(i, 0) = p.point.x();
    pts.mutable_at(i, 1) = p.point.y();
    tangent.mutable_at(i) = p.kind == ContactKind::tangent;
  }
  for (py::ssize_t i = 0; i < m; ++i) {
    const CurveCurveOverlap& o = r.overlaps[static_cast<std::size_t>(i)];
    const double v[4] = {o.s0, o.s1, o.t0, o.t1};
    for (int k = 0; k < 4; ++k) ov.mutable_at(i, k) = v[k];
  }
  py::dict d;
  d["s"] = s;
  d["t"] = t;
  d["points"] = pts;
  d["tangent"] = tangent;
  d["overlaps"] = ov;
  return d;
}

// ---- surfaces ----------------------------------------------------------------------------------

class Surface {
 public:
  explicit Surface(BSplineSurface<3> s) : s_(std::make_shared<const BSplineSurface<3>>(std::move(s))), ev_(s_) {}
  const BSplineSurface<3>& surface() const { return *s_; }

  py::array evaluate(const Array& u, const Array& v) {
    if (shape_of(u) != shape_of(v)) throw InvalidGeometry("evaluate: u and v must have the same shape");
    py::array_t<double> out(with(shape_of(u), 3));
    const double *pu = u.data(), *pv = v.data();
    double* o = out.mutable_data();
    const std::size_t n = static_cast<std::size_t>(u.size());
    released(mutex_, [&] {
    std::vector<double> uv(2 * std::min<std::size_t>(n, 1024));
    write_points<3>(o, n, [&](std::size_t first, std::size_t count, Eigen::Vector3d* P) {
      for (std::size_t i = 0; i < count;) {  // (u, v) pairs in chunks of 1024
        const std::size_t m = std::min<std::size_t>(1024, count - i);
        for (std::size_t k = 0; k < m; ++k) {
          uv[2 * k] = pu[first + i + k];
          uv[2 * k + 1] = pv[first + i + k];
        }
        ev_.points(uv.data(), m, P + i);
        i += m;
      }
    });
    });
    return out;
  }

  py::array derivatives(const Array& u, const Array& v, int n) {
    if (shape_of(u) != shape_of(v)) throw InvalidGeometry("derivatives: u and v must have the same shape");
    check_derivative_order(n, "derivatives: n");
    py::array_t<double> out(with(shape_of(u), n + 1, n + 1, 3));
    const double *pu = u.data(), *pv = v.data();
    double* o = out.mutable_data();
    const std::size_t count = static_cast<std::size_t>(u.size()), per = static_cast<std::size_t>((n + 1) * (n + 1));
    released(mutex_, [&] {
      std::vector<Eigen::Vector3d> D(per);
      for (std::size_t i = 0; i < count; ++i) {
        s_->derivatives(pu[i], pv[i], n, D.data());
        for (std::size_t k = 0; k < per; ++k)
          for (int d = 0; d < 3; ++d) o[(i * per + k) * 3 + d] = D[k][d];
      }
    });
    return out;
  }

  py::tuple project(const Array& points) {
    const std::vector<Eigen::Vector3d> P = points_of<3>(points, "project: points");
    const py::ssize_t n = static_cast<py::ssize_t>(P.size());
    py::array_t<double> u(n), v(n), foot({n, py::ssize_t{3}}), dist(n);
    double *pu = u.mutable_data(), *pv = v.mutable_data(), *pf = foot.mutable_data(), *pd = dist.mutable_data();
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      for (const Eigen::Vector3d& p : P)
        if (!p.allFinite()) throw InvalidGeometry("project: points must be finite");
      if (!projector_) projector_ = std::make_unique<SurfaceProjector>(*s_);
      for (std::size_t i = 0; i < P.size(); ++i) {
        const SurfaceProjection r = projector_->project(P[i]);
        pu[i] = r.u;
        pv[i] = r.v;
        pd[i] = r.distance;
        for (int d = 0; d < 3; ++d) pf[i * 3 + d] = r.point[d];
      }
    }
    return py::make_tuple(u, v, foot, dist);
  }

 private:
  std::shared_ptr<const BSplineSurface<3>> s_;
  std::mutex mutex_;
  SurfaceEvaluator<3> ev_;
  std::unique_ptr<SurfaceProjector> projector_;
};

std::shared_ptr<Surface> make_surface(int degree_u, int degree_v, const Array& knots_u, const Array& knots_v,
                                      const Array& poles, const py::object& weights) {
  if (poles.ndim() != 3 || poles.shape(2) != 3) throw InvalidGeometry("poles: must be an array of shape (nu, nv, 3)");
  std::vector<std::vector<Eigen::Vector3d>> P(static_cast<std::size_t>(poles.shape(0)));
  for (py::ssize_t i = 0; i < poles.shape(0); ++i)
    for (py::ssize_t j = 0; j < poles.shape(1); ++j)
      P[static_cast<std::size_t>(i)].emplace_back(poles.at(i, j, 0), poles.at(i, j, 1), poles.at(i, j, 2));
  std::vector<std::vector<double>> W;
  if (!weights.is_none()) {
    const Array w = Array::ensure(weights);
    if (!w || w.ndim() != 2 || w.shape(0) != poles.shape(0) || w.shape(1) != poles.shape(1))
      throw InvalidGeometry("weights: must be an array of shape (nu, nv) like the poles");
    for (py::ssize_t i = 0; i < w.shape(0); ++i) W.emplace_back(w.data(i, 0), w.data(i, 0) + w.shape(1));
  }
  return std::make_shared<Surface>(BSplineSurface<3>(degree_u, degree_v, to_vector(knots_u, "knots_u"),
                                                     to_vector(knots_v, "knots_v"), P, W));
}

}  // namespace

void bind_kernel(py::module_& m) {
  py::class_<AnyCurve, std::shared_ptr<AnyCurve>>(m, "BSplineCurve",
                                                  "B-spline / NURBS curve in 2D or 3D (poles of shape (n, 2) or (n, 3)).")
      .def(py::init(&make_curve), py::arg("degree"), py::arg("knots"), py::arg("poles"), py::arg("weights") = py::none(),
           "Full (clamped or not) knot vector of n + degree + 1 values; weights None: polynomial.")
      .def_property_readonly("dim", &AnyCurve::dim)
      .def_property_readonly("degree", &AnyCurve::degree)
      .def_property_readonly("knots", &AnyCurve::knots)
      .def_property_readonly("poles", &AnyCurve::poles)
      .def_property_readonly("weights", &AnyCurve::weights)
      .def_property_readonly("domain", &AnyCurve::domain)
      .def("evaluate", &AnyCurve::evaluate, py::arg("u"), "Points C(u): array of u.shape + (dim,).")
      .def("derivatives", &AnyCurve::derivatives, py::arg("u"), py::arg("n"),
           "C^(k)(u), k = 0..n: array of u.shape + (n + 1, dim).")
      .def("project", &AnyCurve::project, py::arg("points"),
           "Closest curve points (global) of points (m, dim): (u (m,), foot points (m, dim), distances (m,)).")
      .def("intersect", &intersect, py::arg("other"), py::arg("tol") = kIntersectionTolerance,
           "All intersections of two 2D curves: dict s, t, points (k, 2), tangent (k,), overlaps (m, 4) "
           "[s0, s1, t0, t1].");

  py::class_<Surface, std::shared_ptr<Surface>>(m, "BSplineSurface", "B-spline / NURBS surface in 3D.")
      .def(py::init(&make_surface), py::arg("degree_u"), py::arg("degree_v"), py::arg("knots_u"), py::arg("knots_v"),
           py::arg("poles"), py::arg("weights") = py::none(), "poles (nu, nv, 3), weights (nu, nv) or None.")
      .def_property_readonly("degrees", [](const Surface& s) { return std::make_pair(s.surface().degree_u(), s.surface().degree_v()); })
      .def_property_readonly("domain", [](const Surface& s) {
        const auto& x = s.surface();
        return py::make_tuple(x.first_u(), x.last_u(), x.first_v(), x.last_v());
      })
      .def("evaluate", &Surface::evaluate, py::arg("u"), py::arg("v"), "Points S(u, v): array of u.shape + (3,).")
      .def("derivatives", &Surface::derivatives, py::arg("u"), py::arg("v"), py::arg("n"),
           "S^(k,l)(u, v), k + l <= n (others zero): array of u.shape + (n + 1, n + 1, 3), [..., k, l, :].")
      .def("project", &Surface::project, py::arg("points"),
           "Closest surface points (global) of points (m, 3): (u, v, foot points (m, 3), distances).");
}

}  // namespace cg::python
