#pragma once
// The Newton iterations of the kernel: one implementation per problem shape, shared by every
// algorithm (as OCCT's math_FunctionRoot / math_FunctionSetRoot / math_NewtonMinimum serve all of
// its geometry). Callers supply the function and its exact derivatives; the iterations own the
// safeguards, the domain handling and the stopping rules.
//
//  - solve_bracketed: a scalar root inside a sign bracket. Newton steps that leave the (shrinking)
//    bracket, or whose derivative has the wrong sign, are replaced by bisection, so the iteration
//    always converges (Press et al., Numerical Recipes 9.4, "rtsafe"). Curve projection, line-curve
//    roots, arc-length inversion.
//  - solve_system: F(x) = 0 for N = 2, 3 unknowns with the Jacobian (plain Newton, The NURBS Book 6.1
//    eq. 6.4 in its 2D form). Curve crossings and tangencies, fillet centres, ray-surface hits.
//  - minimize: a local minimum of f(x) with the exact gradient and Hessian, the Hessian shifted to
//    positive definite where it is not (Levenberg-Marquardt) and steps halved until f does not grow
//    (Dennis & Schnabel, Numerical Methods for Unconstrained Optimization, 6.3 and 6.5). Point
//    projection polish on curves and surfaces (The NURBS Book 6.1 eq. 6.6), ray-curve closest approach.
//
// Every iteration works on a Domain: a coordinate is clamped to [lo, hi], or wrapped into it when it
// is periodic (a surface's periodic direction: a step across the seam continues on the other side).
// No heap allocation; fixed-size Eigen types only.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cg::newton {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int N>
using Mat = Eigen::Matrix<double, N, N>;

/// Box of an iteration: coordinate i in [lo[i], hi[i]] (infinite bounds allowed), clamped, or wrapped
/// into [lo[i], hi[i]) when periodic[i] (then both bounds must be finite).
template <int N>
struct Domain {
  Vec<N> lo = Vec<N>::Constant(-std::numeric_limits<double>::infinity());
  Vec<N> hi = Vec<N>::Constant(std::numeric_limits<double>::infinity());
  std::array<bool, N> periodic{};

  /// x + dx moved into the domain; `taken` receives the step actually made (dx itself along a
  /// periodic coordinate, where wrapping only changes the representative).
  Vec<N> advance(const Vec<N>& x, const Vec<N>& dx, Vec<N>& taken) const {
    Vec<N> y;
    for (int i = 0; i < N; ++i) {
      const double t = x[i] + dx[i];
      if (periodic[static_cast<std::size_t>(i)]) {
        y[i] = wrap(t, lo[i], hi[i]);
        taken[i] = dx[i];
      } else {
        y[i] = t < lo[i] ? lo[i] : (t > hi[i] ? hi[i] : t);
        taken[i] = y[i] - x[i];
      }
    }
    return y;
  }
  static double wrap(double t, double a, double b) {
    if (t >= a && t < b) return t;
    double r = std::fmod(t - a, b - a);
    if (r < 0) r += b - a;
    const double y = a + r;
    return y < b ? y : a;  // a + r may round up onto b
  }
};

// ---- scalar root in a bracket ---------------------------------------------------------------------

