#include "src/modify/transform.hpp"

#include "src/core/error.hpp"

namespace cg {

namespace {
template <int Dim>
void check_finite(const Eigen::Matrix<double, Dim, Dim>& A, const Eigen::Matrix<double, Dim, 1>& t) {
  require(A.allFinite() && t.allFinite(), "affine transform has a non-finite entry");
}
}  // namespace

template <int Dim>
BSplineCurve<Dim> transformed(const BSplineCurve<Dim>& c, const Eigen::Matrix<double, Dim, Dim>& A,
                              const Eigen::Matrix<double, Dim, 1>& t) {
  check_finite<Dim>(A, t);
  // Cartesian poles moved, weights kept (the homogeneous form is rebuilt from them).
  std::vector<typename BSplineCurve<Dim>::Point> P = c.poles();
  for (auto& q : P) q = A * q + t;
  std::vector<double> w = c.weights();
  if (!c.is_periodic()) return BSplineCurve<Dim>(c.degree(), c.knots(), P, w);
  const int p = c.degree(), n = c.num_period_poles();
  P.resize(static_cast<std::size_t>(n));
  w.resize(static_cast<std::size_t>(n));
  const std::vector<double> period(c.knots().begin() + p, c.knots().begin() + p + n);
  return BSplineCurve<Dim>::periodic(p, period, c.period(), P, w);
}

template <int Dim>
BSplineSurface<Dim> transformed(const BSplineSurface<Dim>& s, const Eigen::Matrix<double, Dim, Dim>& A,
                                const Eigen::Matrix<double, Dim, 1>& t) {
  check_finite<Dim>(A, t);
  const auto nu = static_cast<std::size_t>(s.num_poles_u()), nv = static_cast<std::size_t>(s.num_poles_v());
  std::vector<std::vector<typename BSplineSurface<Dim>::Point>> P(nu, std::vector<typename BSplineSurface<Dim>::Point>(nv));
  std::vector<std::vector<double>> W(nu, std::vector<double>(nv));
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const int a = static_cast<int>(i), b = static_cast<int>(j);
      P[i][j] = A * s.pole(a, b) + t;
      W[i][j] = s.weight(a, b);
    }
  return BSplineSurface<Dim>::from_poles(s.degree_u(), s.degree_v(), s.knots_u(), s.knots_v(), P, W, s.is_periodic_u(),
                                         s.is_periodic_v());
}

#define CG_MODIFY_TRANSFORM_INSTANTIATE(D)                                                                   \
  template BSplineCurve<D> transformed(const BSplineCurve<D>&, const Eigen::Matrix<double, D, D>&,           \
                                       const Eigen::Matrix<double, D, 1>&);                                  \
  template BSplineSurface<D> transformed(const BSplineSurface<D>&, const Eigen::Matrix<double, D, D>&,       \
                                         const Eigen::Matrix<double, D, 1>&);
CG_MODIFY_TRANSFORM_INSTANTIATE(1)
CG_MODIFY_TRANSFORM_INSTANTIATE(2)
CG_MODIFY_TRANSFORM_INSTANTIATE(3)

}  // namespace cg
