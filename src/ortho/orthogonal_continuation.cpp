#include "src/ortho/orthogonal_continuation.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::ortho {

namespace {

// The plane rotation D of eq. (13) on a Cartesian vector: (a, b) -> (-b, a) (left normal).
Eigen::Vector2d rotate_left(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }

// N = y_c' Y0 - y_c Y0' (2 rows, degree 2m - 1 as written): x_u = N / Y0^2 (eq. 12).
BernsteinPoly derivative_numerator(const BernsteinPoly& y) {
  const BernsteinPoly yc = y.topRows(2), w = y.bottomRows(1);
  return bernstein_product(w, bernstein_derivative(yc)) - bernstein_product(bernstein_derivative(w), yc);
}

// Polynomial with power-basis coefficients c (ascending) at t (complex coefficients).
std::complex<double> horner(const std::vector<std::complex<double>>& c, double t) {
  std::complex<double> s = 0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) s = s * t + *it;
  return s;
}

// Zeros of the power-basis polynomial c_0 + ... + c_d t^d (c_d != 0) by the companion matrix.
std::vector<std::complex<double>> polynomial_zeros(const Eigen::VectorXd& c, int d) {
  if (d <= 0) return {};
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(d, d);
  for (int i = 1; i < d; ++i) C(i, i - 1) = 1;
  for (int i = 0; i < d; ++i) C(i, d - 1) = -c[i] / c[d];
  Eigen::EigenSolver<Eigen::MatrixXd> es(C, false);
  std::vector<std::complex<double>> z;
  for (int i = 0; i < d; ++i) z.push_back(es.eigenvalues()[i]);
  return z;
}

// Groups zeros closer than tol * max(1, |z|) (single linkage); returns cluster means and sizes.
void cluster_zeros(const std::vector<std::complex<double>>& z, double tol, std::vector<std::complex<double>>& means,
                   std::vector<int>& sizes) {
  const int n = static_cast<int>(z.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
    return i;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const auto a = z[static_cast<std::size_t>(i)], b = z[static_cast<std::size_t>(j)];
      if (std::abs(a - b) <= tol * std::max({1.0, std::abs(a), std::abs(b)}))
        parent[static_cast<std::size_t>(root(i))] = root(j);
    }
  means.clear();
  sizes.clear();
  std::vector<int> index(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    const int r = root(i);
    if (index[static_cast<std::size_t>(r)] < 0) {
      index[static_cast<std::size_t>(r)] = static_cast<int>(means.size());
      means.emplace_back(0.0);
      sizes.push_back(0);
    }
    const int k = index[static_cast<std::size_t>(r)];
    means[static_cast<std::size_t>(k)] += z[static_cast<std::size_t>(i)];
    ++sizes[static_cast<std::size_t>(k)];
  }
  for (std::size_t k = 0; k < means.size(); ++k) means[k] /= sizes[k];
}

}  // namespace

EdgeDirectionPoly squared_edge_direction(const BezierCurve<2>& curve) {
  const BernsteinPoly y = homogeneous_poly(curve);
  const int m = curve.degree();
  require(m >= 1, "orthogonal continuation: the curve needs degree >= 1");
  EdgeDirectionPoly out;
  out.kind = EdgeDirection::Squared;
  out.predicted_degree = std::max(0, 2 * m - 2);
  // x_u Y0^2 = N is written with degree 2m - 1; its leading coefficient vanishes (Sec. 3, after eq. 13),
  // so the exact reduction to 2m - 2 has a rounding-level residual.
  const BernsteinPoly N = bernstein_reduce(derivative_numerator(y), out.predicted_degree, &out.identity_residual);
  out.zeta = BernsteinPoly::Zero(3, N.cols());
  out.zeta.row(0) = -N.row(1);
  out.zeta.row(1) = N.row(0);
  return out;
}

EdgeDirectionPoly weight_reduced_edge_direction(const BezierCurve<2>& curve) {
  const BernsteinPoly y = homogeneous_poly(curve);
  const int m = curve.degree();
  const EdgeDirectionPoly squared = squared_edge_direction(curve);
  const Eigen::VectorXd c = bernstein_to_power(y.bottomRows(1));
  const double cmax = c.cwiseAbs().maxCoeff();
  int d = m;
  while (d > 0 && std::abs(c[d]) <= 1e-12 * cmax) --d;
  const std::vector<std::complex<double>> zeros = polynomial_zeros(c, d);

  // z~ = z^ prod(u - u_sigma) / Y0 (eq. 16): try merging nearby eigenvalues (a nu-fold zero splits into
  // a ring of radius ~eps^(1/nu)), largest tolerance first; accept the first merge for which z~ is a
  // polynomial of Lemma 4.2's degree. Tolerance 0 (all zeros simple) always is: then z~ = z^ / c_d.
  for (double tol : {3e-2, 1e-3, 3e-5, 1e-6, 0.0}) {
    EdgeDirectionPoly out;
    out.kind = EdgeDirection::WeightReduced;
    out.weight_zeros.weight_degree = d;
    cluster_zeros(zeros, tol, out.weight_zeros.zeros, out.weight_zeros.multiplicities);
    const int s = out.weight_zeros.distinct();
    out.predicted_degree = std::max(0, d == m ? m + s - 2 : m + s - 1);
    // prod (u - u_sigma) in the power basis (complex; real up to rounding for conjugate pairs).
    std::vector<std::complex<double>> S{1.0};
    for (const auto& u0 : out.weight_zeros.zeros) {
      std::vector<std::complex<double>> next(S.size() + 1, 0.0);
      for (std::size_t k = 0; k < S.size(); ++k) {
        next[k + 1] += S[k];
        next[k] -= u0 * S[k];
      }
      S = next;
    }
    auto f = [&](double t) {
      const Eigen::VectorXd zh = bernstein_value(squared.zeta, t);
      const double w = bernstein_value(y.bottomRows(1), t)[0];
      return Eigen::Vector3d(zh * (horner(S, t).real() / w));
    };
    out.zeta = bernstein_interpolate(out.predicted_degree, 3, f);
    out.zeta.row(2).setZero();
    // Check the identity on a fine sample (the interpolant matches f only at its nodes otherwise).
    double err = 0, scale = 1e-300;
    for (int k = 0; k <= 64; ++k) {
      const double t = k / 64.0;
      const Eigen::Vector3d fv = f(t);
      err = std::max(err, (bernstein_value(out.zeta, t) - fv).cwiseAbs().maxCoeff());
      scale = std::max(scale, fv.cwiseAbs().maxCoeff());
    }
    out.identity_residual = err / scale;
    if (out.identity_residual <= 1e-9 || tol == 0.0) return out;
  }
  throw AlgorithmFailure("weight_reduced_edge_direction: unreachable");
}

