#include "src/core/bspline_surface.hpp"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/core/periodic.hpp"
#include "src/core/rational.hpp"

namespace cg {

template <int Dim>
void BSplineSurface<Dim>::init(int pu, int pv, std::vector<double> U, std::vector<double> V, int nu, int nv,
                               HPoles h, Poles poles) {
  require(nu >= 1 && nv >= 1 && h.cols() == static_cast<Eigen::Index>(nu) * nv,
          "surface pole grid must have nu * nv = " + std::to_string(nu) + " * " + std::to_string(nv) + " poles");
  validate_knots(U, pu, nu);
  validate_knots(V, pv, nv);
  rational_ = false;
  for (Eigen::Index i = 0; i < h.cols(); ++i) {
    const double w = h(Dim, i);
    if (!(std::isfinite(w) && w > 0.0))
      throw InvalidGeometry("surface weight " + std::to_string(i) + " must be positive and finite");
    if (!h.col(i).allFinite()) throw InvalidGeometry("surface pole " + std::to_string(i) + " is not finite");
    if (w != 1.0) rational_ = true;
  }
  if (poles.cols() != h.cols()) {
    poles.resize(Dim, h.cols());
    for (Eigen::Index i = 0; i < h.cols(); ++i) poles.col(i) = h.col(i).template head<Dim>() / h(Dim, i);
  }
  poles_ = std::move(poles);
  pu_ = pu;
  pv_ = pv;
  nu_ = nu;
  nv_ = nv;
  U_ = std::move(U);
  V_ = std::move(V);
  hpoles_ = std::move(h);
  periodic_u_ = periodic_v_ = false;
}

template <int Dim>
BSplineSurface<Dim>::BSplineSurface(int pu, int pv, std::vector<double> U, std::vector<double> V,
                                    const std::vector<std::vector<Point>>& poles,
                                    const std::vector<std::vector<double>>& weights) {
  const int nu = static_cast<int>(poles.size());
  require(nu > 0, "surface needs poles");
  const int nv = static_cast<int>(poles[0].size());
  require(weights.empty() || static_cast<int>(weights.size()) == nu, "surface weight rows must match pole rows");
  HPoles h(Dim + 1, static_cast<Eigen::Index>(nu) * nv);
  Poles cart(Dim, static_cast<Eigen::Index>(nu) * nv);
  for (int i = 0; i < nu; ++i) {
    require(static_cast<int>(poles[static_cast<std::size_t>(i)].size()) == nv,
            "surface pole row " + std::to_string(i) + " has " + std::to_string(poles[static_cast<std::size_t>(i)].size()) +
                " poles, expected " + std::to_string(nv));
    for (int j = 0; j < nv; ++j) {
      double w = 1.0;
      if (!weights.empty()) {
        require(static_cast<int>(weights[static_cast<std::size_t>(i)].size()) == nv, "surface weight row size mismatch");
        w = weights[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      }
      h.col(i * nv + j).template head<Dim>() = w * poles[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      h(Dim, i * nv + j) = w;
      cart.col(i * nv + j) = poles[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    }
  }
  init(pu, pv, std::move(U), std::move(V), nu, nv, std::move(h), std::move(cart));
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::from_poles(int pu, int pv, std::vector<double> U, std::vector<double> V,
                                                    const std::vector<std::vector<Point>>& poles,
                                                    const std::vector<std::vector<double>>& weights, bool periodic_u,
                                                    bool periodic_v) {
  BSplineSurface s(pu, pv, std::move(U), std::move(V), poles, weights);
  s.set_periodic(periodic_u, periodic_v);
  return s;
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::from_homogeneous(int pu, int pv, std::vector<double> U, std::vector<double> V,
                                                          int nu, int nv, HPoles h, bool periodic_u, bool periodic_v) {
  BSplineSurface s;
  s.init(pu, pv, std::move(U), std::move(V), nu, nv, std::move(h));
  s.set_periodic(periodic_u, periodic_v);
  return s;
}

template <int Dim>
void BSplineSurface<Dim>::set_periodic(bool periodic_u, bool periodic_v) {
  const int nu = nu_, nv = nv_;
  const double scale = hpoles_.cwiseAbs().maxCoeff();
  if (periodic_u) {
    check_unwrapped_periodic(U_, pu_, nu, [&](Eigen::Index a, Eigen::Index b) {
      return (hpoles_.middleCols(a * nv, nv) - hpoles_.middleCols(b * nv, nv)).cwiseAbs().maxCoeff();
    }, scale, "surface (u)");
    periodic_u_ = true;
  }
  if (periodic_v) {
    check_unwrapped_periodic(V_, pv_, nv, [&](Eigen::Index a, Eigen::Index b) {
      double d = 0.0;
      for (int i = 0; i < nu; ++i) d = std::max(d, (hpoles_.col(i * nv + a) - hpoles_.col(i * nv + b)).cwiseAbs().maxCoeff());
      return d;
    }, scale, "surface (v)");
    periodic_v_ = true;
  }
}

namespace {
double wrap_or_check(double t, double a, double b, bool periodic, const char* name) {
  if (!std::isfinite(t)) throw InvalidGeometry(std::string("surface parameter ") + name + " = " + format_number(t) + " is not finite");
  if (periodic) {
    if (t >= a && t < b) return t;
    double r = std::fmod(t - a, b - a);
    if (r < 0) r += b - a;
    return a + r;
  }
  const double eps = 1e-12 * (b - a);
  if (!(t >= a - eps && t <= b + eps)) {
    const ValueRangeText r = format_value_range(t, a, b);
    throw InvalidGeometry(std::string("surface parameter ") + name + " = " + r.value + " outside [" + r.lo + ", " + r.hi + "]");
  }
  return t < a ? a : (t > b ? b : t);
}
}  // namespace

template <int Dim>
void BSplineSurface<Dim>::check_params(double& u, double& v) const {
  require(nu_ > 0, "evaluation of an empty surface");
  u = wrap_or_check(u, first_u(), last_u(), periodic_u_, "u");
  v = wrap_or_check(v, first_v(), last_v(), periodic_v_, "v");
}

template <int Dim>
typename BSplineSurface<Dim>::Point BSplineSurface<Dim>::point(double u, double v) const {
  check_params(u, v);
  const int su = find_span(U_.data(), nu_ - 1, pu_, u);
  const int sv = find_span(V_.data(), nv_ - 1, pv_, v);
  double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
  basis_funs(su, u, pu_, U_.data(), Nu);
  basis_funs(sv, v, pv_, V_.data(), Nv);
  HPoint s = HPoint::Zero();
  for (int k = 0; k <= pu_; ++k) {
    HPoint t = HPoint::Zero();
    const int row = (su - pu_ + k) * nv_ + sv - pv_;
    for (int l = 0; l <= pv_; ++l) t += Nv[l] * hpoles_.col(row + l);
    s += Nu[k] * t;
  }
  if (!rational_) return s.template head<Dim>();
  return s.template head<Dim>() / s[Dim];
}

template <int Dim>
void BSplineSurface<Dim>::derivatives(double u, double v, int order, Point* out) const {
  check_derivative_order(order, "surface");
  check_params(u, v);
  const int su = find_span(U_.data(), nu_ - 1, pu_, u);
  const int sv = find_span(V_.data(), nv_ - 1, pv_, v);
  const int du = order < pu_ ? order : pu_;
  const int dv = order < pv_ ? order : pv_;
  double Nu[(kMaxDegree + 1) * (kMaxDegree + 1)], Nv[(kMaxDegree + 1) * (kMaxDegree + 1)];
  ders_basis_funs(su, u, pu_, du, U_.data(), Nu);
  ders_basis_funs(sv, v, pv_, dv, V_.data(), Nv);
  const int w = order + 1;
  // Homogeneous mixed derivatives (A3.6 on the (Dim+1)-dimensional surface).
  // Stack storage for the usual orders (<= 5); larger orders are rare and may allocate.
  HPoint stack[36];
  std::vector<HPoint> heap;
  HPoint* hom = stack;
  if (w * w > 36) {
    heap.resize(static_cast<std::size_t>(w * w));
    hom = heap.data();
  }
  for (int i = 0; i < w * w; ++i) hom[i] = HPoint::Zero();
  HPoint temp[kMaxDegree + 1];
  for (int k = 0; k <= du; ++k) {
    for (int s = 0; s <= pv_; ++s) {
      temp[s] = HPoint::Zero();
      for (int r = 0; r <= pu_; ++r)
        temp[s] += Nu[k * (pu_ + 1) + r] * hpoles_.col((su - pu_ + r) * nv_ + sv - pv_ + s);
    }
    const int dd = std::min(order - k, dv);
    for (int l = 0; l <= dd; ++l) {
      HPoint acc = HPoint::Zero();
      for (int s = 0; s <= pv_; ++s) acc += Nv[l * (pv_ + 1) + s] * temp[s];
      hom[static_cast<std::size_t>(k * w + l)] = acc;
    }
  }
  for (int i = 0; i < w * w; ++i) out[i] = Point::Zero();
  if (!rational_) {
    for (int k = 0; k <= order; ++k)
      for (int l = 0; k + l <= order; ++l) out[k * w + l] = hom[static_cast<std::size_t>(k * w + l)].template head<Dim>();
    return;
  }
  // The NURBS Book A4.4.
  const double w00 = hom[0][Dim];
  for (int k = 0; k <= order; ++k) {
    for (int l = 0; k + l <= order; ++l) {
      Point v2 = hom[static_cast<std::size_t>(k * w + l)].template head<Dim>();
      for (int j = 1; j <= l; ++j) v2 -= binomial(l, j) * hom[static_cast<std::size_t>(j)][Dim] * out[k * w + l - j];
      for (int i = 1; i <= k; ++i) {
        v2 -= binomial(k, i) * hom[static_cast<std::size_t>(i * w)][Dim] * out[(k - i) * w + l];
        Point v3 = Point::Zero();
        for (int j = 1; j <= l; ++j)
          v3 += binomial(l, j) * hom[static_cast<std::size_t>(i * w + j)][Dim] * out[(k - i) * w + l - j];
        v2 -= binomial(k, i) * v3;
      }
      out[k * w + l] = v2 / w00;
    }
  }
}

template <int Dim>
typename BSplineSurface<Dim>::Point BSplineSurface<Dim>::normal(double u, double v) const {
  if constexpr (Dim != 3) {
    throw InvalidGeometry("surface normal is defined for 3D surfaces only");
  } else {
    const auto d = derivatives<1>(u, v);
    const Point n = d.S_u().cross(d.S_v());
    const double len = n.norm();
    require(len > 0.0, "surface normal undefined at a degenerate point");
    return n / len;
  }
}

template class BSplineSurface<1>;
template class BSplineSurface<2>;
template class BSplineSurface<3>;

}  // namespace cg
