#include "src/ortho/edge_angles.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/analyze/gauss_legendre.hpp"
#include "src/core/basis.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::ortho {

template <int Dim>
BSplineSurface<Dim> ContinuationNet<Dim>::surface() const {
  const int m = curve.degree();
  require(thread1.cols() == m + 1, "continuation net: thread 1 needs degree + 1 = " + std::to_string(m + 1) + " points");
  for (int i = 0; i <= m; ++i)
    require(thread1(Dim, i) > 0 && thread1.col(i).allFinite(),
            "continuation net: weight " + std::to_string(i) + " of thread 1 must be positive and finite");
  HPoles h(Dim + 1, 2 * (m + 1));
  for (int i = 0; i <= m; ++i) {
    h.col(2 * i) = curve.homogeneous_poles().col(i);
    h.col(2 * i + 1) = thread1.col(i);
  }
  std::vector<double> U(static_cast<std::size_t>(2 * (m + 1)), 0.0);
  std::fill(U.begin() + (m + 1), U.end(), 1.0);
  return BSplineSurface<Dim>::from_homogeneous(m, 1, U, {0, 0, 1, 1}, m + 1, 2, h);
}

ContinuationNet<2> translated_start_net(const BezierCurve<2>& curve, double distance) {
  const int m = curve.degree();
  const Eigen::Vector2d chord = curve.pole(m) - curve.pole(0);
  require(chord.norm() > 0, "translated_start_net: the curve's end points coincide");
  const Eigen::Vector2d shift = distance * Eigen::Vector2d(-chord.y(), chord.x()).normalized();
  ContinuationNet<2> net{curve, curve.homogeneous_poles()};
  for (int i = 0; i <= m; ++i) net.thread1.col(i).head<2>() += net.thread1(2, i) * shift;
  return net;
}

template <int Dim>
EdgeAngleSampler<Dim>::EdgeAngleSampler(const BezierCurve<Dim>& curve, const PerformanceMap& eta, int panels, int order)
    : m_(curve.degree()) {
  require(panels >= 1 && order >= 1 && order <= 64 && panels * order <= 100000, "edge angle sampler: bad quadrature size");
  std::vector<double> gx(static_cast<std::size_t>(order)), gw(static_cast<std::size_t>(order));
  gauss_legendre(order, gx.data(), gw.data());  // descending nodes: the samples' u ascend within a panel
  std::reverse(gx.begin(), gx.end());
  std::reverse(gw.begin(), gw.end());
  const int n = panels * order;
  B_.resize(m_ + 1, n);
  const BSplineCurve<Dim> c = curve.to_bspline();
  double Bk[kMaxDegree + 1];
  for (int p = 0; p < panels; ++p)
    for (int j = 0; j < order; ++j) {
      const double u = (p + 0.5 * (1.0 + gx[static_cast<std::size_t>(j)])) / panels;
      u_.push_back(u);
      w_.push_back(0.5 * gw[static_cast<std::size_t>(j)] / panels);
      const double e = eta ? eta(u) : 0.0;
      require(std::isfinite(e) && e > -1.0 && e < 1.0, "performance map eta(u) must lie in (-1, 1), got " +
                                                           format_number(e) + " at u = " + format_number(u));
      eta_.push_back(e);
      Point d[2];
      c.derivatives(u, 1, d);
      require(d[1].norm() > 0, "edge angle sampler: the curve has a zero tangent at u = " + format_number(u));
      x_.push_back(d[0]);
      t_.push_back(d[1].normalized());
      all_bernstein(m_, u, Bk);
      for (int i = 0; i <= m_; ++i) B_(i, static_cast<Eigen::Index>(u_.size() - 1)) = Bk[i];
    }
}

template <int Dim>
void EdgeAngleSampler<Dim>::edge_vectors(const HPoles& thread1, Vectors& V) const {
  V.setZero(Dim, size());
  for (int i = 0; i <= m_; ++i) add_point_change(i, thread1.col(i), V);
}

template <int Dim>
void EdgeAngleSampler<Dim>::add_point_change(int i, const HPoint& dq, Vectors& V) const {
  const Point dc = dq.template head<Dim>();
  const double dw = dq[Dim];
  for (int k = 0; k < size(); ++k) V.col(k) += B_(i, k) * (dc - dw * x_[static_cast<std::size_t>(k)]);
}

template <int Dim>
double EdgeAngleSampler<Dim>::cosine(int k, const Vectors& V) const {
  const double n = V.col(k).norm();
  if (!(n > 1e-300)) return 1.0;
  return t_[static_cast<std::size_t>(k)].dot(V.col(k)) / n;
}

template <int Dim>
double EdgeAngleSampler<Dim>::score(const Vectors& V) const {
  double s = 0;
  for (int k = 0; k < size(); ++k) {
    const double d = cosine(k, V) - eta_[static_cast<std::size_t>(k)];
    s += w_[static_cast<std::size_t>(k)] * d * d;
  }
  return s;
}

double angle_deviation_deg(double c, double eta) {
  return std::abs(std::acos(std::clamp(c, -1.0, 1.0)) - std::acos(std::clamp(eta, -1.0, 1.0))) * 180.0 / kPi;
}

template <int Dim>
EdgeAngleStats measure_edge_angles(const BSplineSurface<Dim>& patch, const PerformanceMap& eta, int samples) {
  require(samples >= 2, "measure_edge_angles: need at least 2 samples");
  EdgeAngleStats s;
  s.min_speed_ratio = HUGE_VAL;
  double sum2 = 0;
  for (int k = 0; k < samples; ++k) {
    const double u = patch.first_u() + (patch.last_u() - patch.first_u()) * k / (samples - 1);
    Eigen::Matrix<double, Dim, 1> d[4];
    patch.derivatives(u, patch.first_v(), 1, d);  // d[1] = S_v, d[2] = S_u
    const double nu = d[2].norm(), nv = d[1].norm();
    const double c = nv > 0 ? d[2].dot(d[1]) / (nu * nv) : 1.0;
    const double e = eta ? eta(u) : 0.0;
    const double dev = angle_deviation_deg(c, e);
    s.max_deviation_deg = std::max(s.max_deviation_deg, dev);
    s.max_abs_cos_error = std::max(s.max_abs_cos_error, std::abs(c - e));
    s.min_speed_ratio = std::min(s.min_speed_ratio, nv / nu);
    sum2 += dev * dev;
  }
  s.rms_deviation_deg = std::sqrt(sum2 / samples);
  return s;
}

template struct ContinuationNet<2>;
template struct ContinuationNet<3>;
template class EdgeAngleSampler<2>;
template class EdgeAngleSampler<3>;
template EdgeAngleStats measure_edge_angles<2>(const BSplineSurface<2>&, const PerformanceMap&, int);
template EdgeAngleStats measure_edge_angles<3>(const BSplineSurface<3>&, const PerformanceMap&, int);

}  // namespace cg::ortho
