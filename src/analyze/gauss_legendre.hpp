#pragma once
// Gauss-Legendre quadrature rules computed to full precision (Newton on the Legendre recurrence from
// the asymptotic initial guess cos(pi (i + 3/4) / (n + 1/2)); Press et al., Numerical Recipes 3rd ed.,
// Sec. 4.6.1) rather than typed-in tables.

namespace cg {

/// The n-point rule on [-1, 1]: nodes x[0] > x[1] > ... (descending) and weights w; 1 <= n <= 64.
/// Throws InvalidGeometry otherwise.
void gauss_legendre(int n, double* x, double* w);

}  // namespace cg
