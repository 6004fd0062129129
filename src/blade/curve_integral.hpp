#pragma once
// Cumulative integrals along a streamline (x, r): meridional length m (integrand |C'|) and the
// conformal coordinate m' (integrand |C'| / r). Internal to the blade model. Section arc lengths use
// src/analyze/arc_length.hpp; this table exists because a Streamline is a copyable value (analyze's
// ArcLength keeps a pointer to its curve) and m' needs the 1/r weight.
//
// The domain [a, b] is cut at the knots (the integrand is smooth inside a span) and every span into
// kCellsPerSpan cells; each cell gets 8-point Gauss-Legendre (exact for polynomials of degree 15, so the
// error on a smooth cell is far below 1e-12 relative). Values inside a cell are integrated on demand with
// the same rule; the inverse starts from the cubic Hermite interpolant of u(value) on the cell (slopes
// 1 / integrand at the cell ends) and polishes it by Newton (derivative = integrand) safeguarded by the
// cell bracket; the Hermite guess is usually right to rounding, so one cell integral confirms it.
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg::blade::detail {

/// 8-point Gauss-Legendre rule on [-1, 1] (exact for polynomials of degree <= 15).
extern const double kGaussLegendre8Nodes[8];
extern const double kGaussLegendre8Weights[8];

enum class Integrand { ArcLength, ArcLengthOverRadius };

class CurveIntegral {
 public:
  CurveIntegral() = default;
  /// a < b inside the domain of a non-periodic curve.
  CurveIntegral(const BSplineCurve<2>& curve, double a, double b, Integrand f);

  double first() const { return breaks_.front(); }
  double last() const { return breaks_.back(); }
  double total() const { return cumulative_.back(); }
  /// Integral from first() to u (u clamped into [first(), last()]).
  double at(const BSplineCurve<2>& curve, double u) const;
  /// u in [first(), last()] with at(u) = value (value clamped into [0, total()]).
  double inverse(const BSplineCurve<2>& curve, double value) const;
  /// The integrand at u.
  double integrand(const BSplineCurve<2>& curve, double u) const;

 private:
  double integrate_cell(const BSplineCurve<2>& curve, double lo, double hi) const;
  Integrand f_ = Integrand::ArcLength;
  std::vector<double> breaks_;
  std::vector<double> cumulative_;
  std::vector<double> rate_;  // integrand at every break: the inverse starts from the cubic Hermite guess
};

}  // namespace cg::blade::detail
