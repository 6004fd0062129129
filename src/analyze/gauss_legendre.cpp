#include "src/analyze/gauss_legendre.hpp"

#include <cmath>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg {

void gauss_legendre(int n, double* x, double* w) {
  require(n >= 1 && n <= 64, "gauss_legendre: 1 <= n <= 64");
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;  // Legendre recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

}  // namespace cg
