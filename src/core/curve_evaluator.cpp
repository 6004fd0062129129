#include "src/core/curve_evaluator.hpp"

#include <cmath>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"

namespace cg {

template <int Dim>
CurveEvaluator<Dim>::CurveEvaluator(const BSplineCurve<Dim>& curve)
    : curve_(&curve),
      p_(curve.degree()),
      n_(curve.num_poles() - 1),
      rational_(curve.is_rational()),
      periodic_(curve.is_periodic()) {
  require(curve.num_poles() > 0, "CurveEvaluator needs a non-empty curve");
  first_ = curve.first_param();
  last_ = curve.last_param();
  eps_ = 1e-12 * (last_ - first_);
  const std::size_t spans = static_cast<std::size_t>(n_ - p_ + 1);
  coeffs_.assign(spans * static_cast<std::size_t>((p_ + 1) * (Dim + 1)), 0.0);
  built_.assign(spans, 0);
}

template <int Dim>
void CurveEvaluator<Dim>::build_span(int s) {
  const double* U = curve_->knots().data();
  const double mid = 0.5 * (U[s] + U[s + 1]);
  const double half = 0.5 * (U[s + 1] - U[s]);
  double ders[(kMaxDegree + 1) * (kMaxDegree + 1)];
  ders_basis_funs(s, mid, p_, p_, U, ders);
  double* c = &coeffs_[static_cast<std::size_t>((s - p_) * (p_ + 1) * (Dim + 1))];
  const auto& H = curve_->homogeneous_poles();
  double f = 1.0;  // half^k / k!
  for (int k = 0; k <= p_; ++k) {
    Eigen::Map<HPoint> ck(c + k * (Dim + 1));
    ck.setZero();
    for (int j = 0; j <= p_; ++j) ck += ders[k * (p_ + 1) + j] * H.col(s - p_ + j);
    ck *= f;
    f *= half / (k + 1);
  }
  built_[static_cast<std::size_t>(s - p_)] = 1;
}

template <int Dim>
typename CurveEvaluator<Dim>::Local CurveEvaluator<Dim>::locate(double u) {
  if (!(u >= span_lo_ && u < span_hi_)) {
    if (periodic_) {
      u = curve_->check_param(u);
    } else if (!(u >= first_ - eps_ && u <= last_ + eps_)) {
      throw InvalidGeometry("parameter " + std::to_string(u) + " outside the curve domain [" +
                            std::to_string(first_) + ", " + std::to_string(last_) + "]");
    }
    if (!(u >= span_lo_ && u < span_hi_)) {
      const double* U = curve_->knots().data();
      span_ = find_span_hint(U, n_, p_, u, span_);
      span_lo_ = U[span_];
      span_hi_ = U[span_ + 1];
      if (span_ == n_) span_hi_ = last_ + eps_ + 1e-300;  // the last span is closed on the right
      if (span_ == p_ && !periodic_) span_lo_ = first_ - eps_;
      mid_ = 0.5 * (U[span_] + U[span_ + 1]);
      scale_ = 2.0 / (U[span_ + 1] - U[span_]);
      if (!built_[static_cast<std::size_t>(span_ - p_)]) build_span(span_);
    }
  }
  return {&coeffs_[static_cast<std::size_t>((span_ - p_) * (p_ + 1) * (Dim + 1))], (u - mid_) * scale_, scale_};
}

template <int Dim>
typename CurveEvaluator<Dim>::Point CurveEvaluator<Dim>::point(double u) {
  const Local L = locate(u);
  using HMap = Eigen::Map<const HPoint>;
  HPoint r = HMap(L.coeffs + p_ * (Dim + 1));
  for (int k = p_ - 1; k >= 0; --k) r = r * L.t + HMap(L.coeffs + k * (Dim + 1));
  if (!rational_) return r.template head<Dim>();
  return r.template head<Dim>() / r[Dim];
}

template <int Dim>
void CurveEvaluator<Dim>::d1(double u, Point& P, Point& D1) {
  const Local L = locate(u);
  using HMap = Eigen::Map<const HPoint>;
  HPoint r0 = HMap(L.coeffs + p_ * (Dim + 1));
  HPoint r1 = HPoint::Zero();
  for (int k = p_ - 1; k >= 0; --k) {
    r1 = r1 * L.t + r0;
    r0 = r0 * L.t + HMap(L.coeffs + k * (Dim + 1));
  }
  r1 *= L.scale;
  if (!rational_) {
    P = r0.template head<Dim>();
    D1 = r1.template head<Dim>();
    return;
  }
  const double iw = 1.0 / r0[Dim];
  P = r0.template head<Dim>() * iw;
  D1 = (r1.template head<Dim>() - r1[Dim] * P) * iw;
}

template <int Dim>
void CurveEvaluator<Dim>::d2(double u, Point& P, Point& D1, Point& D2) {
  const Local L = locate(u);
  using HMap = Eigen::Map<const HPoint>;
  HPoint r0 = HMap(L.coeffs + p_ * (Dim + 1));
  HPoint r1 = HPoint::Zero(), r2 = HPoint::Zero();
  for (int k = p_ - 1; k >= 0; --k) {
    r2 = r2 * L.t + r1;
    r1 = r1 * L.t + r0;
    r0 = r0 * L.t + HMap(L.coeffs + k * (Dim + 1));
  }
  r1 *= L.scale;
  r2 *= 2.0 * L.scale * L.scale;
  if (!rational_) {
    P = r0.template head<Dim>();
    D1 = r1.template head<Dim>();
    D2 = r2.template head<Dim>();
    return;
  }
  const double iw = 1.0 / r0[Dim];
  P = r0.template head<Dim>() * iw;
  D1 = (r1.template head<Dim>() - r1[Dim] * P) * iw;
  D2 = (r2.template head<Dim>() - 2.0 * r1[Dim] * D1 - r2[Dim] * P) * iw;
}

template <int Dim>
void CurveEvaluator<Dim>::points(const double* u, std::size_t n, Point* P) {
  for (std::size_t i = 0; i < n; ++i) P[i] = point(u[i]);
}

template <int Dim>
void CurveEvaluator<Dim>::points_d1(const double* u, std::size_t n, Point* P, Point* D1) {
  for (std::size_t i = 0; i < n; ++i) d1(u[i], P[i], D1[i]);
}

template <int Dim>
void CurveEvaluator<Dim>::points_d2(const double* u, std::size_t n, Point* P, Point* D1, Point* D2) {
  for (std::size_t i = 0; i < n; ++i) d2(u[i], P[i], D1[i], D2[i]);
}

template <int Dim>
std::vector<typename CurveEvaluator<Dim>::Point> CurveEvaluator<Dim>::points(const std::vector<double>& u) {
  std::vector<Point> P(u.size());
  points(u.data(), u.size(), P.data());
  return P;
}

template class CurveEvaluator<1>;
template class CurveEvaluator<2>;
template class CurveEvaluator<3>;

}  // namespace cg
