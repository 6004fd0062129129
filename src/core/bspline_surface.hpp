#pragma once
// Tensor-product B-spline / NURBS surfaces, poles stored homogeneous (w*P, w) and, exactly as given,
// Cartesian (for bit-exact conversion to and from OCCT; see bspline_curve.hpp).
// Pole (i, j), i along u (0..nu-1), j along v (0..nv-1), is column i * nv + j of homogeneous_poles().
// Periodic directions are stored unwrapped, as for curves (see bspline_curve.hpp).
#include <Eigen/Core>
#include <vector>

#include "src/core/knots.hpp"

namespace cg {

/// The mixed partial derivatives S^(k,l) = d^(k+l) S / du^k dv^l, k + l <= Order, of a surface at one
/// point, by name (S_u, S_uv, ...) or by (k, l). Entries with k + l > Order are zero. Flat storage
/// d[k * (Order + 1) + l] is the layout of BSplineSurface::derivatives(u, v, order, out).
template <int Dim, int Order>
struct SurfaceDerivatives {
  static_assert(Order >= 0 && Order <= 3, "named surface derivatives cover orders 0..3");
  using Point = Eigen::Matrix<double, Dim, 1>;
  static constexpr int kOrder = Order;
  Point d[(Order + 1) * (Order + 1)];

  const Point& operator()(int k, int l) const { return d[k * (Order + 1) + l]; }
  const Point& S() const { return d[0]; }
  const Point& S_u() const { return at<1, 0>(); }
  const Point& S_v() const { return at<0, 1>(); }
  const Point& S_uu() const { return at<2, 0>(); }
  const Point& S_uv() const { return at<1, 1>(); }
  const Point& S_vv() const { return at<0, 2>(); }
  const Point& S_uuu() const { return at<3, 0>(); }
  const Point& S_uuv() const { return at<2, 1>(); }
  const Point& S_uvv() const { return at<1, 2>(); }
  const Point& S_vvv() const { return at<0, 3>(); }

 private:
  template <int K, int L>
  const Point& at() const {
    static_assert(K + L <= Order, "derivative above the order evaluated");
    return d[K * (Order + 1) + L];
  }
};

template <int Dim>
class BSplineSurface {
  static_assert(Dim >= 1 && Dim <= 3, "BSplineSurface is instantiated for dimensions 1, 2, 3");

 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
  using HPoles = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;

  BSplineSurface() = default;
  /// poles[i][j]: nu rows of nv poles; weights likewise (empty = polynomial).
  BSplineSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 const std::vector<std::vector<Point>>& poles, const std::vector<std::vector<double>>& weights = {});
  /// As the constructor, with periodic directions: poles, weights and knots must then be unwrapped
  /// (in a periodic direction the last degree rows/columns repeat the first ones).
  static BSplineSurface from_poles(int degree_u, int degree_v, std::vector<double> knots_u,
                                   std::vector<double> knots_v, const std::vector<std::vector<Point>>& poles,
                                   const std::vector<std::vector<double>>& weights, bool periodic_u,
                                   bool periodic_v);
  /// From homogeneous poles (nu * nv columns, index i * nv + j); periodic directions must be unwrapped.
  static BSplineSurface from_homogeneous(int degree_u, int degree_v, std::vector<double> knots_u,
                                         std::vector<double> knots_v, int nu, int nv, HPoles hpoles,
                                         bool periodic_u = false, bool periodic_v = false);

  int degree_u() const { return pu_; }
  int degree_v() const { return pv_; }
  const std::vector<double>& knots_u() const { return U_; }
  const std::vector<double>& knots_v() const { return V_; }
  int num_poles_u() const { return nu_; }
  int num_poles_v() const { return nv_; }
  const HPoles& homogeneous_poles() const { return hpoles_; }
  HPoint homogeneous_pole(int i, int j) const { return hpoles_.col(i * nv_ + j); }
  Point pole(int i, int j) const { return poles_.col(i * nv_ + j); }
  double weight(int i, int j) const { return hpoles_(Dim, i * nv_ + j); }
  bool is_rational() const { return rational_; }
  bool is_periodic_u() const { return periodic_u_; }
  bool is_periodic_v() const { return periodic_v_; }
  double first_u() const { return U_[static_cast<std::size_t>(pu_)]; }
  double last_u() const { return U_[static_cast<std::size_t>(nu_)]; }
  double first_v() const { return V_[static_cast<std::size_t>(pv_)]; }
  double last_v() const { return V_[static_cast<std::size_t>(nv_)]; }

  /// Maps (u, v) into the domain (wrapping periodic directions); throws when outside by more than 1e-12.
  void check_params(double& u, double& v) const;

  Point point(double u, double v) const;
  /// Mixed partials up to Order by name: `const auto d = s.derivatives<2>(u, v); d.S_uv()`.
  template <int Order>
  SurfaceDerivatives<Dim, Order> derivatives(double u, double v) const {
    SurfaceDerivatives<Dim, Order> r;
    derivatives(u, v, Order, r.d);
    return r;
  }
  /// Flat form: S^(k,l), 0 <= k + l <= order, into out[k * (order + 1) + l] ((order+1)^2 entries;
  /// entries with k + l > order are set to zero; so out[2] is S_u at order 1 but S_vv at order 2:
  /// prefer the named form). The NURBS Book A3.6 + A4.4.
  void derivatives(double u, double v, int order, Point* out) const;
  /// Unit normal S_u x S_v / |S_u x S_v| (3D only).
  Point normal(double u, double v) const;

 private:
  using Poles = Eigen::Matrix<double, Dim, Eigen::Dynamic>;
  // `poles`: the Cartesian poles if given (else computed from h).
  void init(int pu, int pv, std::vector<double> U, std::vector<double> V, int nu, int nv, HPoles h,
            Poles poles = Poles());
  void set_periodic(bool periodic_u, bool periodic_v);
  int pu_ = 0, pv_ = 0, nu_ = 0, nv_ = 0;
  std::vector<double> U_, V_;
  HPoles hpoles_;
  Poles poles_;
  bool rational_ = false, periodic_u_ = false, periodic_v_ = false;
};

using Surface3 = BSplineSurface<3>;

extern template class BSplineSurface<1>;
extern template class BSplineSurface<2>;
extern template class BSplineSurface<3>;

}  // namespace cg
