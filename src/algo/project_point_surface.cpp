#include "src/algo/project_point_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/rational.hpp"
#include "src/algo/distinct_minima.hpp"

namespace cg {

namespace {

// Subdivision depth cap; the flatness test ends branches long before (the variation bound shrinks
// with the patch).
constexpr int kMaxDepth = 50;
// A coefficient sign counts as strict only above this fraction of the largest coefficient, so a
// critical point lying on a patch edge (coefficients ~ rounding there) never excludes both patches.
constexpr double kSignMargin = 1e-12;

// Homogeneous poles of the iso-curve at fixed u (fixed_u) or fixed v: the other direction's poles
// combined with the basis functions at the fixed value.
BSplineCurve<3> iso_curve(const BSplineSurface<3>& s, bool fixed_u, double value) {
  const int p = fixed_u ? s.degree_u() : s.degree_v();
  const auto& K = fixed_u ? s.knots_u() : s.knots_v();
  const int n = fixed_u ? s.num_poles_u() : s.num_poles_v();
  const int m = fixed_u ? s.num_poles_v() : s.num_poles_u();
  const int span = find_span(K.data(), n - 1, p, value);
  double N[kMaxDegree + 1];
  basis_funs(span, value, p, K.data(), N);
  Eigen::Matrix<double, 4, Eigen::Dynamic> H(4, m);
  for (int j = 0; j < m; ++j) {
    Eigen::Vector4d q = Eigen::Vector4d::Zero();
    for (int k = 0; k <= p; ++k) {
      const int i = span - p + k;
      q += N[k] * (fixed_u ? s.homogeneous_pole(i, j) : s.homogeneous_pole(j, i));
    }
    H.col(j) = q;
  }
  return fixed_u ? BSplineCurve<3>::from_homogeneous(s.degree_v(), s.knots_v(), H, s.is_periodic_v())
                 : BSplineCurve<3>::from_homogeneous(s.degree_u(), s.knots_u(), H, s.is_periodic_u());
}

// c (na+nb-1) x (ma+mb-1) += a (na x ma) * b (nb x mb), plain 2D convolution of scaled Bernstein
// coefficients (c~_kl = C(n,k) C(m,l) c_kl multiply without further factors). Vector entries (dim
// components each) are combined by the dot product.
void conv2(const double* a, int na, int ma, const double* b, int nb, int mb, int dim, double sign, double* c) {
  const int mc = ma + mb - 1;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < ma; ++j) {
      const double* x = a + (i * ma + j) * dim;
      for (int k = 0; k < nb; ++k) {
        double* row = c + (i + k) * mc + j;
        const double* y = b + (k * mb) * dim;
        for (int l = 0; l < mb; ++l) {
          double s = 0;
          for (int d = 0; d < dim; ++d) s += x[d] * y[l * dim + d];
          row[l] += sign * s;
        }
      }
    }
}

}  // namespace

SurfaceProjector::~SurfaceProjector() = default;

