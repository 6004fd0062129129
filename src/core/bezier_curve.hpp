#pragma once
// Rational Bézier curves on [0, 1], evaluated by de Casteljau on the homogeneous poles
// (The NURBS Book A1.5, the shared kernels of bezier_ops.hpp). Used for Bézier decomposition and
// subdivision-based algorithms.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

template <int Dim>
class BezierCurve {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
  using HPoles = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;

  BezierCurve() = default;
  explicit BezierCurve(const std::vector<Point>& poles, const std::vector<double>& weights = {});
  explicit BezierCurve(HPoles hpoles);

  int degree() const { return static_cast<int>(hpoles_.cols()) - 1; }
  const HPoles& homogeneous_poles() const { return hpoles_; }
  Point pole(int i) const { return hpoles_.col(i).template head<Dim>() / hpoles_(Dim, i); }
  double weight(int i) const { return hpoles_(Dim, i); }
  bool is_rational() const;

  /// de Casteljau evaluation at t (t outside [0, 1] extrapolates).
  Point point(double t) const;
  /// Derivatives up to `order` (via the equivalent B-spline on {0^(p+1), 1^(p+1)}).
  std::vector<Point> derivatives(double t, int order) const;
  /// The two halves [0, t] and [t, 1], each reparametrised to [0, 1] (de Casteljau subdivision).
  std::pair<BezierCurve, BezierCurve> split(double t) const;
  /// The same curve as a clamped B-spline on [a, b].
  BSplineCurve<Dim> to_bspline(double a = 0.0, double b = 1.0) const;

 private:
  HPoles hpoles_;
};

extern template class BezierCurve<1>;
extern template class BezierCurve<2>;
extern template class BezierCurve<3>;

}  // namespace cg
