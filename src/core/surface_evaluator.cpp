#include "src/core/surface_evaluator.hpp"

#include "src/core/basis.hpp"
#include "src/core/error.hpp"

namespace cg {

template <int Dim>
SurfaceEvaluator<Dim>::SurfaceEvaluator(const BSplineSurface<Dim>& s)
    : s_(&s), pu_(s.degree_u()), pv_(s.degree_v()) {
  require(s.num_poles_u() > 0, "SurfaceEvaluator needs a non-empty surface");
  nspan_u_ = s.num_poles_u() - pu_;
  nspan_v_ = s.num_poles_v() - pv_;
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
const double* SurfaceEvaluator<Dim>::locate(double& u, double& v, double& s, double& t) {
  if (!(u >= ulo_ && u < uhi_ && v >= vlo_ && v < vhi_)) {
    s_->check_params(u, v);
    const double* U = s_->knots_u().data();
    const double* V = s_->knots_v().data();
    const int nu = s_->num_poles_u() - 1, nv = s_->num_poles_v() - 1;
    if (!(u >= ulo_ && u < uhi_)) {
      cu_ = find_span_hint(U, nu, pu_, u, cu_);
      ulo_ = cu_ == pu_ ? s_->first_u() - 1e-12 * (s_->last_u() - s_->first_u()) : U[cu_];
      uhi_ = cu_ == nu ? s_->last_u() + 1e-12 * (s_->last_u() - s_->first_u()) + 1e-300 : U[cu_ + 1];
      umid_ = 0.5 * (U[cu_] + U[cu_ + 1]);
      uscale_ = 2.0 / (U[cu_ + 1] - U[cu_]);
    }
    if (!(v >= vlo_ && v < vhi_)) {
      cv_ = find_span_hint(V, nv, pv_, v, cv_);
      vlo_ = cv_ == pv_ ? s_->first_v() - 1e-12 * (s_->last_v() - s_->first_v()) : V[cv_];
      vhi_ = cv_ == nv ? s_->last_v() + 1e-12 * (s_->last_v() - s_->first_v()) + 1e-300 : V[cv_ + 1];
      vmid_ = 0.5 * (V[cv_] + V[cv_ + 1]);
      vscale_ = 2.0 / (V[cv_ + 1] - V[cv_]);
    }
  }
  const std::size_t patch = static_cast<std::size_t>((cu_ - pu_) * nspan_v_ + (cv_ - pv_));
  if (!built_[patch]) build_patch(cu_, cv_);
  s = (u - umid_) * uscale_;
  t = (v - vmid_) * vscale_;
  return &coeffs_[patch * static_cast<std::size_t>((pu_ + 1) * (pv_ + 1) * (Dim + 1))];
}

template <int Dim>
typename SurfaceEvaluator<Dim>::Point SurfaceEvaluator<Dim>::point(double u, double v) {
  double s, t;
  const double* c = locate(u, v, s, t);
  using HMap = Eigen::Map<const HPoint>;
  HPoint r = HPoint::Zero();
  for (int k = pu_; k >= 0; --k) {
    const double* ck = c + k * (pv_ + 1) * (Dim + 1);
    HPoint b = HMap(ck + pv_ * (Dim + 1));
    for (int l = pv_ - 1; l >= 0; --l) b = b * t + HMap(ck + l * (Dim + 1));
    r = r * s + b;
  }
  if (!s_->is_rational()) return r.template head<Dim>();
  return r.template head<Dim>() / r[Dim];
}

template <int Dim>
void SurfaceEvaluator<Dim>::d1(double u, double v, Point& P, Point& Su, Point& Sv) {
  double s, t;
  const double* c = locate(u, v, s, t);
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
  ru *= uscale_;
  rv *= vscale_;
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
  for (std::size_t i = 0; i < n; ++i) P[i] = point(uv[2 * i], uv[2 * i + 1]);
}

template class SurfaceEvaluator<1>;
template class SurfaceEvaluator<2>;
template class SurfaceEvaluator<3>;

}  // namespace cg
