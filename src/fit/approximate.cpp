#include "src/fit/approximate.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "src/core/basis.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

namespace {

void check_degree(int p) {
  require(p >= 1 && p <= kMaxDegree,
          "degree " + std::to_string(p) + " out of range [1, " + std::to_string(kMaxDegree) + "]");
}

// Schoenberg-Whitney for the interior poles 1 .. n-1 of a clamped fit against the interior parameters
// params[1 .. m-1]: each pole needs its own parameter strictly inside its basis support, in increasing
// order. Supports are ordered intervals (U_i, U_{i+p+1}), so assigning greedily the first free
// parameter is optimal. Equivalent to full column rank of the least-squares matrix.
bool schoenberg_whitney(const std::vector<double>& params, int p, const std::vector<double>& U) {
  const int n = static_cast<int>(U.size()) - p - 2;  // last pole index
  const std::size_t last = params.size() - 1;        // params[last] is the fixed end point
  std::size_t j = 1;
  for (int i = 1; i <= n - 1; ++i) {
    const double lo = U[static_cast<std::size_t>(i)], hi = U[static_cast<std::size_t>(i + p + 1)];
    while (j < last && params[j] <= lo) ++j;
    if (j >= last || params[j] >= hi) return false;
    ++j;
  }
  return true;
}

template <int Dim>
double max_error(const BSplineCurve<Dim>& c, const PointList<Dim>& points, const std::vector<double>& params,
                 std::vector<double>& err) {
  CurveEvaluator<Dim> ev(c);
  err.resize(points.size());
  double e = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    err[k] = (ev.point(params[k]) - points[k]).norm();
    e = std::max(e, err[k]);
  }
  return e;
}

// Candidate knots: for every span [U_s, U_s+1) (s = span index into `breaks`) whose data error exceeds
// tol and which holds at least 2 data points, the midpoint between its two middle data parameters, so
// both halves keep half of the span's data. Worst spans first. params must be sorted.
std::vector<double> refinement_candidates(const std::vector<double>& breaks, const std::vector<double>& params,
                                          const std::vector<double>& err, double tol) {
  const std::size_t spans = breaks.size() - 1;
  std::vector<double> worst(spans, 0.0);
  std::vector<std::size_t> first(spans, params.size()), count(spans, 0);
  for (std::size_t k = 0; k < params.size(); ++k) {
    std::size_t s =
        static_cast<std::size_t>(std::upper_bound(breaks.begin(), breaks.end(), params[k]) - breaks.begin());
    s = std::min(std::max<std::size_t>(s, 1), spans) - 1;
    worst[s] = std::max(worst[s], err[k]);
    if (count[s]++ == 0) first[s] = k;
  }
  std::vector<std::size_t> order;
  for (std::size_t s = 0; s < spans; ++s)
    if (worst[s] > tol && count[s] >= 2) order.push_back(s);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return worst[a] > worst[b]; });
  std::vector<double> cand;
  for (std::size_t s : order) {
    const std::size_t mid = first[s] + count[s] / 2;
    const double k = 0.5 * (params[mid - 1] + params[mid]);
    if (k > breaks[s] && k < breaks[s + 1]) cand.push_back(k);
  }
  return cand;
}

double sum_of_squares(const std::vector<double>& e) {
  double s = 0;
  for (double x : e) s += x * x;
  return s;
}

std::vector<double> distinct_values(const std::vector<double>& U, double a, double b) {
  std::vector<double> v{a};
  for (double k : U)
    if (k > v.back() && k < b) v.push_back(k);
  v.push_back(b);
  return v;
}

void check_tolerance(double tol, int npoints, int p) {
  require(std::isfinite(tol) && tol > 0, "approximation tolerance must be positive, got " + format_number(tol));
  require(npoints >= p + 1, "approximation of degree " + std::to_string(p) + " needs at least " +
                                std::to_string(p + 1) + " points, got " + std::to_string(npoints));
}