SurfaceProjector::SurfaceProjector(const BSplineSurface<3>& surface, double tolerance)
    : s_(std::make_shared<const BSplineSurface<3>>(surface)),
      pu_(surface.degree_u()),
      pv_(surface.degree_v()),
      rational_(surface.is_rational()) {
  umin_ = surface.first_u();
  umax_ = surface.last_u();
  vmin_ = surface.first_v();
  vmax_ = surface.last_v();
  domain_.lo = Eigen::Vector2d(umin_, vmin_);
  domain_.hi = Eigen::Vector2d(umax_, vmax_);
  domain_.periodic = {surface.is_periodic_u(), surface.is_periodic_v()};
  newton_.xtol = Eigen::Vector2d(1e-15 * (umax_ - umin_ + std::abs(umax_)), 1e-15 * (vmax_ - vmin_ + std::abs(vmax_)));
  newton_.shift_extra = 1e-3;
  const auto patches = surface_bezier_patches(surface);
  npatch_ = static_cast<int>(patches.size());
  const int block = (pu_ + 1) * (pv_ + 1) * 4;
  BoundingBox<3> all;
  for (const auto& p : patches) {
    patch_dom_.push_back(Piece{p.u0, p.u1, p.v0, p.v1, 0});
    patch_box_.push_back(p.box);
    all.add(p.box);
    patch_poles_.insert(patch_poles_.end(), p.hpoles.data(), p.hpoles.data() + block);
  }
  const double scale = all.diagonal();
  scale_ = all.hi.cwiseAbs().cwiseMax(all.lo.cwiseAbs()).maxCoeff();
  tol_ = tolerance > 0 ? tolerance : 1e-12 * (1.0 + scale);
  merge_tol_ = 1e-6 * (1.0 + scale);

  // Boundaries (not across a periodic seam) and creases (knots of multiplicity >= degree: C0 lines),
  // the seam of a periodic direction included when its multiplicity makes it one.
  auto add_iso = [&](bool fixed_u, double value) {
    iso_.push_back(IsoCurve{fixed_u, value, CurveProjector<3>(iso_curve(surface, fixed_u, value), tol_)});
  };
  if (!surface.is_periodic_u()) {
    add_iso(true, umin_);
    add_iso(true, umax_);
  }
  if (!surface.is_periodic_v()) {
    add_iso(false, vmin_);
    add_iso(false, vmax_);
  }
  for (int dir = 0; dir < 2; ++dir) {
    const auto& K = dir == 0 ? surface.knots_u() : surface.knots_v();
    const int p = dir == 0 ? pu_ : pv_;
    const double lo = dir == 0 ? umin_ : vmin_, hi = dir == 0 ? umax_ : vmax_;
    const bool periodic = dir == 0 ? surface.is_periodic_u() : surface.is_periodic_v();
    const auto dk = distinct_knots(K);
    for (std::size_t i = 0; i < dk.values.size(); ++i)
      if ((dk.values[i] > lo || (periodic && dk.values[i] == lo)) && dk.values[i] < hi && dk.mults[i] >= p)
        add_iso(dir == 0, dk.values[i]);
  }

  for (int k = 0; k <= pu_; ++k) bu_.push_back(binomial(pu_, k));
  for (int k = 0; k <= pv_; ++k) bv_.push_back(binomial(pv_, k));
  for (int k = 0; k < pu_; ++k) bu1_.push_back(pu_ * binomial(pu_ - 1, k));
  for (int k = 0; k < pv_; ++k) bv1_.push_back(pv_ * binomial(pv_ - 1, k));
  const std::size_t n1 = static_cast<std::size_t>((pu_ + 1) * (pv_ + 1));
  const std::size_t n2 = static_cast<std::size_t>((2 * pu_ + 1) * (2 * pv_ + 1));
  Ds_.resize(3 * n1);
  Dd_.resize(3 * n1);
  ws_.resize(n1);
  wd_.resize(n1);
  X_.resize(n2);
  Y_.resize(n2);
  hu_.resize(static_cast<std::size_t>((3 * pu_ + 1) * (3 * pv_ + 1)));
  hv_.resize(hu_.size());
  for (int n = 0; n <= 3 * std::max(pu_, pv_) + 1; ++n) {
    inv_binom_.emplace_back();
    for (int k = 0; k <= n; ++k) inv_binom_.back().push_back(1.0 / binomial(n, k));
  }
  stack_.reserve(2 * kMaxDepth + 4);
  pool_.resize(static_cast<std::size_t>((2 * kMaxDepth + 4) * block));
}

void SurfaceProjector::consider(double u, double v, double dist, const Eigen::Vector3d& point) {
  if (!(dist <= best_ + tol_)) return;
  if (!have_best_ && dist > best_) return;  // beyond the search radius
  if (dist < best_ || !have_best_) {
    best_ = dist;
    best_u_ = u;
    best_v_ = v;
    best_point_ = point;
    have_best_ = true;
  }
  cands_.push_back(Candidate{u, v, dist, point});
}