/// Root of f in [lo, hi] where f(lo) has the sign sign_lo (+1 or -1) and f(hi) the opposite one,
/// from x (inside). f(x, df) returns f(x) and writes f'(x). Stops when |f| <= ftol, f = 0, the step
/// or the bracket is below xtol, or after max_iterations; returns the last iterate.
template <class F>
double solve_bracketed(F&& f, double lo, double hi, int sign_lo, double x, double xtol, double ftol = 0.0,
                       int max_iterations = 100) {
  for (int it = 0; it < max_iterations; ++it) {
    double df = 0;
    const double fx = f(x, df);
    if (fx == 0 || std::abs(fx) <= ftol) break;
    ((fx < 0) == (sign_lo < 0) ? lo : hi) = x;
    // f runs from sign_lo to -sign_lo: a derivative of the other sign points out of the bracket.
    double next = x - fx / df;
    if (!(df * sign_lo < 0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - x) <= xtol || hi - lo <= xtol;
    x = next;
    if (done) break;
  }
  return x;
}

/// Root of f in [lo, hi] without derivatives, f_lo = f(lo) and f_hi = f(hi) of opposite signs: the
/// Illinois variant of regula falsi (Dowell & Jarratt, BIT 11 (1971)): the secant of the bracket ends,
/// with the value at an end halved when that end is kept twice in a row, so both ends move and the
/// bracket shrinks superlinearly (order ~1.44) to the root. Stops when f = 0, |f| <= ftol (returns that
/// point) or the bracket is at most xtol wide (returns its middle). f(x) returns f(x).
template <class F>
double solve_bracketed_secant(F&& f, double lo, double hi, double f_lo, double f_hi, double xtol,
                              double ftol = 0.0, int max_iterations = 200) {
  if (f_lo == 0) return lo;
  if (f_hi == 0) return hi;
  double a = lo, b = hi, fa = f_lo, fb = f_hi;
  int kept = 0;  // +1: a was kept by the last step, -1: b was
  for (int it = 0; it < max_iterations && std::abs(b - a) > xtol; ++it) {
    double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > std::min(a, b) && c < std::max(a, b))) c = 0.5 * (a + b);
    const double fc = f(c);
    if (fc == 0 || std::abs(fc) <= ftol) return c;
    if ((fc < 0) == (fb < 0)) {  // the root lies between a and c
      b = c;
      fb = fc;
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else {
      a = c;
      fa = fc;
      if (kept == -1) fb *= 0.5;
      kept = -1;
    }
  }
  return 0.5 * (a + b);
}

// ---- linear algebra helpers -----------------------------------------------------------------------

/// Solves J dx = r; false when J is singular to rounding (|det J| <= 1e-15 times the product of its
/// column norms, Hadamard's bound: the columns are parallel to within 1e-15 rad) or dx is not finite.
template <int N>
bool solve_linear(const Mat<N>& J, const Vec<N>& r, Vec<N>& dx) {
  const double det = J.determinant();
  double hadamard = 1;
  for (int i = 0; i < N; ++i) hadamard *= J.col(i).norm();
  if (!(std::abs(det) > 1e-15 * hadamard) || !(std::abs(det) > 1e-300)) return false;
  if constexpr (N == 1) {
    dx[0] = r[0] / J(0, 0);
  } else if constexpr (N == 2) {
    dx[0] = (r[0] * J(1, 1) - J(0, 1) * r[1]) / det;
    dx[1] = (J(0, 0) * r[1] - J(1, 0) * r[0]) / det;
  } else {
    dx = J.partialPivLu().solve(r);
  }
  return dx.allFinite();
}

/// Solves H dx = r for a symmetric positive definite H (no conditioning test: a shifted Hessian may
/// be nearly singular on purpose); false when dx is not finite.
template <int N>
bool solve_spd(const Mat<N>& H, const Vec<N>& r, Vec<N>& dx) {
  if constexpr (N == 1) {
    dx[0] = r[0] / H(0, 0);
  } else if constexpr (N == 2) {
    const double det = H(0, 0) * H(1, 1) - H(0, 1) * H(1, 0);
    dx[0] = (H(1, 1) * r[0] - H(0, 1) * r[1]) / det;
    dx[1] = (H(0, 0) * r[1] - H(1, 0) * r[0]) / det;
  } else {
    dx = H.llt().solve(r);
  }
  return dx.allFinite();
}

/// Smallest eigenvalue of a symmetric N x N matrix (N = 1, 2 in closed form).
template <int N>
double smallest_eigenvalue(const Mat<N>& H) {
  if constexpr (N == 1) {
    return H(0, 0);
  } else if constexpr (N == 2) {
    const double tr = H.trace(), det = H(0, 0) * H(1, 1) - H(0, 1) * H(1, 0);
    return 0.5 * tr - std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
  } else {
    return Eigen::SelfAdjointEigenSolver<Mat<N>>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
  }
}

// ---- systems F(x) = 0 ----------------------------------------------------------------------------

struct SystemOptions {
  int max_iterations = 40;
  /// Settled when max_i |dx_i| / scale_i <= step_tol (a few ulps of the domain) ...
  double step_tol = 1e-15;
  /// ... or when the relative step failed to halve this many times in a row (rounding reached).
  int max_stalls = 4;
  /// Settled as soon as |F| <= residual_tol (0: not used).
  double residual_tol = 0.0;
};

