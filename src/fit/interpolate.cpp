#include "src/fit/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/fit/collocation.hpp"

namespace cg {

namespace {

void check_degree(int p) {
  require(p >= 1 && p <= kMaxDegree,
          "degree " + std::to_string(p) + " out of range [1, " + std::to_string(kMaxDegree) + "]");
}

// Degree in range and at least degree + 1 points (`what` names the operation in the message).
void check_point_count(std::size_t n, int p, const char* what) {
  check_degree(p);
  require(n >= static_cast<std::size_t>(p + 1), std::string(what) + " of degree " + std::to_string(p) +
                                                    " needs at least " + std::to_string(p + 1) + " points, got " +
                                                    std::to_string(n));
}

template <int Dim>
Eigen::MatrixXd to_rows(const PointList<Dim>& points) {
  Eigen::MatrixXd M(static_cast<Eigen::Index>(points.size()), Dim);
  for (std::size_t k = 0; k < points.size(); ++k) M.row(static_cast<Eigen::Index>(k)) = points[k].transpose();
  return M;
}

template <int Dim>
PointList<Dim> to_points(const Eigen::MatrixXd& M) {
  PointList<Dim> P(static_cast<std::size_t>(M.rows()));
  for (Eigen::Index k = 0; k < M.rows(); ++k) P[static_cast<std::size_t>(k)] = M.row(k).transpose();
  return P;
}

void check_params(const std::vector<double>& params, const char* what) {
  for (std::size_t k = 0; k < params.size(); ++k) {
    require(std::isfinite(params[k]), std::string(what) + " parameter " + std::to_string(k) + " is not finite");
    if (k > 0)
      require(params[k] > params[k - 1],
              std::string(what) + " parameters must be strictly increasing (parameter " + std::to_string(k) + ")");
  }
}

}  // namespace

template <int Dim>
std::vector<double> interpolation_parameters(const PointList<Dim>& points, ParamMethod method, bool closed) {
  const std::size_t n = points.size();
  require(n >= 2, "interpolation needs at least 2 points, got " + std::to_string(n));
  const std::size_t segments = closed ? n : n - 1;
  std::vector<double> chord(segments);
  double polygon = 0;
  for (std::size_t k = 0; k < segments; ++k) {
    chord[k] = (points[(k + 1) % n] - points[k]).norm();
    require(std::isfinite(chord[k]), "point " + std::to_string(k) + " is not finite");
    polygon += chord[k];
  }
  // Coincident consecutive points give a zero chord: a repeated parameter and a singular system.
  for (std::size_t k = 0; k < segments; ++k)
    require(chord[k] > 1e-14 * polygon, "points " + std::to_string(k) + " and " + std::to_string((k + 1) % n) +
                                            " coincide (distance " + format_number(chord[k]) +
                                            "); consecutive points must be distinct");
  std::vector<double> step(segments);
  for (std::size_t k = 0; k < segments; ++k)
    step[k] = method == ParamMethod::Uniform       ? 1.0
              : method == ParamMethod::ChordLength ? chord[k]
                                                   : std::sqrt(chord[k]);
  double total = 0;
  for (double s : step) total += s;
  std::vector<double> t(n);
  double acc = 0;
  t[0] = 0;
  for (std::size_t k = 1; k < n; ++k) {
    acc += step[k - 1];
    t[k] = acc / total;
  }
  if (!closed) t[n - 1] = 1.0;  // exact end despite rounding
  return t;
}

std::vector<double> averaged_knots(const std::vector<double>& params, int p) {
  check_degree(p);
  const int n = static_cast<int>(params.size()) - 1;
  require(n >= p, "averaged knots of degree " + std::to_string(p) + " need at least " + std::to_string(p + 1) +
                      " parameters, got " + std::to_string(n + 1));
  std::vector<double> U(static_cast<std::size_t>(n + p + 2));
  for (int i = 0; i <= p; ++i) {
    U[static_cast<std::size_t>(i)] = params.front();
    U[static_cast<std::size_t>(n + 1 + i)] = params.back();
  }
  for (int j = 1; j <= n - p; ++j) {
    double s = 0;
    for (int i = j; i < j + p; ++i) s += params[static_cast<std::size_t>(i)];
    U[static_cast<std::size_t>(j + p)] = s / p;
  }
  return U;
}

std::vector<double> averaged_knots_end_derivatives(const std::vector<double>& params, int p) {
  check_degree(p);
  require(p >= 2, "interpolation with end derivatives needs degree >= 2, got " + std::to_string(p));
  const int n = static_cast<int>(params.size()) - 1;
  require(n >= 1 && n + 1 >= p - 1, "interpolation with end derivatives of degree " + std::to_string(p) +
                                        " needs at least " + std::to_string(std::max(2, p - 1)) + " points, got " +
                                        std::to_string(n + 1));
  const int poles = n + 3;
  std::vector<double> U(static_cast<std::size_t>(poles + p + 1));
  for (int i = 0; i <= p; ++i) {
    U[static_cast<std::size_t>(i)] = params.front();
    U[static_cast<std::size_t>(poles + i)] = params.back();
  }
  // eq. 9.22: interior knot j averages the window of p parameters starting at j - 1.
  for (int j = 1; j <= n - p + 2; ++j) {
    double s = 0;
    for (int i = j - 1; i <= j + p - 2; ++i) s += params[static_cast<std::size_t>(i)];
    U[static_cast<std::size_t>(j + p)] = s / p;
  }
  return U;
}

template <int Dim>
BSplineCurve<Dim> interpolate(const PointList<Dim>& points, int degree, const std::vector<double>& params,
                              const std::vector<double>& knots) {
  const int n = static_cast<int>(points.size());
  check_point_count(points.size(), degree, "interpolation");
  require(static_cast<int>(params.size()) == n, "one parameter per point needed");
  check_params(params, "interpolation");
  validate_knots(knots, degree, n);
  const Eigen::MatrixXd P = solve_collocation(degree, knots, false, params,
                                              std::vector<int>(static_cast<std::size_t>(n), 0), to_rows<Dim>(points));
  return BSplineCurve<Dim>(degree, knots, to_points<Dim>(P));
}

template <int Dim>
BSplineCurve<Dim> interpolate(const PointList<Dim>& points, int degree, ParamMethod method) {
  check_point_count(points.size(), degree, "interpolation");
  const std::vector<double> t = interpolation_parameters<Dim>(points, method);
  return interpolate<Dim>(points, degree, t, averaged_knots(t, degree));
}

template <int Dim>
BSplineCurve<Dim> interpolate_end_derivatives(const PointList<Dim>& points, const Eigen::Matrix<double, Dim, 1>& d0,
                                              const Eigen::Matrix<double, Dim, 1>& dn, int degree,
                                              const std::vector<double>& params, const std::vector<double>& knots) {
  check_degree(degree);
  const int n = static_cast<int>(points.size());
  require(n >= 2, "interpolation with end derivatives needs at least 2 points, got " + std::to_string(n));
  require(static_cast<int>(params.size()) == n, "one parameter per point needed");
  require(d0.allFinite() && dn.allFinite(), "end derivatives must be finite");
  check_params(params, "interpolation");
  validate_knots(knots, degree, n + 2);
  // Row order Q0, D0, Q1 .. Q(n-2), Dn, Q(n-1) matches the pole order (a banded, diagonal-dominant-ish
  // matrix whose diagonal is non-zero exactly under Schoenberg-Whitney).
  std::vector<double> t;
  std::vector<int> order;
  Eigen::MatrixXd rhs(n + 2, Dim);
  t.reserve(static_cast<std::size_t>(n + 2));
  auto add = [&](double u, int k, const Eigen::Matrix<double, Dim, 1>& v) {
    rhs.row(static_cast<Eigen::Index>(t.size())) = v.transpose();
    t.push_back(u);
    order.push_back(k);
  };
  add(params.front(), 0, points.front());
  add(params.front(), 1, d0);
  for (int k = 1; k + 1 < n; ++k) add(params[static_cast<std::size_t>(k)], 0, points[static_cast<std::size_t>(k)]);
  add(params.back(), 1, dn);
  add(params.back(), 0, points.back());
  const Eigen::MatrixXd P = solve_collocation(degree, knots, false, t, order, rhs);
  return BSplineCurve<Dim>(degree, knots, to_points<Dim>(P));
}

template <int Dim>
BSplineCurve<Dim> interpolate_end_derivatives(const PointList<Dim>& points, const Eigen::Matrix<double, Dim, 1>& d0,
                                              const Eigen::Matrix<double, Dim, 1>& dn, int degree, ParamMethod method) {
  check_degree(degree);
  const std::vector<double> t = interpolation_parameters<Dim>(points, method);
  return interpolate_end_derivatives<Dim>(points, d0, dn, degree, t, averaged_knots_end_derivatives(t, degree));
}

std::vector<double> periodic_interpolation_knots(const std::vector<double>& params, int p) {
  const std::size_t n = params.size();
  check_point_count(n, p, "periodic interpolation");
  check_params(params, "periodic interpolation");
  require(params.back() < params.front() + 1.0, "periodic parameters must lie within one period of length 1");
  if (p % 2 == 1) return params;
  // Even degree: t_j midway between u_{j-1} and u_j (u_{-1} = u_{n-1} - 1).
  std::vector<double> t(n);
  t[0] = 0.5 * (params[n - 1] - 1.0 + params[0]);
  for (std::size_t j = 1; j < n; ++j) t[j] = 0.5 * (params[j - 1] + params[j]);
  return t;
}

template <int Dim>
BSplineCurve<Dim> interpolate_closed(const PointList<Dim>& points, int degree, const std::vector<double>& params,
                                     const std::vector<double>& period_knots) {
  const int n = static_cast<int>(points.size());
  check_point_count(points.size(), degree, "closed interpolation");
  require(static_cast<int>(params.size()) == n && static_cast<int>(period_knots.size()) == n,
          "closed interpolation needs one parameter and one knot per point");
  check_params(params, "periodic interpolation");
  require(params.back() < params.front() + 1.0, "periodic parameters must lie within one period of length 1");
  const std::vector<double> U = unwrap_periodic_knots(degree, period_knots, 1.0);
  validate_knots(U, degree, n + degree);
  const Eigen::MatrixXd P = solve_collocation(degree, U, true, params, std::vector<int>(static_cast<std::size_t>(n), 0),
                                              to_rows<Dim>(points));
  return BSplineCurve<Dim>::periodic(degree, period_knots, 1.0, to_points<Dim>(P));
}

template <int Dim>
BSplineCurve<Dim> interpolate_closed(const PointList<Dim>& points, int degree, ParamMethod method) {
  check_point_count(points.size(), degree, "closed interpolation");
  const std::vector<double> t = interpolation_parameters<Dim>(points, method, true);
  return interpolate_closed<Dim>(points, degree, t, periodic_interpolation_knots(t, degree));
}

#define CG_FIT_INTERPOLATE_INSTANTIATE(D)                                                                          \
  template std::vector<double> interpolation_parameters<D>(const PointList<D>&, ParamMethod, bool);                \
  template BSplineCurve<D> interpolate<D>(const PointList<D>&, int, const std::vector<double>&,                    \
                                          const std::vector<double>&);                                             \
  template BSplineCurve<D> interpolate<D>(const PointList<D>&, int, ParamMethod);                                  \
  template BSplineCurve<D> interpolate_end_derivatives<D>(const PointList<D>&, const Eigen::Matrix<double, D, 1>&, \
                                                          const Eigen::Matrix<double, D, 1>&, int, ParamMethod);   \
  template BSplineCurve<D> interpolate_end_derivatives<D>(const PointList<D>&, const Eigen::Matrix<double, D, 1>&, \
                                                          const Eigen::Matrix<double, D, 1>&, int,                 \
                                                          const std::vector<double>&, const std::vector<double>&); \
  template BSplineCurve<D> interpolate_closed<D>(const PointList<D>&, int, ParamMethod);                           \
  template BSplineCurve<D> interpolate_closed<D>(const PointList<D>&, int, const std::vector<double>&,             \
                                                 const std::vector<double>&);
CG_FIT_INTERPOLATE_INSTANTIATE(1)
CG_FIT_INTERPOLATE_INSTANTIATE(2)
CG_FIT_INTERPOLATE_INSTANTIATE(3)

}  // namespace cg
