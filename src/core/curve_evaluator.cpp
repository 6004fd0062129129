#include "src/core/curve_evaluator.hpp"

#include <cmath>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

template <int Dim>
CurveEvaluator<Dim>::CurveEvaluator(const BSplineCurve<Dim>& curve)
    : CurveEvaluator(std::make_shared<const BSplineCurve<Dim>>(curve)) {}

template <int Dim>
CurveEvaluator<Dim>::CurveEvaluator(std::shared_ptr<const BSplineCurve<Dim>> shared)
    : curve_(std::move(shared)),
      p_(curve_->degree()),
      n_(curve_->num_poles() - 1),
      rational_(curve_->is_rational()),
      periodic_(curve_->is_periodic()) {
  const BSplineCurve<Dim>& curve = *curve_;
  require(curve.num_poles() > 0, "CurveEvaluator needs a non-empty curve");
  first_ = curve.first_param();
  last_ = curve.last_param();
  eps_ = 1e-12 * (last_ - first_);
  spans_ = SpanTable(curve.knots().data(), n_, p_, eps_, periodic_);
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
void CurveEvaluator<Dim>::relocate(double& u) {
  if (periodic_) {
    u = curve_->check_param(u);  // wraps into the base period; rejects non-finite u
  } else if (!(u >= first_ - eps_ && u <= last_ + eps_)) {
    const ValueRangeText t = format_value_range(u, first_, last_);
    throw InvalidGeometry("parameter " + t.value + " outside the curve domain [" + t.lo + ", " + t.hi + "] (tolerance " +
                          format_number(eps_) + ")");
  }
  if (u >= sp_.lo && u < sp_.hi) return;  // wrapping landed in the current span
  span_ = spans_.find(u);
  sp_ = spans_.span(span_);
  if (!built_[static_cast<std::size_t>(span_ - p_)]) build_span(span_);
  cur_ = static_cast<std::size_t>((span_ - p_) * (p_ + 1) * (Dim + 1));
}

// Horner's rule on the span polynomial and its first Order derivatives in t (The NURBS Book,
// section 1.2, on the homogeneous coefficients), then the chain rule dt/du = scale and, for rational
// curves, the quotient rule (A4.2). The span state lives in locals so stores through the output
// pointers cannot force reloads; it is refreshed only after relocate().
template <int Dim>
template <int P, int Order>
void CurveEvaluator<Dim>::eval_batch(const double* u, std::size_t n, Point* P0, Point* D1, Point* D2) {
  constexpr int W = Dim + 1;
  const int p = P > 0 ? P : p_;
  const bool rational = rational_;
  SpanTable::Span sp = sp_;
  const double* c = coeffs_.data() + cur_;
  for (std::size_t i = 0; i < n; ++i) {
    double x = u[i];
    if (!(x >= sp.lo && x < sp.hi)) {
      relocate(x);
      sp = sp_;
      c = coeffs_.data() + cur_;
    }
    const double sc = sp.scale;
    const double t = (x - sp.mid) * sc;
    double r0[W], r1[W], r2[W];
    for (int d = 0; d < W; ++d) {
      r0[d] = c[p * W + d];
      r1[d] = 0.0;
      r2[d] = 0.0;
    }
    for (int k = p - 1; k >= 0; --k) {
      const double* ck = c + k * W;
      for (int d = 0; d < W; ++d) {
        if (Order >= 2) r2[d] = r2[d] * t + r1[d];
        if (Order >= 1) r1[d] = r1[d] * t + r0[d];
        r0[d] = r0[d] * t + ck[d];
      }
    }
    const double s1 = sc, s2 = 2.0 * sc * sc;  // d/du of t, and 2! * (dt/du)^2 for the t^2 Taylor term
    if (!rational) {
      for (int d = 0; d < Dim; ++d) {
        P0[i][d] = r0[d];
        if (Order >= 1) D1[i][d] = r1[d] * s1;
        if (Order >= 2) D2[i][d] = r2[d] * s2;
      }
      continue;
    }
    const double iw = 1.0 / r0[Dim];
    double q0[Dim], q1[Dim];
    for (int d = 0; d < Dim; ++d) q0[d] = r0[d] * iw;
    for (int d = 0; d < Dim; ++d) P0[i][d] = q0[d];
    if (Order >= 1) {
      const double w1 = r1[Dim] * s1;
      for (int d = 0; d < Dim; ++d) q1[d] = (r1[d] * s1 - w1 * q0[d]) * iw;
      for (int d = 0; d < Dim; ++d) D1[i][d] = q1[d];
      if (Order >= 2) {
        const double w2 = r2[Dim] * s2;
        for (int d = 0; d < Dim; ++d) D2[i][d] = (r2[d] * s2 - 2.0 * w1 * q1[d] - w2 * q0[d]) * iw;
      }
    }
  }
}

template <int Dim>
template <int Order>
void CurveEvaluator<Dim>::dispatch(const double* u, std::size_t n, Point* P0, Point* D1, Point* D2) {
  switch (p_) {
    case 1: return eval_batch<1, Order>(u, n, P0, D1, D2);
    case 2: return eval_batch<2, Order>(u, n, P0, D1, D2);
    case 3: return eval_batch<3, Order>(u, n, P0, D1, D2);
    case 4: return eval_batch<4, Order>(u, n, P0, D1, D2);
    case 5: return eval_batch<5, Order>(u, n, P0, D1, D2);
    case 6: return eval_batch<6, Order>(u, n, P0, D1, D2);
    case 7: return eval_batch<7, Order>(u, n, P0, D1, D2);
    default: return eval_batch<0, Order>(u, n, P0, D1, D2);
  }
}

template <int Dim>
typename CurveEvaluator<Dim>::Point CurveEvaluator<Dim>::point(double u) {
  Point P;
  dispatch<0>(&u, 1, &P, nullptr, nullptr);
  return P;
}

template <int Dim>
void CurveEvaluator<Dim>::d1(double u, Point& P, Point& D1) {
  dispatch<1>(&u, 1, &P, &D1, nullptr);
}

template <int Dim>
void CurveEvaluator<Dim>::d2(double u, Point& P, Point& D1, Point& D2) {
  dispatch<2>(&u, 1, &P, &D1, &D2);
}

template <int Dim>
void CurveEvaluator<Dim>::points(const double* u, std::size_t n, Point* P) {
  dispatch<0>(u, n, P, nullptr, nullptr);
}

template <int Dim>
void CurveEvaluator<Dim>::points_d1(const double* u, std::size_t n, Point* P, Point* D1) {
  dispatch<1>(u, n, P, D1, nullptr);
}

template <int Dim>
void CurveEvaluator<Dim>::points_d2(const double* u, std::size_t n, Point* P, Point* D1, Point* D2) {
  dispatch<2>(u, n, P, D1, D2);
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
