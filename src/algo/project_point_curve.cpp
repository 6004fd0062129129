#include "src/algo/project_point_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "src/core/error.hpp"
#include "src/core/newton.hpp"
#include "src/core/rational.hpp"
#include "src/algo/distinct_minima.hpp"

namespace cg {

namespace {

// Deepest subdivision of one span: 2^-60 of a span is below the resolution of any parameter, and the
// flatness test ends every branch long before (the variation bound halves with each level).
constexpr int kMaxDepth = 60;
// Bernstein coefficients of h have degree up to 3p - 1.
constexpr int kMaxH = 3 * kMaxDegree;

}  // namespace

template <int Dim>
CurveProjector<Dim>::CurveProjector(const BSplineCurve<Dim>& curve, double tolerance)
    : ev_(curve), p_(curve.degree()), rational_(curve.is_rational()) {
  constexpr int W = Dim + 1;
  const auto spans = curve_bezier_spans(curve);
  nspan_ = static_cast<int>(spans.size());
  const int block = (p_ + 1) * W;
  span_poles_.resize(static_cast<std::size_t>(nspan_ * block));
  BoundingBox<Dim> all;
  for (int k = 0; k < nspan_; ++k) {
    const auto& s = spans[static_cast<std::size_t>(k)];
    span_a_.push_back(s.a);
    span_b_.push_back(s.b);
    span_box_.push_back(s.box);
    all.add(s.box);
    std::memcpy(&span_poles_[static_cast<std::size_t>(k * block)], s.hpoles.data(), sizeof(double) * block);
    // The end poles of a Bézier piece are curve points: exact span boundary points.
    knot_points_.push_back(s.hpoles.col(0).template head<Dim>() / s.hpoles(Dim, 0));
    if (k + 1 == nspan_) knot_points_.push_back(s.hpoles.col(p_).template head<Dim>() / s.hpoles(Dim, p_));
  }
  const double scale = all.diagonal();
  scale_ = all.hi.cwiseAbs().cwiseMax(all.lo.cwiseAbs()).maxCoeff();
  tol_ = tolerance > 0 ? tolerance : 1e-12 * (1.0 + scale);
  // Two closest points nearer than this are one minimum (the distance is flat to ~tol_ over a
  // parameter range of ~sqrt(tol_) around a minimum, so candidates of one minimum lie this close).
  merge_tol_ = 1e-6 * (1.0 + scale);
  hdeg_ = rational_ ? 3 * p_ - 1 : 2 * p_ - 1;
  for (int j = 0; j <= p_; ++j) binom_p_.push_back(binomial(p_, j));
  for (int j = 0; j < p_; ++j) binom_p1_.push_back(binomial(p_ - 1, j) * p_);
  for (int k = 0; k <= hdeg_; ++k) inv_binom_h_.push_back(1.0 / binomial(hdeg_, k));
  stack_.reserve(2 * kMaxDepth + 4);
  pool_.resize(static_cast<std::size_t>((2 * kMaxDepth + 4) * block));
  cands_.reserve(static_cast<std::size_t>(nspan_ + 64));
  order_.reserve(static_cast<std::size_t>(nspan_));
}

template <int Dim>
void CurveProjector<Dim>::consider(double u, double dist, const Point& point) {
  if (!(dist <= best_ + tol_)) return;
  if (!have_best_ && dist > best_) return;  // beyond the search radius
  if (dist < best_ || !have_best_) {
    best_ = dist;
    have_best_ = true;
  }
  cands_.push_back(Candidate{u, dist, point});
}

// Newton's method on f(u) = C'(u).(C(u) - P) inside [lo, hi] where f(lo) < 0 < f(hi), with
// f' = C''.(C - P) + |C'|^2 (newton::solve_bracketed: bisection safeguard, so it always converges).
template <int Dim>
void CurveProjector<Dim>::newton(double lo, double hi, double u) {
  Point C, C1, C2;
  const double eps = 4e-16 * (std::abs(lo) + std::abs(hi) + (hi - lo));
  u = newton::solve_bracketed(
      [&](double x, double& df) {
        ev_.d2(x, C, C1, C2);
        const Point r = C - P_;
        df = C2.dot(r) + C1.squaredNorm();
        return C1.dot(r);
      },
      lo, hi, -1, u, eps);
  const Point C0 = ev_.point(u);
  consider(u, (C0 - P_).norm(), C0);
}

template <int Dim>
double refine_foot(CurveEvaluator<Dim>& ev, const Eigen::Matrix<double, Dim, 1>& P, double u,
                   const newton::Domain<1>& dom, int max_iterations, double value_noise) {
  using Point = Eigen::Matrix<double, Dim, 1>;
  using V1 = Eigen::Matrix<double, 1, 1>;
  newton::MinimizeOptions<1> opt;
  opt.max_iterations = max_iterations;
  opt.value_noise = value_noise;
  const double width = std::isfinite(dom.hi[0] - dom.lo[0]) ? dom.hi[0] - dom.lo[0] : 1.0;
  opt.xtol[0] = 4e-16 * (std::abs(dom.lo[0]) + std::abs(dom.hi[0]) + width);
  Point C, C1, C2;
  const auto r = newton::minimize<1>(
      [&](const V1& x, V1* g, Eigen::Matrix<double, 1, 1>* H) {
        if (!g) return 0.5 * (ev.point(x[0]) - P).squaredNorm();
        ev.d2(x[0], C, C1, C2);
        const Point res = C - P;
        (*g)[0] = C1.dot(res);
        (*H)(0, 0) = C1.squaredNorm() + C2.dot(res);
        return 0.5 * res.squaredNorm();
      },
      V1(u), dom, opt);
  return r.x[0];
}

// Step 4: refine_foot from c.u over the whole curve (wrapping a periodic curve's parameter).
template <int Dim>
typename CurveProjector<Dim>::Candidate CurveProjector<Dim>::polish(const Candidate& c) {
  const BSplineCurve<Dim>& curve = ev_.curve();
  newton::Domain<1> dom;
  dom.lo[0] = curve.first_param();
  dom.hi[0] = curve.last_param();
  dom.periodic[0] = curve.is_periodic();
  // Rounding of |C - P|^2 / 2: |C - P| times the rounding of the coordinates (see newton.hpp).
  const double ulp = 4e-16 * (scale_ + P_.cwiseAbs().maxCoeff());
  const double u = refine_foot<Dim>(ev_, P_, c.u, dom, 40, ulp * (c.dist + ulp));
  const Point q = ev_.point(u);
  return Candidate{u, (q - P_).norm(), q};
}

// Examines one Bézier piece [a, b] with homogeneous poles hp; see the header for the method.
template <int Dim>
void CurveProjector<Dim>::examine(const double* hp, double a, double b, int depth) {
  constexpr int W = Dim + 1;
  const int p = p_;
  double D[kMaxDegree + 1][Dim], w[kMaxDegree + 1];
  double dist0 = 0;
  BoundingBox<Dim> box;
  for (int j = 0; j <= p; ++j) {
    const double* h = hp + j * W;
    w[j] = h[Dim];
    Point q;
    for (int d = 0; d < Dim; ++d) {
      q[d] = h[d] / w[j];
      D[j][d] = h[d] - w[j] * P_[d];
    }
    box.add(q);
    if (j == 0) dist0 = (q - P_).norm();
  }
  if (box.distance(P_) > best_ + tol_) return;

  // Scaled Bernstein coefficients (c~_k = C(n, k) c_k) multiply by plain convolution.
  double Ds[kMaxDegree + 1][Dim], Dd[kMaxDegree][Dim];
  for (int j = 0; j <= p; ++j)
    for (int d = 0; d < Dim; ++d) Ds[j][d] = binom_p_[j] * D[j][d];
  for (int j = 0; j < p; ++j)
    for (int d = 0; d < Dim; ++d) Dd[j][d] = binom_p1_[j] * (D[j + 1][d] - D[j][d]);
  double X[2 * kMaxDegree + 1] = {};  // D.D', degree 2p - 1
  for (int i = 0; i <= p; ++i)
    for (int j = 0; j < p; ++j) {
      double s = 0;
      for (int d = 0; d < Dim; ++d) s += Ds[i][d] * Dd[j][d];
      X[i + j] += s;
    }
  double h[kMaxH + 1];
  double wmin = 1.0;
  if (!rational_) {
    for (int k = 0; k <= hdeg_; ++k) h[k] = X[k];
  } else {
    double Y[2 * kMaxDegree + 1] = {};  // D.D, degree 2p
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j <= p; ++j) {
        double s = 0;
        for (int d = 0; d < Dim; ++d) s += Ds[i][d] * Ds[j][d];
        Y[i + j] += s;
      }
    for (int k = 0; k <= hdeg_; ++k) h[k] = 0.0;
    wmin = w[0];
    for (int i = 0; i <= p; ++i) {
      wmin = std::min(wmin, w[i]);
      const double ws = binom_p_[i] * w[i];
      for (int j = 0; j < 2 * p; ++j) h[i + j] += ws * X[j];
    }
    for (int i = 0; i < p; ++i) {
      const double wd = binom_p1_[i] * (w[i + 1] - w[i]);
      for (int j = 0; j <= 2 * p; ++j) h[i + j] -= wd * Y[j];
    }
  }
  double hmax = 0;
  int changes = 0, first_sign = 0, last_sign = 0, change_at = 0;
  for (int k = 0; k <= hdeg_; ++k) {
    h[k] *= inv_binom_h_[k];
    hmax = std::max(hmax, std::abs(h[k]));
    const int s = h[k] > 0 ? 1 : h[k] < 0 ? -1 : 0;
    if (s == 0) continue;
    if (first_sign == 0) first_sign = s;
    else if (s != last_sign) {
      ++changes;
      change_at = k;
    }
    last_sign = s;
  }
  // |d(dist^2)/dt| = 2|h|/w^3 <= V on t in [0, 1]: the distance on the piece is at least
  // sqrt(dist0^2 - V). If that is within tol of dist0, the piece is flat: its end points represent it.
  const double V = 2.0 * hmax / (wmin * wmin * wmin);
  if (dist0 - std::sqrt(std::max(0.0, dist0 * dist0 - V)) <= tol_) return;
  if (changes == 0) return;  // monotone distance: the minimum is at an end point (already considered)
  if (changes == 1) {
    if (first_sign > 0) return;  // the only critical point is a maximum
    // Start where the control polygon of h crosses zero.
    int k = change_at - 1;
    while (k > 0 && h[k] == 0) --k;
    const double t = (k + h[k] / (h[k] - h[change_at]) * (change_at - k)) / hdeg_;
    newton(a, b, a + std::clamp(t, 0.0, 1.0) * (b - a));
    return;
  }
  const double m = 0.5 * (a + b);
  if (depth >= kMaxDepth) {
    const Point C = ev_.point(m);
    consider(m, (C - P_).norm(), C);
    return;
  }
  // Split; the split point is a curve point. The halves go on the stack (left on top: examined first).
  const int block = (p + 1) * W;
  const std::size_t top = stack_.size();
  if (pool_.size() < (top + 2) * static_cast<std::size_t>(block)) pool_.resize((top + 2) * static_cast<std::size_t>(block));
  double* right = &pool_[top * static_cast<std::size_t>(block)];
  double* left = right + block;
  split_bezier(p, W, hp, 0.5, left, right);
  Point mid;
  for (int d = 0; d < Dim; ++d) mid[d] = left[p * W + d] / left[p * W + Dim];
  consider(m, (mid - P_).norm(), mid);
  stack_.push_back(Piece{m, b, depth + 1});
  stack_.push_back(Piece{a, m, depth + 1});
}