template <int N>
struct SystemResult {
  Vec<N> x;
  bool settled = false;   ///< the iteration converged by one of the rules of SystemOptions
  bool singular = false;  ///< stopped at a singular Jacobian (x is the last iterate)
  int iterations = 0;
};

/// Newton on F(x) = 0 from x. f(x, F, J) writes F(x) and its Jacobian. scale: per-coordinate lengths
/// for the relative step (the domain widths for bounded coordinates).
template <int N, class F>
SystemResult<N> solve_system(F&& f, Vec<N> x, const Domain<N>& dom, const Vec<N>& scale,
                             const SystemOptions& opt = SystemOptions()) {
  SystemResult<N> res;
  double prev = std::numeric_limits<double>::infinity();
  int stalls = 0;
  Vec<N> Fx, dx, taken;
  Mat<N> J;
  for (int it = 0; it < opt.max_iterations; ++it) {
    res.iterations = it + 1;
    f(x, Fx, J);
    if (opt.residual_tol > 0 && Fx.norm() <= opt.residual_tol) {
      res.settled = true;
      break;
    }
    if (!solve_linear<N>(J, -Fx, dx)) {
      res.singular = true;
      break;
    }
    x = dom.advance(x, dx, taken);
    const double r = (taken.array().abs() / scale.array()).maxCoeff();
    if (r <= opt.step_tol) {
      res.settled = true;
      break;
    }
    stalls = r >= 0.5 * prev ? stalls + 1 : 0;
    prev = r;
    if (opt.max_stalls > 0 && stalls >= opt.max_stalls) {
      res.settled = true;
      break;
    }
  }
  res.x = x;
  return res;
}

// ---- local minimum of f ---------------------------------------------------------------------------

template <int N>
struct MinimizeOptions {
  int max_iterations = 40;
  int max_halvings = 40;
  /// Stops when no coordinate moves by more than xtol[i] in an accepted step.
  Vec<N> xtol = Vec<N>::Constant(1e-15);
  /// Where the Hessian's smallest eigenvalue is below shift_floor * |trace|, it is shifted up to that
  /// floor plus shift_extra * |trace| (Levenberg-Marquardt; a floor at the rounding level keeps full
  /// Newton steps at a degenerate minimum).
  double shift_floor = 1e-12;
  double shift_extra = 0.0;
  /// Rounding level of f: a step is accepted when f grows by at most this much. Near a minimum f is
  /// flat to second order, so its computed change drowns in rounding long before x is exact; without
  /// this slack the descent test stops x at ~sqrt(rounding) (e.g. 1e-8 for a distance of order 1).
  double value_noise = 0.0;
};

template <int N>
struct MinimizeResult {
  Vec<N> x;
  double value = 0;  ///< f(x)
  int iterations = 0;
};

/// Damped Newton descent from x: f(x, g, H) returns f(x) and, when g and H are non-null, writes the
/// gradient and the Hessian. f never increases along the iterates; the result is a critical point of
/// f on the domain when the iteration stops by the step rule (or a point on a clamped bound).
template <int N, class F>
MinimizeResult<N> minimize(F&& f, Vec<N> x, const Domain<N>& dom, const MinimizeOptions<N>& opt = MinimizeOptions<N>()) {
  MinimizeResult<N> res;
  Vec<N> g, step, taken;
  Mat<N> H;
  double fx = f(x, nullptr, nullptr);
  for (int it = 0; it < opt.max_iterations; ++it) {
    res.iterations = it + 1;
    f(x, &g, &H);
    const double tr = std::abs(H.trace());
    const double lmin = smallest_eigenvalue<N>(H);
    const double floor = opt.shift_floor * std::max(tr, 1e-300);
    if (lmin < floor) H += Mat<N>::Identity() * (floor - lmin + opt.shift_extra * tr);
    if (!solve_spd<N>(H, -g, step)) break;
    bool moved = false;
    for (int half = 0; half < opt.max_halvings; ++half) {
      const Vec<N> xn = dom.advance(x, step, taken);
      const double fn = f(xn, nullptr, nullptr);
      if (fn <= fx + opt.value_noise) {
        moved = (taken.array().abs() > opt.xtol.array()).any();
        x = xn;
        fx = fn;
        break;
      }
      step *= 0.5;
    }
    if (!moved) break;
  }
  res.x = x;
  res.value = fx;
  return res;
}

}  // namespace cg::newton
