#pragma once
// B-spline and NURBS curves of any degree in 1, 2 or 3 dimensions.
//
// Poles are stored in homogeneous form (w*P, w) — the 3D rational curve is evaluated as a 4D
// polynomial one (as OCCT's BSplCLib does), so evaluation never re-weights the poles. A polynomial
// curve keeps w = 1 and skips the division. The Cartesian poles are kept as well, exactly as given:
// (w*P)/w differs from P in the last bit for ~9% of random values, and conversions to and from OCCT
// (which stores P and w) must be bit-exact.
//
// Periodic curves are stored unwrapped: n + p poles whose last p repeat the first p, and a full knot
// vector continued by the period. Evaluation maps u into the base period first.
#include <Eigen/Core>
#include <vector>

#include "src/core/knots.hpp"

namespace cg {

template <int Dim>
class BSplineCurve {
  static_assert(Dim >= 1 && Dim <= 3, "BSplineCurve is instantiated for dimensions 1, 2, 3");

 public:
  static constexpr int kDim = Dim;
  using Point = Eigen::Matrix<double, Dim, 1>;
  using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
  using HPoles = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;

  /// An empty curve (no poles); only assignable. Any evaluation throws.
  BSplineCurve() = default;

  /// Non-periodic curve from a full knot vector, Cartesian poles and optional weights
  /// (empty = polynomial). Throws InvalidGeometry on inconsistent input.
  BSplineCurve(int degree, std::vector<double> knots, const std::vector<Point>& poles,
               const std::vector<double>& weights = {});

  /// Curve from homogeneous poles (columns (w*P, w)). With periodic = true the data must already be
  /// unwrapped (last p poles repeat the first p, knots continue by the period); this is checked.
  static BSplineCurve from_homogeneous(int degree, std::vector<double> knots, HPoles hpoles,
                                       bool periodic = false);

  /// Periodic curve of period T from one period of flat knots t_0 <= ... <= t_{n-1} < t_0 + T
  /// (the seam knot t_0 listed with its multiplicity) and n poles (not repeated).
  static BSplineCurve periodic(int degree, const std::vector<double>& period_knots, double period,
                               const std::vector<Point>& poles, const std::vector<double>& weights = {});

  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return knots_; }
  int num_poles() const { return static_cast<int>(hpoles_.cols()); }
  const HPoles& homogeneous_poles() const { return hpoles_; }
  Point pole(int i) const { return poles_.col(i); }
  double weight(int i) const { return hpoles_(Dim, i); }
  std::vector<Point> poles() const;
  std::vector<double> weights() const;
  bool is_rational() const { return rational_; }
  bool is_periodic() const { return periodic_; }
  /// Number of distinct poles of a periodic curve (num_poles() - degree()); num_poles() otherwise.
  int num_period_poles() const { return periodic_ ? num_poles() - degree_ : num_poles(); }
  double first_param() const { return knots_[static_cast<std::size_t>(degree_)]; }
  double last_param() const { return knots_[static_cast<std::size_t>(num_poles())]; }
  double period() const { return last_param() - first_param(); }
  /// True when C(first) == C(last) within tol (periodic curves are always closed).
  bool is_closed(double tol = 1e-12) const;

  /// Maps u into the domain: wraps for periodic curves; throws InvalidGeometry when u is outside
  /// [first, last] by more than 1e-12 of the domain length for non-periodic ones.
  double check_param(double u) const;
  /// Knot span containing u (after check_param).
  int span(double u) const;

  Point point(double u) const;
  HPoint homogeneous_point(double u) const;
  /// C^(k)(u), k = 0..order, into out[0..order]; order in [0, kMaxDegree] (InvalidGeometry otherwise).
  void derivatives(double u, int order, Point* out) const;
  std::vector<Point> derivatives(double u, int order) const;
  /// Homogeneous derivatives Cw^(k)(u), k = 0..order (The NURBS Book A3.2 on the 4D curve).
  void homogeneous_derivatives(double u, int order, HPoint* out) const;

 private:
  using Poles = Eigen::Matrix<double, Dim, Eigen::Dynamic>;
  // `poles`: the Cartesian poles if given (else computed from hpoles).
  void init(int degree, std::vector<double> knots, HPoles hpoles, Poles poles = Poles());
  int degree_ = 0;
  std::vector<double> knots_;
  HPoles hpoles_;
  Poles poles_;
  bool rational_ = false;
  bool periodic_ = false;
};

using Curve2 = BSplineCurve<2>;
using Curve3 = BSplineCurve<3>;

extern template class BSplineCurve<1>;
extern template class BSplineCurve<2>;
extern template class BSplineCurve<3>;

}  // namespace cg
