#include "src/analyze/derivative_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/knots.hpp"
#include "src/core/rational.hpp"

namespace cg {

template <int Dim>
DerivativeBounds bezier_derivative_bounds(const double* hp, int p, double h) {
  constexpr int W = Dim + 1;
  DerivativeBounds b;
  double diff[(kMaxDegree + 1) * W];
  std::copy(hp, hp + (p + 1) * W, diff);
  double wmin = hp[Dim];
  for (int j = 0; j <= p; ++j) {
    wmin = std::min(wmin, hp[j * W + Dim]);
    double n2 = 0;
    for (int d = 0; d < Dim; ++d) n2 += (hp[j * W + d] / hp[j * W + Dim]) * (hp[j * W + d] / hp[j * W + Dim]);
    b.sup[0] = std::max(b.sup[0], std::sqrt(n2));
  }
  double a[4] = {0, 0, 0, 0}, om[4] = {0, 0, 0, 0};  // sup|A^(k)| (Cartesian part), sup|w^(k)|
  double factor = 1;
  for (int k = 1; k <= 3 && k <= p; ++k) {
    for (int j = 0; j <= p - k; ++j)
      for (int d = 0; d < W; ++d) diff[j * W + d] = diff[(j + 1) * W + d] - diff[j * W + d];
    factor *= (p - k + 1) / h;
    for (int j = 0; j <= p - k; ++j) {
      double n2 = 0;
      for (int d = 0; d < Dim; ++d) n2 += diff[j * W + d] * diff[j * W + d];
      a[k] = std::max(a[k], factor * std::sqrt(n2));
      om[k] = std::max(om[k], factor * std::abs(diff[j * W + Dim]));
    }
  }
  for (int k = 1; k <= 3; ++k) {
    double s = a[k];
    for (int i = 1; i <= k; ++i) s += binomial(k, i) * om[i] * b.sup[k - i];
    b.sup[k] = s / wmin;
  }
  return b;
}

template DerivativeBounds bezier_derivative_bounds<1>(const double*, int, double);
template DerivativeBounds bezier_derivative_bounds<2>(const double*, int, double);
template DerivativeBounds bezier_derivative_bounds<3>(const double*, int, double);

}  // namespace cg