OrthogonalContinuation continue_orthogonally(const BezierCurve<2>& curve, const ContinuationFactors& factors,
                                             EdgeDirection kind) {
  return continue_orthogonally(
      curve, kind == EdgeDirection::Squared ? squared_edge_direction(curve) : weight_reduced_edge_direction(curve),
      factors);
}

OrthogonalContinuation continue_orthogonally(const BezierCurve<2>& curve, const EdgeDirectionPoly& direction,
                                             const ContinuationFactors& factors) {
  require(factors.L.rows() == 1 && factors.L.cols() >= 1 && factors.Q.rows() == 1 && factors.Q.cols() >= 1,
          "orthogonal continuation: L and Q must be scalar Bernstein polynomials");
  require(factors.L.allFinite() && factors.Q.allFinite(), "orthogonal continuation: L and Q must be finite");
  const BernsteinPoly y = homogeneous_poly(curve);
  const int m = curve.degree();
  const int l = bernstein_degree(factors.L), q = bernstein_degree(factors.Q);
  const int dz = bernstein_degree(direction.zeta);
  // Lemma 3.1: the patch degree is that of the higher of y and z = L zeta - Q y (eq. 14).
  const int M = std::max({m, dz + l, m + q});
  require(M <= kMaxDegree, "orthogonal continuation: patch degree " + std::to_string(M) + " exceeds " +
                               std::to_string(kMaxDegree) + " (lower the degrees of L and Q)");
  const BernsteinPoly z =
      bernstein_elevate(bernstein_product(factors.L, direction.zeta), M) - bernstein_elevate(bernstein_product(factors.Q, y), M);
  const BernsteinPoly row0 = bernstein_elevate(y, M);
  const BernsteinPoly row1 = row0 + z;  // Y(u, 1) = Y(u, 0) + Y_v(u, 0) for a patch linear in v
  for (int i = 0; i <= M; ++i)
    require(row1(2, i) > 0 && std::isfinite(row1(2, i)),
            "orthogonal continuation: weight " + std::to_string(i) + " of thread 1 is " + format_number(row1(2, i)) +
                " (must be > 0: keep the Bernstein coefficients of Q below 1)");
  Eigen::Matrix<double, 3, Eigen::Dynamic> h(3, 2 * (M + 1));
  for (int i = 0; i <= M; ++i) {
    h.col(2 * i) = row0.col(i);
    h.col(2 * i + 1) = row1.col(i);
  }
  std::vector<double> U(static_cast<std::size_t>(2 * (M + 1)), 0.0);
  std::fill(U.begin() + (M + 1), U.end(), 1.0);
  OrthogonalContinuation out{BSplineSurface<2>::from_homogeneous(M, 1, U, {0, 0, 1, 1}, M + 1, 2, h), M, direction,
                             factors, curve};
  return out;
}

Eigen::Vector2d OrthogonalContinuation::edge_normal(double u) const {
  Eigen::Vector3d Y, dY;
  bernstein_value_d1<3>(curve.homogeneous_poles(), u, Y, dY);
  const Eigen::Vector2d xu = (dY.head<2>() * Y[2] - Y.head<2>() * dY[2]) / (Y[2] * Y[2]);
  return rotate_left(xu).normalized();
}

double OrthogonalContinuation::edge_speed(double u) const {
  // x_v(u, 0) = L zeta_c / Y0 (see the header).
  Eigen::Vector3d Y, dY, Z, dZ;
  bernstein_value_d1<3>(curve.homogeneous_poles(), u, Y, dY);
  bernstein_value_d1<3>(direction.zeta, u, Z, dZ);
  Eigen::Matrix<double, 1, 1> L, dL;
  bernstein_value_d1<1>(factors.L, u, L, dL);
  const Eigen::Vector2d xu = (dY.head<2>() * Y[2] - Y.head<2>() * dY[2]) / (Y[2] * Y[2]);
  return L[0] * Z.head<2>().dot(rotate_left(xu).normalized()) / Y[2];
}

double OrthogonalContinuation::thread_distance(double u) const {
  Eigen::Matrix<double, 1, 1> Q, dQ;
  bernstein_value_d1<1>(factors.Q, u, Q, dQ);
  return edge_speed(u) / (1.0 - Q[0]);
}

double OrthogonalContinuation::v_at_distance(double u, double s) const {
  // From Y(u, v) = y + v z: x(u, v) = x + n v g / (1 - v Q), solved for v.
  Eigen::Matrix<double, 1, 1> Q, dQ;
  bernstein_value_d1<1>(factors.Q, u, Q, dQ);
  return s / (edge_speed(u) + s * Q[0]);
}

}  // namespace cg::ortho