// Least squares N X = R. By the normal equations (sparse LDLT of N^T N, banded for a B-spline fit)
// where their pivots stay within 1e-6 of each other, so that squaring the condition number costs no
// digit that matters (the examples' fits: pivots within 0.065 of each other, poles agreeing with QR's
// to 2.3e-14 of the largest); 5-10x cheaper than QR (the inner wall's section fits were a fifth of the
// rotor's plan). Otherwise by sparse QR of N itself (Householder, COLAMD ordering). Returns false when
// N is numerically rank deficient or so badly conditioned (|R_ii| spread beyond 1e10) that the poles
// would be meaningless: that happens with data barely inside some basis supports although
// Schoenberg-Whitney holds.
bool solve_least_squares(Eigen::SparseMatrix<double>& N, const Eigen::MatrixXd& R, Eigen::MatrixXd& X) {
  N.makeCompressed();
  {
    const Eigen::SparseMatrix<double> M = N.transpose() * N;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(M);
    if (ldlt.info() == Eigen::Success) {
      const Eigen::VectorXd D = ldlt.vectorD();
      if (D.minCoeff() > 1e-6 * D.maxCoeff()) {
        X = ldlt.solve(N.transpose() * R);
        if (ldlt.info() == Eigen::Success && X.allFinite()) return true;
      }
    }
  }
  Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
  qr.compute(N);
  if (qr.info() != Eigen::Success || qr.rank() < N.cols()) return false;
  const Eigen::VectorXd d = Eigen::VectorXd(qr.matrixR().diagonal()).cwiseAbs();
  if (!(d.minCoeff() > 1e-10 * d.maxCoeff())) return false;
  X = qr.solve(R);
  return qr.info() == Eigen::Success && X.allFinite();
}

// Parameter correction (Hoschek 1988; The NURBS Book 9.4.1 remarks): one Newton step of the foot-point
// equation (C(u) - Q) . C'(u) = 0 per interior point, kept strictly between its neighbours so the
// parameters stay increasing. End parameters stay 0 and 1 (the end points are interpolated); a closed
// list keeps its first parameter 0 at the seam and the last below 1.
template <int Dim>
std::vector<double> corrected_parameters(const BSplineCurve<Dim>& c, const PointList<Dim>& points,
                                         const std::vector<double>& params, bool closed) {
  CurveEvaluator<Dim> ev(c);
  std::vector<double> t = params;
  const std::size_t last = closed ? t.size() : t.size() - 1;  // closed: only the seam point stays at 0
  for (std::size_t k = 1; k < last; ++k) {
    typename BSplineCurve<Dim>::Point P, D1, D2;
    ev.d2(params[k], P, D1, D2);
    const auto r = P - points[k];
    const double denom = D1.squaredNorm() + r.dot(D2);
    if (!(denom > 0)) continue;
    const double u = params[k] - r.dot(D1) / denom;
    const double lo = t[k - 1], hi = k + 1 < t.size() ? params[k + 1] : 1.0;
    // Stay inside (lo, hi) with a margin so consecutive parameters never merge.
    if (u > lo + 1e-3 * (params[k] - lo) && u < hi - 1e-3 * (hi - params[k])) t[k] = u;
  }
  return t;
}

// Alternates parameter correction and refitting while the residual drops by more than 1 %, at most
// `rounds` times; fit(params, curve) refits on fixed knots and returns false when ill-posed. Updates
// the fit, its parameters, errors and residual in place.
template <int Dim, class Fit>
void improve_parameters(const PointList<Dim>& points, bool closed, int rounds, Fit fit, ApproximationResult<Dim>& res,
                        std::vector<double>& err, double& residual) {
  for (int it = 0; it < rounds; ++it) {
    std::vector<double> t = corrected_parameters(res.curve, points, res.params, closed);
    BSplineCurve<Dim> c;
    if (!fit(t, c)) return;
    std::vector<double> e;
    const double me = max_error(c, points, t, e);
    const double r = sum_of_squares(e);
    if (!(r < residual)) return;
    const bool small_gain = r > 0.99 * residual;
    res.curve = std::move(c);
    res.params = std::move(t);
    res.max_error = me;
    err = std::move(e);
    residual = r;
    if (small_gain) return;
  }
}

// Open fit on fixed knots for improve_parameters.
template <int Dim>
bool fit_open(const PointList<Dim>& points, const std::vector<double>& t, int p, const std::vector<double>& U,
              BSplineCurve<Dim>& out) {
  if (!schoenberg_whitney(t, p, U)) return false;
  try {
    out = fit_least_squares<Dim>(points, t, p, U);
  } catch (const InvalidGeometry&) {
    return false;
  }
  return true;
}

