#include "src/core/bezier_curve.hpp"

#include <cmath>
#include <string>

#include "src/core/bezier_ops.hpp"
#include "src/core/error.hpp"

namespace cg {

template <int Dim>
BezierCurve<Dim>::BezierCurve(HPoles hpoles) : hpoles_(std::move(hpoles)) {
  require(hpoles_.cols() >= 2 && hpoles_.cols() <= kMaxDegree + 1,
          "a Bezier curve needs 2 to " + std::to_string(kMaxDegree + 1) + " poles, got " +
              std::to_string(hpoles_.cols()));
  for (Eigen::Index i = 0; i < hpoles_.cols(); ++i)
    require(std::isfinite(hpoles_(Dim, i)) && hpoles_(Dim, i) > 0.0,
            "Bezier weight " + std::to_string(i) + " must be positive");
}

template <int Dim>
BezierCurve<Dim>::BezierCurve(const std::vector<Point>& poles, const std::vector<double>& weights) {
  require(weights.empty() || weights.size() == poles.size(), "Bezier weight count must equal pole count");
  HPoles h(Dim + 1, static_cast<Eigen::Index>(poles.size()));
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    h.col(static_cast<Eigen::Index>(i)) << w * poles[i], w;
  }
  *this = BezierCurve(std::move(h));
}

template <int Dim>
bool BezierCurve<Dim>::is_rational() const {
  return (hpoles_.row(Dim).array() != 1.0).any();
}

template <int Dim>
typename BezierCurve<Dim>::Point BezierCurve<Dim>::point(double t) const {
  HPoint Q;
  de_casteljau_point(degree(), Dim + 1, hpoles_.data(), t, Q.data());
  return Q.template head<Dim>() / Q[Dim];
}

template <int Dim>
std::vector<typename BezierCurve<Dim>::Point> BezierCurve<Dim>::derivatives(double t, int order) const {
  return to_bspline().derivatives(t, order);
}

template <int Dim>
std::pair<BezierCurve<Dim>, BezierCurve<Dim>> BezierCurve<Dim>::split(double t) const {
  const int p = degree();
  HPoles left(Dim + 1, p + 1), right(Dim + 1, p + 1);
  split_bezier(p, Dim + 1, hpoles_.data(), t, left.data(), right.data());
  return {BezierCurve(std::move(left)), BezierCurve(std::move(right))};
}

template <int Dim>
BSplineCurve<Dim> BezierCurve<Dim>::to_bspline(double a, double b) const {
  const int p = degree();
  std::vector<double> U(static_cast<std::size_t>(2 * p + 2), a);
  for (int i = p + 1; i < 2 * p + 2; ++i) U[static_cast<std::size_t>(i)] = b;
  return BSplineCurve<Dim>::from_homogeneous(p, std::move(U), hpoles_);
}

template class BezierCurve<1>;
template class BezierCurve<2>;
template class BezierCurve<3>;

}  // namespace cg