template <int Dim>
CurveProjection<Dim> CurveProjector<Dim>::run(const Point& P, double max_distance, std::vector<double>* params) {
  require(P.allFinite(), "projection point must have finite coordinates");
  require(max_distance >= 0, "max_distance must be >= 0");
  constexpr int W = Dim + 1;
  const int block = (p_ + 1) * W;
  P_ = P;
  cands_.clear();
  have_best_ = false;
  best_ = max_distance;  // the search radius prunes like a found point until one is found
  for (int k = 0; k <= nspan_; ++k) {
    const double d = (knot_points_[static_cast<std::size_t>(k)] - P).norm();
    consider(k < nspan_ ? span_a_[static_cast<std::size_t>(k)] : span_b_.back(), d,
             knot_points_[static_cast<std::size_t>(k)]);
  }
  order_.clear();
  for (int k = 0; k < nspan_; ++k) {
    const double lb = span_box_[static_cast<std::size_t>(k)].distance(P);
    if (lb <= best_ + tol_) order_.emplace_back(lb, k);
  }
  std::sort(order_.begin(), order_.end());
  for (const auto& [lb, k] : order_) {
    if (lb > best_ + tol_) break;
    stack_.clear();
    examine(&span_poles_[static_cast<std::size_t>(k * block)], span_a_[static_cast<std::size_t>(k)],
            span_b_[static_cast<std::size_t>(k)], 0);
    while (!stack_.empty()) {
      const Piece piece = stack_.back();
      stack_.pop_back();
      // Copy the poles out of the pool: examine() writes the children into the same block.
      double hp[(kMaxDegree + 1) * (Dim + 1)];
      std::memcpy(hp, &pool_[stack_.size() * static_cast<std::size_t>(block)], sizeof(double) * block);
      examine(hp, piece.a, piece.b, piece.depth);
    }
  }

  CurveProjection<Dim> res;
  if (!have_best_) {
    if (params) params->clear();
    return res;
  }
  // Distinct minima: greedy by distance, a candidate joins a kept one when their points are within
  // merge_tol_ (the candidates of one minimum lie that close, see the constructor).
  std::size_t kept = detail::keep_distinct_minima(cands_, best_ + tol_, merge_tol_);
  // Step 4: polish each distinct minimum (never worse), then merge again (two candidates of one foot
  // may now coincide, and the best may have dropped by up to the tolerance).
  cands_.resize(kept);
  for (auto& c : cands_) {
    const Candidate q = polish(c);
    if (q.dist <= c.dist) c = q;
  }
  double best = cands_[0].dist;
  for (const auto& c : cands_) best = std::min(best, c.dist);
  kept = detail::keep_distinct_minima(cands_, best + tol_, merge_tol_);
  res.found = true;
  res.param = cands_[0].u;
  res.point = cands_[0].point;
  res.distance = cands_[0].dist;
  res.num_minima = static_cast<int>(kept);
  if (params) {
    params->clear();
    for (std::size_t j = 0; j < kept; ++j) params->push_back(cands_[j].u);
    std::sort(params->begin(), params->end());
  }
  return res;
}