// Periodic least squares on one period of knots `period` (period 1): basis j acts on pole j mod n,
// all poles free. False when the matrix is numerically rank deficient.
template <int Dim>
bool fit_periodic(const PointList<Dim>& points, const std::vector<double>& params, int p,
                  const std::vector<double>& period, BSplineCurve<Dim>& out) {
  const int n = static_cast<int>(period.size());
  const int npts = static_cast<int>(points.size());
  const std::vector<double> U = unwrap_periodic_knots(p, period, 1.0);
  std::vector<Eigen::Triplet<double>> trip;
  double N[kMaxDegree + 1];
  Eigen::MatrixXd Q(npts, Dim);
  for (int k = 0; k < npts; ++k) {
    Q.row(k) = points[static_cast<std::size_t>(k)].transpose();
    const double u = params[static_cast<std::size_t>(k)];
    const int s = find_span(U.data(), n + p - 1, p, u);
    basis_funs(s, u, p, U.data(), N);
    for (int j = 0; j <= p; ++j)
      if (N[j] != 0.0) trip.emplace_back(k, (s - p + j) % n, N[j]);
  }
  Eigen::SparseMatrix<double> A(npts, n);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::MatrixXd X;
  if (!solve_least_squares(A, Q, X)) return false;
  PointList<Dim> P(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) P[static_cast<std::size_t>(i)] = X.row(i).transpose();
  out = BSplineCurve<Dim>::periodic(p, period, 1.0, P);
  return true;
}

// Shared input checks of the drivers; sets the data parameters and returns the pole limit.
template <int Dim>
int start_approximation(const PointList<Dim>& points, int p, double tol, const ApproximationOptions& options,
                        bool closed, ApproximationResult<Dim>& res) {
  check_degree(p);
  const int npts = static_cast<int>(points.size());
  check_tolerance(tol, npts, p);
  res.params = interpolation_parameters<Dim>(points, options.method, closed);
  const int max_poles = options.max_poles > 0 ? std::min(options.max_poles, npts) : npts;
  require(max_poles >= p + 1, "max_poles must be at least degree + 1");
  return max_poles;
}

}  // namespace

std::vector<double> approximation_knots(const std::vector<double>& params, int p, int num_poles) {
  check_degree(p);
  const int m = static_cast<int>(params.size()) - 1;
  const int n = num_poles - 1;
  require(num_poles >= p + 1 && n <= m, "approximation with " + std::to_string(num_poles) +
                                            " poles needs degree + 1 <= poles <= points (" + std::to_string(m + 1) +
                                            ")");
  std::vector<double> U(static_cast<std::size_t>(n + p + 2));
  for (int i = 0; i <= p; ++i) {
    U[static_cast<std::size_t>(i)] = params.front();
    U[static_cast<std::size_t>(n + 1 + i)] = params.back();
  }
  // eq. 9.68-9.69: d = (m+1)/(n-p+1); u_{p+j} = (1-a) u_{i-1} + a u_i with i = int(j d), a = j d - i.
  const double d = static_cast<double>(m + 1) / (n - p + 1);
  for (int j = 1; j <= n - p; ++j) {
    const int i = static_cast<int>(j * d);
    const double a = j * d - i;
    U[static_cast<std::size_t>(p + j)] =
        (1 - a) * params[static_cast<std::size_t>(i - 1)] + a * params[static_cast<std::size_t>(i)];
  }
  return U;
}