// Bernstein coefficients of h_u (along_u) or h_v on the patch; D holds the unscaled D = A - wP (3 per
// pole), w the weights, Ds_/ws_/Y_ the scaled D, w and D.D. The unscaled coefficients go to `out`
// (rows x cols). Returns false when h has one strict sign (no critical point); `variation` receives
// 2 max|h| / min(w)^3, the bound of |d(dist^2)/dt| on the patch.
bool SurfaceProjector::has_critical_point(const double* D, const double* w, bool along_u, double& variation,
                                          std::vector<double>& out, int& rows, int& cols) {
  const int a = pu_, b = pv_;
  const int na = along_u ? a : a + 1, nb = along_u ? b + 1 : b;  // derivative pole grid
  for (int k = 0; k < na; ++k)
    for (int l = 0; l < nb; ++l) {
      const int i0 = k * (b + 1) + l, i1 = along_u ? (k + 1) * (b + 1) + l : k * (b + 1) + l + 1;
      const double sc = along_u ? bu1_[k] * bv_[l] : bu_[k] * bv1_[l];
      for (int d = 0; d < 3; ++d) Dd_[(k * nb + l) * 3 + d] = sc * (D[i1 * 3 + d] - D[i0 * 3 + d]);
      wd_[k * nb + l] = sc * (w[i1] - w[i0]);
    }
  const int xn = a + 1 + na - 1, xm = b + 1 + nb - 1;  // X = D.D_t grid
  int hn = xn, hm = xm;
  if (!rational_) {
    std::fill(out.begin(), out.begin() + xn * xm, 0.0);
    conv2(Ds_.data(), a + 1, b + 1, Dd_.data(), na, nb, 3, 1.0, out.data());
  } else {
    std::fill(X_.begin(), X_.begin() + xn * xm, 0.0);
    conv2(Ds_.data(), a + 1, b + 1, Dd_.data(), na, nb, 3, 1.0, X_.data());
    hn = a + xn;
    hm = b + xm;
    std::fill(out.begin(), out.begin() + hn * hm, 0.0);
    conv2(ws_.data(), a + 1, b + 1, X_.data(), xn, xm, 1, 1.0, out.data());
    conv2(wd_.data(), na, nb, Y_.data(), 2 * a + 1, 2 * b + 1, 1, -1.0, out.data());
  }
  rows = hn;
  cols = hm;
  double hmax = 0, lo = 1e300, hi = -1e300;
  const double* ik = inv_binom_[static_cast<std::size_t>(hn - 1)].data();
  const double* il = inv_binom_[static_cast<std::size_t>(hm - 1)].data();
  for (int k = 0; k < hn; ++k)
    for (int l = 0; l < hm; ++l) {
      double& x = out[static_cast<std::size_t>(k * hm + l)];
      x *= ik[k] * il[l];
      hmax = std::max(hmax, std::abs(x));
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  double wmin = 1.0;
  if (rational_) {
    wmin = w[0];
    for (int i = 0; i < (a + 1) * (b + 1); ++i) wmin = std::min(wmin, w[i]);
  }
  variation = 2.0 * hmax / (wmin * wmin * wmin);
  const double margin = kSignMargin * hmax;
  return !(lo > margin || hi < -margin);
}

// Sufficient condition for at most one critical point in the patch: the symmetric part of the
// Jacobian of (h_u, h_v) with respect to the local (s, t) is positive definite on the whole patch, so
// the map is injective on the convex patch ((h(x) - h(y)).(x - y) > 0). Bounds of the four partial
// derivatives come from their Bernstein coefficients (differences of those of h_u, h_v).
bool SurfaceProjector::single_critical_point() const {
  const int m = hu_rows_ - 1, n = hu_cols_ - 1;  // h_u degrees; h_v has degrees (m + 1, n - 1)
  if (m < 1 || n < 1) return false;
  double a_min = 1e300, d_min = 1e300, e_max = 0;
  for (int k = 0; k < m; ++k)
    for (int l = 0; l <= n; ++l)
      a_min = std::min(a_min, m * (hu_[(k + 1) * (n + 1) + l] - hu_[k * (n + 1) + l]));
  const int mv = hv_rows_ - 1, nv = hv_cols_ - 1;
  for (int k = 0; k <= mv; ++k)
    for (int l = 0; l < nv; ++l)
      d_min = std::min(d_min, nv * (hv_[k * (nv + 1) + l + 1] - hv_[k * (nv + 1) + l]));
  if (!(a_min > 0 && d_min > 0)) return false;
  // d h_u / dt and d h_v / ds share the degrees (m, n - 1) = (mv - 1, nv).
  for (int k = 0; k <= m; ++k)
    for (int l = 0; l < n; ++l) {
      const double bt = n * (hu_[k * (n + 1) + l + 1] - hu_[k * (n + 1) + l]);
      const double cs = mv * (hv_[(k + 1) * (nv + 1) + l] - hv_[k * (nv + 1) + l]);
      e_max = std::max(e_max, std::abs(0.5 * (bt + cs)));
    }
  return a_min * d_min > e_max * e_max;
}

// Damped Newton (Levenberg-Marquardt) on grad(|S - P|^2 / 2) = 0 with the analytic Hessian
// (newton::minimize: clamped to the domain, wrapped across a periodic seam, the distance never
// increasing). The end point is a candidate; returns true when it is a critical point (uv receives it).
bool SurfaceProjector::newton(double u, double v, Eigen::Vector2d& uv) {
  const Candidate c = polish(Candidate{u, v, 0.0, Eigen::Vector3d::Zero()});
  consider(c.u, c.v, c.dist, c.point);
  uv = Eigen::Vector2d(c.u, c.v);
  // A critical point: the residual is orthogonal to both tangents to ~1e-9 (Newton converges
  // quadratically, so a converged point is far below this; a stalled one far above).
  const auto d = s_->derivatives<1>(c.u, c.v);
  const Eigen::Vector3d r = c.point - P_;
  return std::abs(d.S_u().dot(r)) <= 1e-9 * d.S_u().norm() * (c.dist + tol_) &&
         std::abs(d.S_v().dot(r)) <= 1e-9 * d.S_v().norm() * (c.dist + tol_);
}

// The Newton iteration from c's (u, v); returns the end point with its surface point and distance.
SurfaceProjector::Candidate SurfaceProjector::polish(const Candidate& c) {
  auto half_sq_dist = [&](const Eigen::Vector2d& x, Eigen::Vector2d* g, Eigen::Matrix2d* H) {
    if (!g) return 0.5 * (s_->point(x[0], x[1]) - P_).squaredNorm();
    const auto d = s_->derivatives<2>(x[0], x[1]);
    const Eigen::Vector3d r = d.S() - P_;
    const Eigen::Vector3d &Su = d.S_u(), &Sv = d.S_v();
    *g = Eigen::Vector2d(Su.dot(r), Sv.dot(r));
    const double huv = Su.dot(Sv) + d.S_uv().dot(r);
    *H << Su.dot(Su) + d.S_uu().dot(r), huv, huv, Sv.dot(Sv) + d.S_vv().dot(r);
    return 0.5 * r.squaredNorm();
  };
  // Rounding of |S - P|^2 / 2: |S - P| times the rounding of the coordinates (~1e-16 of their size).
  newton::MinimizeOptions<2> opt = newton_;
  const double ulp = 4e-16 * (scale_ + P_.cwiseAbs().maxCoeff());
  const double d0 = c.dist > 0 ? c.dist : (s_->point(c.u, c.v) - P_).norm();
  opt.value_noise = ulp * (d0 + ulp);
  const auto res = newton::minimize<2>(half_sq_dist, Eigen::Vector2d(c.u, c.v), domain_, opt);
  const Eigen::Vector3d S = s_->point(res.x[0], res.x[1]);
  return Candidate{res.x[0], res.x[1], (S - P_).norm(), S};
}

void SurfaceProjector::examine(const double* hp, const Piece& piece) {
  const int a = pu_, b = pv_;
  const int n = (a + 1) * (b + 1);
  double D[(kMaxDegree + 1) * (kMaxDegree + 1) * 3];
  double w[(kMaxDegree + 1) * (kMaxDegree + 1)];
  BoundingBox<3> box;
  int nearest = 0;
  double nearest_d = 1e300;
  for (int i = 0; i < n; ++i) {
    w[i] = hp[i * 4 + 3];
    const Eigen::Vector3d q(hp[i * 4] / w[i], hp[i * 4 + 1] / w[i], hp[i * 4 + 2] / w[i]);
    box.add(q);
    const double dq = (q - P_).squaredNorm();
    if (dq < nearest_d) {
      nearest_d = dq;
      nearest = i;
    }
    for (int d = 0; d < 3; ++d) D[i * 3 + d] = hp[i * 4 + d] - w[i] * P_[d];
  }
  double lb = box.distance(P_);
  // Directional bound: |X - P| >= (X - P).n >= min_j (Q_j - P).n for X in the hull of the poles.
  const Eigen::Vector3d qn = Eigen::Vector3d(D[nearest * 3], D[nearest * 3 + 1], D[nearest * 3 + 2]) / w[nearest];
  if (qn.norm() > 0) {
    const Eigen::Vector3d nrm = qn.normalized();
    double m = 1e300;
    for (int i = 0; i < n; ++i) m = std::min(m, (D[i * 3] * nrm[0] + D[i * 3 + 1] * nrm[1] + D[i * 3 + 2] * nrm[2]) / w[i]);
    lb = std::max(lb, m);
  }
  // The same toward the best point: at a foot seen from the convex side this bound equals the distance.
  if (have_best_ && best_ > 0) {
    const Eigen::Vector3d nrm = (best_point_ - P_) / best_;
    double m = 1e300;
    for (int i = 0; i < n; ++i) m = std::min(m, (D[i * 3] * nrm[0] + D[i * 3 + 1] * nrm[1] + D[i * 3 + 2] * nrm[2]) / w[i]);
    lb = std::max(lb, m);
  }
  if (lb > best_ + tol_) return;

  for (int k = 0; k <= a; ++k)
    for (int l = 0; l <= b; ++l) {
      const int i = k * (b + 1) + l;
      const double sc = bu_[k] * bv_[l];
      for (int d = 0; d < 3; ++d) Ds_[i * 3 + d] = sc * D[i * 3 + d];
      ws_[i] = sc * w[i];
    }
  if (rational_) {
    std::fill(Y_.begin(), Y_.end(), 0.0);
    conv2(Ds_.data(), a + 1, b + 1, Ds_.data(), a + 1, b + 1, 3, 1.0, Y_.data());
  }
  double Vu = 0, Vv = 0;
  if (!has_critical_point(D, w, true, Vu, hu_, hu_rows_, hu_cols_)) return;
  if (!has_critical_point(D, w, false, Vv, hv_, hv_rows_, hv_cols_)) return;
  const double dist0 = std::sqrt(D[0] * D[0] + D[1] * D[1] + D[2] * D[2]) / w[0];
  if (dist0 - std::sqrt(std::max(0.0, dist0 * dist0 - Vu - Vv)) <= tol_) {
    // Flat: the distance is within tol of the corner's everywhere; the corners represent the patch.
    const int corners[4] = {0, b, a * (b + 1), a * (b + 1) + b};
    const double cu[4] = {piece.u0, piece.u0, piece.u1, piece.u1}, cv[4] = {piece.v0, piece.v1, piece.v0, piece.v1};
    for (int c = 0; c < 4; ++c) {
      const int i = corners[c];
      const Eigen::Vector3d q(hp[i * 4] / w[i], hp[i * 4 + 1] / w[i], hp[i * 4 + 2] / w[i]);
      consider(cu[c], cv[c], (q - P_).norm(), q);
    }
    return;
  }
  const double um = 0.5 * (piece.u0 + piece.u1), vm = 0.5 * (piece.v0 + piece.v1);
  if (piece.depth >= kMaxDepth) {
    const Eigen::Vector3d q = s_->point(um, vm);
    consider(um, vm, (q - P_).norm(), q);
    return;
  }
  // Newton from the parameter of the nearest pole (Greville-like position) unless the current best
  // point already lies in this patch (then the halves are examined without repeating it).
  auto inside = [&](double u, double v) { return u >= piece.u0 && u <= piece.u1 && v >= piece.v0 && v <= piece.v1; };
  const bool best_inside = have_best_ && inside(best_u_, best_v_);
  const bool single = single_critical_point();
  const int k = nearest / (b + 1), l = nearest % (b + 1);
  const double u_start = piece.u0 + (piece.u1 - piece.u0) * k / a, v_start = piece.v0 + (piece.v1 - piece.v0) * l / b;
  if (single) {
    // The patch has at most one critical point: once Newton converges to it inside the patch, the
    // patch's minimum is there or on its boundary, which is a surface boundary or crease (step 1) or
    // not a minimum of the surface.
    Eigen::Vector2d uv;
    const bool critical = best_inside ? newton(best_u_, best_v_, uv) : newton(u_start, v_start, uv);
    if (critical && inside(uv.x(), uv.y())) return;
  } else if (!best_inside) {
    Eigen::Vector2d uv;
    newton(u_start, v_start, uv);
  }
  // Split along the direction in which the control net is longer.
  double len_u = 0, len_v = 0;
  for (int k = 0; k <= a; ++k)
    for (int l = 0; l <= b; ++l) {
      const int i = k * (b + 1) + l;
      const Eigen::Vector3d q(hp[i * 4] / w[i], hp[i * 4 + 1] / w[i], hp[i * 4 + 2] / w[i]);
      if (k < a) {
        const int j = i + b + 1;
        len_u += (Eigen::Vector3d(hp[j * 4], hp[j * 4 + 1], hp[j * 4 + 2]) / w[j] - q).norm();
      }
      if (l < b) {
        const int j = i + 1;
        len_v += (Eigen::Vector3d(hp[j * 4], hp[j * 4 + 1], hp[j * 4 + 2]) / w[j] - q).norm();
      }
    }
  const bool along_u = len_u * (b + 1) >= len_v * (a + 1);
  const int block = n * 4;
  const std::size_t top = stack_.size();
  if (pool_.size() < (top + 2) * static_cast<std::size_t>(block)) pool_.resize((top + 2) * static_cast<std::size_t>(block));
  double* right = &pool_[top * static_cast<std::size_t>(block)];
  double* left = right + block;
  split_bezier_patch(a, b, 4, hp, along_u, 0.5, left, right);
  Piece lp = piece, rp = piece;
  lp.depth = rp.depth = piece.depth + 1;
  if (along_u) {
    lp.u1 = rp.u0 = um;
  } else {
    lp.v1 = rp.v0 = vm;
  }
  stack_.push_back(rp);
  stack_.push_back(lp);
}

SurfaceProjection SurfaceProjector::run(const Eigen::Vector3d& P, double max_distance,
                                        std::vector<Eigen::Vector2d>* params) {
  require(P.allFinite(), "projection point must have finite coordinates");
  require(max_distance >= 0, "max_distance must be >= 0");
  const int block = (pu_ + 1) * (pv_ + 1) * 4;
  P_ = P;
  cands_.clear();
  have_best_ = false;
  best_ = max_distance;
  // Patch corners are exact surface points: a cheap first upper bound.
  for (int k = 0; k < npatch_; ++k) {
    const double* hp = &patch_poles_[static_cast<std::size_t>(k * block)];
    const Eigen::Vector3d q = Eigen::Vector3d(hp[0], hp[1], hp[2]) / hp[3];
    consider(patch_dom_[static_cast<std::size_t>(k)].u0, patch_dom_[static_cast<std::size_t>(k)].v0, (q - P).norm(), q);
  }
  for (auto& iso : iso_) {
    const auto r = iso.proj.project(P, best_ + tol_);
    if (!r.found) continue;
    if (iso.fixed_u) consider(iso.value, r.param, r.distance, r.point);
    else consider(r.param, iso.value, r.distance, r.point);
  }
  order_.clear();
  for (int k = 0; k < npatch_; ++k) {
    const double lb = patch_box_[static_cast<std::size_t>(k)].distance(P);
    if (lb <= best_ + tol_) order_.emplace_back(lb, k);
  }
  std::sort(order_.begin(), order_.end());
  for (const auto& [lb, k] : order_) {
    if (lb > best_ + tol_) break;
    stack_.clear();
    examine(&patch_poles_[static_cast<std::size_t>(k * block)], patch_dom_[static_cast<std::size_t>(k)]);
    while (!stack_.empty()) {
      const Piece piece = stack_.back();
      stack_.pop_back();
      // examine() writes the halves into the popped block: copy it out first.
      double hp[(kMaxDegree + 1) * (kMaxDegree + 1) * 4];
      std::memcpy(hp, &pool_[stack_.size() * static_cast<std::size_t>(block)], sizeof(double) * block);
      examine(hp, piece);
    }
  }
  SurfaceProjection res;
  if (!have_best_) {
    if (params) params->clear();
    return res;
  }
  std::size_t kept = detail::keep_distinct_minima(cands_, best_ + tol_, merge_tol_);
  // Step 6: polish every distinct minimum (never worse: Newton does not increase the distance), then
  // merge again, as two candidates of one foot may now coincide and the best may have dropped.
  cands_.resize(kept);
  for (auto& c : cands_) {
    const Candidate q = polish(c);
    if (q.dist <= c.dist) c = q;
    if (domain_.periodic[0]) c.u = newton::Domain<2>::wrap(c.u, umin_, umax_);
    if (domain_.periodic[1]) c.v = newton::Domain<2>::wrap(c.v, vmin_, vmax_);
  }
  double best = cands_[0].dist;
  for (const auto& c : cands_) best = std::min(best, c.dist);
  kept = detail::keep_distinct_minima(cands_, best + tol_, merge_tol_);
  res.found = true;
  res.u = cands_[0].u;
  res.v = cands_[0].v;
  res.point = cands_[0].point;
  res.distance = cands_[0].dist;
  res.num_minima = static_cast<int>(kept);
  if (params) {
    params->clear();
    for (std::size_t j = 0; j < kept; ++j) params->emplace_back(cands_[j].u, cands_[j].v);
  }
  return res;
}

SurfaceProjection SurfaceProjector::project(const Eigen::Vector3d& P, double max_distance) {
  return run(P, max_distance, nullptr);
}

SurfaceProjection SurfaceProjector::project_all(const Eigen::Vector3d& P, std::vector<Eigen::Vector2d>& params,
                                                double max_distance) {
  return run(P, max_distance, &params);
}

std::vector<std::pair<bool, double>> SurfaceProjector::iso_curves() const {
  std::vector<std::pair<bool, double>> out;
  for (const auto& iso : iso_) out.emplace_back(iso.fixed_u, iso.value);
  return out;
}

SurfaceProjection project_point_on_surface(const BSplineSurface<3>& surface, const Eigen::Vector3d& P) {
  SurfaceProjector proj(surface);
  return proj.project(P);
}

}  // namespace cg
