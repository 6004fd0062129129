#include "src/core/surface_evaluator.hpp"

#include "src/core/basis.hpp"
#include "src/core/error.hpp"

namespace cg {

template <int Dim>
SurfaceEvaluator<Dim>::SurfaceEvaluator(const BSplineSurface<Dim>& s)
    : SurfaceEvaluator(std::make_shared<const BSplineSurface<Dim>>(s)) {}

template <int Dim>
SurfaceEvaluator<Dim>::SurfaceEvaluator(std::shared_ptr<const BSplineSurface<Dim>> shared)
    : s_(std::move(shared)), pu_(s_->degree_u()), pv_(s_->degree_v()) {
  const BSplineSurface<Dim>& s = *s_;
  require(s.num_poles_u() > 0, "SurfaceEvaluator needs a non-empty surface");
  nspan_u_ = s.num_poles_u() - pu_;
  nspan_v_ = s.num_poles_v() - pv_;
  const double epsu = 1e-12 * (s.last_u() - s.first_u()), epsv = 1e-12 * (s.last_v() - s.first_v());
  spans_u_ = SpanTable(s.knots_u().data(), s.num_poles_u() - 1, pu_, epsu, s.is_periodic_u());
  spans_v_ = SpanTable(s.knots_v().data(), s.num_poles_v() - 1, pv_, epsv, s.is_periodic_v());
  const std::size_t patches = static_cast<std::size_t>(nspan_u_) * static_cast<std::size_t>(nspan_v_);
  coeffs_.assign(patches * static_cast<std::size_t>((pu_ + 1) * (pv_ + 1) * (Dim + 1)), 0.0);
  built_.assign(patches, 0);
}

template <int Dim>
void SurfaceEvaluator<Dim>::build_patch(int su, int sv) {
  const double* U = s_->knots_u().data();
  const double* V = s_->knots_v().data();
  const double um = 0.5 * (U[su] + U[su + 1]), uh = 0.5 * (U[su + 1] - U[su]);
  const double vm = 0.5 * (V[sv] + V[sv + 1]), vh = 0.5 * (V[sv + 1] - V[sv]);
  double Nu[(kMaxDegree + 1) * (kMaxDegree + 1)], Nv[(kMaxDegree + 1) * (kMaxDegree + 1)];
  ders_basis_funs(su, um, pu_, pu_, U, Nu);
  ders_basis_funs(sv, vm, pv_, pv_, V, Nv);
  const std::size_t patch = static_cast<std::size_t>((su - pu_) * nspan_v_ + (sv - pv_));
  double* c = &coeffs_[patch * static_cast<std::size_t>((pu_ + 1) * (pv_ + 1) * (Dim + 1))];
  const int nv = s_->num_poles_v();
  const auto& H = s_->homogeneous_poles();
  HPoint temp[kMaxDegree + 1];
  double fu = 1.0;
  for (int k = 0; k <= pu_; ++k) {
    for (int j = 0; j <= pv_; ++j) {
      temp[j].setZero();
      for (int i = 0; i <= pu_; ++i) temp[j] += Nu[k * (pu_ + 1) + i] * H.col((su - pu_ + i) * nv + sv - pv_ + j);
    }
    double fv = 1.0;
    for (int l = 0; l <= pv_; ++l) {
      Eigen::Map<HPoint> ckl(c + (k * (pv_ + 1) + l) * (Dim + 1));
      ckl.setZero();
      for (int j = 0; j <= pv_; ++j) ckl += Nv[l * (pv_ + 1) + j] * temp[j];
      ckl *= fu * fv;
      fv *= vh / (l + 1);
    }
    fu *= uh / (k + 1);
  }
  built_[patch] = 1;
}

template <int Dim>
void SurfaceEvaluator<Dim>::relocate(double& u, double& v) {
  s_->check_params(u, v);  // wraps periodic directions, clamps within the tolerance, throws outside
  if (!(u >= su_.lo && u < su_.hi)) {
    cu_ = spans_u_.find(u);
    su_ = spans_u_.span(cu_);
  }
  if (!(v >= sv_.lo && v < sv_.hi)) {
    cv_ = spans_v_.find(v);
    sv_ = spans_v_.span(cv_);
  }
  const std::size_t patch = static_cast<std::size_t>((cu_ - pu_) * nspan_v_ + (cv_ - pv_));
  if (!built_[patch]) build_patch(cu_, cv_);
  cur_ = patch * static_cast<std::size_t>((pu_ + 1) * (pv_ + 1) * (Dim + 1));
}

template <int Dim>
typename SurfaceEvaluator<Dim>::Point SurfaceEvaluator<Dim>::point(double u, double v) {
  const double uv[2] = {u, v};
  Point P;
  points(uv, 1, &P);
  return P;
}

// Row-cached double Horner (The NURBS Book section 1.2, nested over the two directions): for the
// current patch and u, the coefficients are contracted in s to row[l] = sum_k c_kl s^k once, and
// each point then evaluates the univariate polynomial sum_l row[l] t^l.
template <int Dim>
template <int PU, int PV>
void SurfaceEvaluator<Dim>::eval_batch(const double* uv, std::size_t n, Point* P) {
  constexpr int W = Dim + 1;
  const int pu = PU > 0 ? PU : pu_, pv = PV > 0 ? PV : pv_;
  const bool rational = s_->is_rational();
  double row[(PV > 0 ? PV : kMaxDegree) + 1][W] = {};
  double row_u = 0;
  bool row_valid = false;
  for (std::size_t i = 0; i < n; ++i) {
    double u = uv[2 * i], v = uv[2 * i + 1];
    if (!(u >= su_.lo && u < su_.hi && v >= sv_.lo && v < sv_.hi)) {
      const std::size_t before = cur_;
      relocate(u, v);
      if (cur_ != before) row_valid = false;
    }
    if (!row_valid || u != row_u) {
      const double s = (u - su_.mid) * su_.scale;
      const double* c = coeffs_.data() + cur_;
      for (int l = 0; l <= pv; ++l) {
        for (int d = 0; d < W; ++d) row[l][d] = c[(pu * (pv + 1) + l) * W + d];
        for (int k = pu - 1; k >= 0; --k)
          for (int d = 0; d < W; ++d) row[l][d] = row[l][d] * s + c[(k * (pv + 1) + l) * W + d];
      }
      row_u = u;
      row_valid = true;
    }
    const double t = (v - sv_.mid) * sv_.scale;
    double r[W];
    for (int d = 0; d < W; ++d) r[d] = row[pv][d];
    for (int l = pv - 1; l >= 0; --l)
      for (int d = 0; d < W; ++d) r[d] = r[d] * t + row[l][d];
    if (!rational) {
      for (int d = 0; d < Dim; ++d) P[i][d] = r[d];
    } else {
      const double iw = 1.0 / r[Dim];
      for (int d = 0; d < Dim; ++d) P[i][d] = r[d] * iw;
    }
  }
}

template <int Dim>
void SurfaceEvaluator<Dim>::d1(double u, double v, Point& P, Point& Su, Point& Sv) {
  if (!(u >= su_.lo && u < su_.hi && v >= sv_.lo && v < sv_.hi)) relocate(u, v);
  const double s = (u - su_.mid) * su_.scale, t = (v - sv_.mid) * sv_.scale;
  const double* c = coeffs_.data() + cur_;
  using HMap = Eigen::Map<const HPoint>;
  HPoint r = HPoint::Zero(), ru = HPoint::Zero(), rv = HPoint::Zero();
  for (int k = pu_; k >= 0; --k) {
    const double* ck = c + k * (pv_ + 1) * (Dim + 1);
    HPoint b = HMap(ck + pv_ * (Dim + 1));
    HPoint bt = HPoint::Zero();
    for (int l = pv_ - 1; l >= 0; --l) {
      bt = bt * t + b;
      b = b * t + HMap(ck + l * (Dim + 1));
    }
    ru = ru * s + r;
    r = r * s + b;
    rv = rv * s + bt;
  }
  ru *= su_.scale;
  rv *= sv_.scale;
  if (!s_->is_rational()) {
    P = r.template head<Dim>();
    Su = ru.template head<Dim>();
    Sv = rv.template head<Dim>();
    return;
  }
  const double iw = 1.0 / r[Dim];
  P = r.template head<Dim>() * iw;
  Su = (ru.template head<Dim>() - ru[Dim] * P) * iw;
  Sv = (rv.template head<Dim>() - rv[Dim] * P) * iw;
}

template <int Dim>
void SurfaceEvaluator<Dim>::points(const double* uv, std::size_t n, Point* P) {
  if (pu_ == pv_) {
    switch (pu_) {
      case 1: return eval_batch<1, 1>(uv, n, P);
      case 2: return eval_batch<2, 2>(uv, n, P);
      case 3: return eval_batch<3, 3>(uv, n, P);
      case 4: return eval_batch<4, 4>(uv, n, P);
      case 5: return eval_batch<5, 5>(uv, n, P);
      default: break;
    }
  }
  eval_batch<0, 0>(uv, n, P);
}

template class SurfaceEvaluator<1>;
template class SurfaceEvaluator<2>;
template class SurfaceEvaluator<3>;

}  // namespace cg