template <int Dim>
BSplineCurve<Dim> fit_least_squares(const PointList<Dim>& points, const std::vector<double>& params, int p,
                                    const std::vector<double>& U) {
  check_degree(p);
  const int m = static_cast<int>(points.size()) - 1;
  require(m >= 1 && static_cast<int>(params.size()) == m + 1, "least squares needs >= 2 points and one parameter each");
  const int n = static_cast<int>(U.size()) - p - 2;
  validate_knots(U, p, n + 1);
  require(n <= m, "least squares with " + std::to_string(n + 1) + " poles needs at least as many points, got " +
                      std::to_string(m + 1));
  for (int k = 1; k <= m; ++k)
    require(params[static_cast<std::size_t>(k)] >= params[static_cast<std::size_t>(k - 1)],
            "least-squares parameters must be non-decreasing");
  require(params.front() == U.front() && params.back() == U.back(),
          "least-squares parameters must start and end at the knot domain ends");
  require(schoenberg_whitney(params, p, U),
          "least-squares data do not determine the poles: the parameters violate the Schoenberg-Whitney condition "
          "for these knots (a basis function without its own data point)");
  PointList<Dim> P(static_cast<std::size_t>(n + 1));
  P.front() = points.front();
  P.back() = points.back();
  if (n >= 2) {
    // R_k = Q_k - N_0(u_k) Q_0 - N_n(u_k) Q_m for the interior data (eq. 9.63-9.66).
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::MatrixXd R(m - 1, Dim);
    double N[kMaxDegree + 1];
    for (int k = 1; k < m; ++k) {
      const double u = params[static_cast<std::size_t>(k)];
      const int s = find_span(U.data(), n, p, u);
      basis_funs(s, u, p, U.data(), N);
      Eigen::Matrix<double, Dim, 1> r = points[static_cast<std::size_t>(k)];
      for (int j = 0; j <= p; ++j) {
        const int i = s - p + j;
        if (i == 0)
          r -= N[j] * points.front();
        else if (i == n)
          r -= N[j] * points.back();
        else if (N[j] != 0.0)
          trip.emplace_back(k - 1, i - 1, N[j]);
      }
      R.row(k - 1) = r.transpose();
    }
    Eigen::SparseMatrix<double> A(m - 1, n - 1);
    A.setFromTriplets(trip.begin(), trip.end());
    Eigen::MatrixXd X;
    if (!solve_least_squares(A, R, X))
      throw InvalidGeometry("least-squares system is numerically singular for these parameters and knots");
    for (int i = 1; i < n; ++i) P[static_cast<std::size_t>(i)] = X.row(i - 1).transpose();
  }
  return BSplineCurve<Dim>(p, U, P);
}

template <int Dim>
ApproximationResult<Dim> approximate(const PointList<Dim>& points, int p, double tol,
                                     const ApproximationOptions& options) {
  const int npts = static_cast<int>(points.size());
  ApproximationResult<Dim> res;
  const int max_poles = start_approximation(points, p, tol, options, false, res);
  std::vector<double> U(static_cast<std::size_t>(2 * p + 2), 0.0);
  std::fill(U.begin() + p + 1, U.end(), 1.0);
  std::vector<double> err;
  res.curve = fit_least_squares<Dim>(points, res.params, p, U);  // one Bezier span: always well posed
  res.max_error = max_error(res.curve, points, res.params, err);
  double residual = sum_of_squares(err);
  auto refit = [&](const std::vector<double>& t, BSplineCurve<Dim>& c) { return fit_open(points, t, p, U, c); };
  improve_parameters(points, false, options.parameter_corrections, refit, res, err, residual);
  while (res.max_error > tol) {
    const int poles = static_cast<int>(U.size()) - p - 1;
    if (poles >= max_poles) break;
    // Split every span that misses the tolerance; if that fit is ill-posed, retry with the worst span
    // only; if that fails too, refinement has stalled. Knot insertion nests the spline spaces, so the
    // least-squares residual cannot grow: a fit whose residual grows was ruined by rounding (an
    // ill-conditioned matrix although Schoenberg-Whitney holds) and is rejected.
    const std::vector<double> cand = refinement_candidates(distinct_values(U, 0.0, 1.0), res.params, err, tol);
    bool refitted = false;
    for (std::size_t limit : {cand.size(), std::size_t{1}}) {
      std::vector<double> V = U;
      int added = 0;
      for (std::size_t c = 0; c < cand.size() && static_cast<std::size_t>(added) < limit; ++c) {
        if (poles + added >= max_poles) break;
        std::vector<double> W = V;
        W.insert(std::upper_bound(W.begin(), W.end(), cand[c]), cand[c]);
        if (!schoenberg_whitney(res.params, p, W)) continue;
        V = std::move(W);
        ++added;
      }
      if (added == 0) break;
      BSplineCurve<Dim> fit;
      try {
        fit = fit_least_squares<Dim>(points, res.params, p, V);
      } catch (const InvalidGeometry&) {
        continue;
      }
      std::vector<double> e;
      const double me = max_error(fit, points, res.params, e);
      const double r = sum_of_squares(e);
      if (!(r <= residual * (1 + 1e-6) + 1e-300)) continue;
      U = std::move(V);
      res.curve = std::move(fit);
      res.max_error = me;
      err = std::move(e);
      residual = r;
      refitted = true;
      break;
    }
    if (!refitted) break;
    improve_parameters(points, false, options.parameter_corrections, refit, res, err, residual);
  }
  if (res.max_error > tol && npts <= max_poles) {
    // Refinement stalled or reached one pole per point: interpolate (A9.1, error at rounding level).
    res.curve = interpolate<Dim>(points, p, res.params, averaged_knots(res.params, p));
    res.max_error = max_error(res.curve, points, res.params, err);
  }
  res.tolerance_met = res.max_error <= tol;
  return res;
}