template <int Dim>
CurveProjection<Dim> CurveProjector<Dim>::project(const Point& P, double max_distance) {
  return run(P, max_distance, nullptr);
}

template <int Dim>
CurveProjection<Dim> CurveProjector<Dim>::project_all(const Point& P, std::vector<double>& params,
                                                      double max_distance) {
  return run(P, max_distance, &params);
}

template <int Dim>
CurveProjectionAll<Dim> project_point_on_curve(const BSplineCurve<Dim>& curve,
                                               const Eigen::Matrix<double, Dim, 1>& P) {
  CurveProjector<Dim> proj(curve);
  CurveProjectionAll<Dim> out;
  static_cast<CurveProjection<Dim>&>(out) = proj.project_all(P, out.params);
  return out;
}

template class CurveProjector<1>;
template class CurveProjector<2>;
template class CurveProjector<3>;
template double refine_foot<1>(CurveEvaluator<1>&, const Eigen::Matrix<double, 1, 1>&, double, const newton::Domain<1>&, int, double);
template double refine_foot<2>(CurveEvaluator<2>&, const Eigen::Vector2d&, double, const newton::Domain<1>&, int, double);
template double refine_foot<3>(CurveEvaluator<3>&, const Eigen::Vector3d&, double, const newton::Domain<1>&, int, double);
template CurveProjectionAll<1> project_point_on_curve<1>(const BSplineCurve<1>&, const Eigen::Matrix<double, 1, 1>&);
template CurveProjectionAll<2> project_point_on_curve<2>(const BSplineCurve<2>&, const Eigen::Vector2d&);
template CurveProjectionAll<3> project_point_on_curve<3>(const BSplineCurve<3>&, const Eigen::Vector3d&);

}  // namespace cg
