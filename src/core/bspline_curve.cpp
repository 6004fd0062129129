#include "src/core/bspline_curve.hpp"

#include <cmath>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/periodic.hpp"
#include "src/core/rational.hpp"

namespace cg {

namespace {
template <int Dim>
typename BSplineCurve<Dim>::HPoles to_homogeneous(const std::vector<typename BSplineCurve<Dim>::Point>& poles,
                                                  const std::vector<double>& weights) {
  require(weights.empty() || weights.size() == poles.size(),
          "weight count " + std::to_string(weights.size()) + " must equal pole count " +
              std::to_string(poles.size()));
  typename BSplineCurve<Dim>::HPoles h(Dim + 1, static_cast<Eigen::Index>(poles.size()));
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    const auto j = static_cast<Eigen::Index>(i);
    h.col(j).template head<Dim>() = w * poles[i];
    h(Dim, j) = w;
  }
  return h;
}

template <int Dim>
Eigen::Matrix<double, Dim, Eigen::Dynamic> cartesian(const std::vector<Eigen::Matrix<double, Dim, 1>>& poles) {
  Eigen::Matrix<double, Dim, Eigen::Dynamic> P(Dim, static_cast<Eigen::Index>(poles.size()));
  for (std::size_t i = 0; i < poles.size(); ++i) P.col(static_cast<Eigen::Index>(i)) = poles[i];
  return P;
}
}  // namespace

template <int Dim>
void BSplineCurve<Dim>::init(int degree, std::vector<double> knots, HPoles hpoles, Poles poles) {
  validate_knots(knots, degree, static_cast<int>(hpoles.cols()));
  rational_ = false;
  for (Eigen::Index i = 0; i < hpoles.cols(); ++i) {
    const double w = hpoles(Dim, i);
    if (!(std::isfinite(w) && w > 0.0))
      throw InvalidGeometry("weight " + std::to_string(i) + " = " + format_number(w) + " must be positive and finite");
    if (!hpoles.col(i).allFinite()) throw InvalidGeometry("pole " + std::to_string(i) + " is not finite");
    if (w != 1.0) rational_ = true;
  }
  if (poles.cols() != hpoles.cols()) {
    poles.resize(Dim, hpoles.cols());
    for (Eigen::Index i = 0; i < hpoles.cols(); ++i)
      poles.col(i) = hpoles.col(i).template head<Dim>() / hpoles(Dim, i);
  }
  degree_ = degree;
  knots_ = std::move(knots);
  hpoles_ = std::move(hpoles);
  poles_ = std::move(poles);
  periodic_ = false;
}