template <int Dim>
ApproximationResult<Dim> approximate_closed(const PointList<Dim>& points, int p, double tol,
                                            const ApproximationOptions& options) {
  const int npts = static_cast<int>(points.size());
  ApproximationResult<Dim> res;
  const int max_poles = start_approximation(points, p, tol, options, true, res);
  // One period of knots starting at 0 (the seam at the first point); p + 1 uniform spans to begin.
  std::vector<double> t(static_cast<std::size_t>(p + 1));
  for (int j = 0; j <= p; ++j) t[static_cast<std::size_t>(j)] = static_cast<double>(j) / (p + 1);
  auto refit = [&](const std::vector<double>& params, BSplineCurve<Dim>& c) {
    return fit_periodic(points, params, p, t, c);
  };
  std::vector<double> err;
  bool have_curve = false;
  double residual = HUGE_VAL;
  for (;;) {
    const int n = static_cast<int>(t.size());
    BSplineCurve<Dim> c;
    if (!refit(res.params, c)) break;  // rank lost: keep the previous fit, interpolate below if needed
    std::vector<double> e;
    const double me = max_error(c, points, res.params, e);
    const double r = sum_of_squares(e);
    if (have_curve && !(r <= residual * (1 + 1e-6) + 1e-300)) break;  // ruined by rounding (see approximate)
    res.curve = std::move(c);
    res.max_error = me;
    err = std::move(e);
    residual = r;
    have_curve = true;
    improve_parameters(points, true, options.parameter_corrections, refit, res, err, residual);
    if (res.max_error <= tol || n >= max_poles) break;
    // Insert where the error is largest, keeping data strictly inside every span (with one data point
    // per span and n spans the periodic system has full rank; the QR rank is checked anyway).
    std::vector<double> breaks = t;
    breaks.push_back(1.0);
    int added = 0;
    for (double k : refinement_candidates(breaks, res.params, err, tol)) {
      if (n + added >= max_poles) break;
      t.insert(std::upper_bound(t.begin(), t.end(), k), k);
      ++added;
    }
    if (added == 0) break;
  }
  if (!have_curve || (res.max_error > tol && npts <= max_poles)) {
    res.curve = interpolate_closed<Dim>(points, p, res.params, periodic_interpolation_knots(res.params, p));
    res.max_error = max_error(res.curve, points, res.params, err);
  }
  res.tolerance_met = res.max_error <= tol;
  return res;
}

#define CG_FIT_APPROXIMATE_INSTANTIATE(D)                                                                        \
  template BSplineCurve<D> fit_least_squares<D>(const PointList<D>&, const std::vector<double>&, int,            \
                                                const std::vector<double>&);                                     \
  template ApproximationResult<D> approximate<D>(const PointList<D>&, int, double, const ApproximationOptions&); \
  template ApproximationResult<D> approximate_closed<D>(const PointList<D>&, int, double, const ApproximationOptions&);
CG_FIT_APPROXIMATE_INSTANTIATE(1)
CG_FIT_APPROXIMATE_INSTANTIATE(2)
CG_FIT_APPROXIMATE_INSTANTIATE(3)

}  // namespace cg