template <int Dim>
BSplineCurve<Dim>::BSplineCurve(int degree, std::vector<double> knots, const std::vector<Point>& poles,
                                const std::vector<double>& weights) {
  init(degree, std::move(knots), to_homogeneous<Dim>(poles, weights), cartesian<Dim>(poles));
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::from_homogeneous(int degree, std::vector<double> knots, HPoles hpoles,
                                                      bool periodic) {
  BSplineCurve c;
  c.init(degree, std::move(knots), std::move(hpoles));
  if (periodic) {
    check_unwrapped_periodic(c.knots_, c.degree_, c.hpoles_.cols(),
                             [&](Eigen::Index a, Eigen::Index b) { return (c.hpoles_.col(a) - c.hpoles_.col(b)).norm(); },
                             c.hpoles_.cwiseAbs().maxCoeff(), "curve");
    c.periodic_ = true;
  }
  return c;
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::periodic(int degree, const std::vector<double>& period_knots, double period,
                                              const std::vector<Point>& poles, const std::vector<double>& weights) {
  const int n = static_cast<int>(poles.size());
  require(degree >= 1 && degree <= kMaxDegree, "degree " + std::to_string(degree) + " out of range [1, " +
                                                   std::to_string(kMaxDegree) + "]");
  require(n >= degree + 1, "a periodic curve of degree " + std::to_string(degree) + " needs at least " +
                               std::to_string(degree + 1) + " poles, got " + std::to_string(n));
  require(static_cast<int>(period_knots.size()) == n,
          "a periodic curve needs as many knots per period as poles (" + std::to_string(n) + "), got " +
              std::to_string(period_knots.size()));
  std::vector<double> U = unwrap_periodic_knots(degree, period_knots, period);
  HPoles h0 = to_homogeneous<Dim>(poles, weights);
  HPoles h(Dim + 1, n + degree);
  h.leftCols(n) = h0;
  h.rightCols(degree) = h0.leftCols(degree);
  const Poles P0 = cartesian<Dim>(poles);
  Poles P(Dim, n + degree);
  P.leftCols(n) = P0;
  P.rightCols(degree) = P0.leftCols(degree);
  BSplineCurve c;
  c.init(degree, std::move(U), std::move(h), std::move(P));
  c.periodic_ = true;
  return c;
}

template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> BSplineCurve<Dim>::poles() const {
  std::vector<Point> P(static_cast<std::size_t>(num_poles()));
  for (int i = 0; i < num_poles(); ++i) P[static_cast<std::size_t>(i)] = pole(i);
  return P;
}

template <int Dim>
std::vector<double> BSplineCurve<Dim>::weights() const {
  std::vector<double> w(static_cast<std::size_t>(num_poles()));
  for (int i = 0; i < num_poles(); ++i) w[static_cast<std::size_t>(i)] = weight(i);
  return w;
}

template <int Dim>
bool BSplineCurve<Dim>::is_closed(double tol) const {
  return periodic_ || (point(first_param()) - point(last_param())).norm() <= tol;
}

template <int Dim>
double BSplineCurve<Dim>::check_param(double u) const {
  require(num_poles() > 0, "evaluation of an empty curve");
  const double a = first_param(), b = last_param();
  // Without this a periodic curve would wrap NaN/inf into a NaN span search.
  if (!std::isfinite(u)) throw InvalidGeometry("curve parameter " + format_number(u) + " is not finite");
  if (periodic_) {
    if (u >= a && u < b) return u;
    const double T = b - a;
    double r = std::fmod(u - a, T);
    if (r < 0) r += T;
    return a + r;
  }
  const double eps = 1e-12 * (b - a);
  if (!(u >= a - eps && u <= b + eps)) {
    const ValueRangeText t = format_value_range(u, a, b);
    throw InvalidGeometry("parameter " + t.value + " outside the curve domain [" + t.lo + ", " + t.hi + "]");
  }
  return u < a ? a : (u > b ? b : u);
}

template <int Dim>
int BSplineCurve<Dim>::span(double u) const {
  return find_span(knots_.data(), num_poles() - 1, degree_, check_param(u));
}

template <int Dim>
typename BSplineCurve<Dim>::HPoint BSplineCurve<Dim>::homogeneous_point(double u) const {
  u = check_param(u);
  const int p = degree_;
  const int s = find_span(knots_.data(), num_poles() - 1, p, u);
  double N[kMaxDegree + 1];
  basis_funs(s, u, p, knots_.data(), N);
  HPoint h = HPoint::Zero();
  for (int j = 0; j <= p; ++j) h += N[j] * hpoles_.col(s - p + j);
  return h;
}

template <int Dim>
typename BSplineCurve<Dim>::Point BSplineCurve<Dim>::point(double u) const {
  const HPoint h = homogeneous_point(u);
  if (!rational_) return h.template head<Dim>();
  return h.template head<Dim>() / h[Dim];
}

template <int Dim>
void BSplineCurve<Dim>::homogeneous_derivatives(double u, int order, HPoint* out) const {
  check_derivative_order(order, "curve");
  u = check_param(u);
  const int p = degree_;
  const int s = find_span(knots_.data(), num_poles() - 1, p, u);
  const int du = order < p ? order : p;
  double ders[(kMaxDegree + 1) * (kMaxDegree + 1)];
  ders_basis_funs(s, u, p, du, knots_.data(), ders);
  for (int k = 0; k <= du; ++k) {
    HPoint h = HPoint::Zero();
    for (int j = 0; j <= p; ++j) h += ders[k * (p + 1) + j] * hpoles_.col(s - p + j);
    out[k] = h;
  }
  for (int k = du + 1; k <= order; ++k) out[k] = HPoint::Zero();
}

template <int Dim>
void BSplineCurve<Dim>::derivatives(double u, int order, Point* out) const {
  check_derivative_order(order, "curve");
  HPoint hom[kMaxDegree + 1];  // order <= kMaxDegree (checked): no heap allocation
  homogeneous_derivatives(u, order, hom);
  if (!rational_) {
    for (int k = 0; k <= order; ++k) out[k] = hom[k].template head<Dim>();
    return;
  }
  rational_curve_derivatives<Dim>(hom, order, out);
}

template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> BSplineCurve<Dim>::derivatives(double u, int order) const {
  check_derivative_order(order, "curve");
  std::vector<Point> out(static_cast<std::size_t>(order + 1));
  derivatives(u, order, out.data());
  return out;
}

template class BSplineCurve<1>;
template class BSplineCurve<2>;
template class BSplineCurve<3>;

}  // namespace cg
