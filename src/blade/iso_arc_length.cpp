#include "src/blade/iso_arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/analyze/gauss_legendre.hpp"
#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade {

IsoArcLengthNodes::IsoArcLengthNodes(const BSplineCurve<3>& c) : degree_(c.degree()), knots_(c.knots()) {
  require(c.num_poles() > 0, "iso-curve arc length of an empty curve");
  const double a = c.first_param(), b = c.last_param();
  breaks_.push_back(a);
  for (double k : knots_)
    if (k > breaks_.back() && k < b) breaks_.push_back(k);
  breaks_.push_back(b);
  double x[kRule], w[kRule];
  gauss_legendre(kRule, x, w);
  const int p = degree_, n = c.num_poles();
  const std::size_t stride = 2 * static_cast<std::size_t>(p + 1);
  const std::size_t spans = breaks_.size() - 1;
  basis_.reserve(spans * kPerSpan * stride);
  double ders[2 * (kMaxDegree + 1)];
  for (std::size_t i = 0; i < spans; ++i) {
    const double lo = breaks_[i], hi = breaks_[i + 1], mid = 0.5 * (lo + hi);
    const int span = find_span(knots_.data(), n - 1, p, mid);  // the polynomial piece of [lo, hi]
    auto add = [&](double u, double weight) {
      ders_basis_funs(span, u, p, 1, knots_.data(), ders);  // at lo / hi: the limits from inside
      basis_.insert(basis_.end(), ders, ders + stride);
      first_pole_.push_back(span - p);
      weights_.push_back(weight);
    };
    for (const auto& [pa, pb] : {std::pair{lo, hi}, std::pair{lo, mid}, std::pair{mid, hi}}) {
      const double h = 0.5 * (pb - pa), m = 0.5 * (pa + pb);
      for (int j = 0; j < kRule; ++j) add(m + h * x[j], h * w[j]);
    }
    add(lo, 0);
    add(mid, 0);
    add(hi, 0);
  }
}

IsoArcLength::IsoArcLength(const BSplineCurve<3>& c, std::shared_ptr<const IsoArcLengthNodes> nodes, double rel_tol)
    : curve_(&c) {
  require(rel_tol >= 1e-15 && rel_tol < 1, "iso-curve arc length: tolerance out of range [1e-15, 1)");
  require(nodes && c.degree() == nodes->degree() && c.knots() == nodes->knots(),
          "iso-curve arc length: the curve's degree and knots differ from its nodes'");
  const IsoArcLengthNodes& nd = *nodes;
  const int p = c.degree();
  const auto& H = c.homogeneous_poles();
  const bool rational = c.is_rational();
  // Speed |C'| at node k from the homogeneous poles: C' = (A' - w' C) / w (The NURBS Book eq. 4.8).
  auto node_speed = [&](std::size_t k) {
    const double* B = nd.basis(k);
    const int f = nd.first_pole(k);
    Eigen::Vector4d h = Eigen::Vector4d::Zero(), d = Eigen::Vector4d::Zero();
    for (int j = 0; j <= p; ++j) {
      h += B[j] * H.col(f + j);
      d += B[p + 1 + j] * H.col(f + j);
    }
    if (!rational) return d.head<3>().norm();
    return ((d.head<3>() - (d[3] / h[3]) * h.head<3>()) / h[3]).norm();
  };
  const std::vector<double>& br = nd.breaks();
  const std::size_t spans = br.size() - 1;
  constexpr int R = IsoArcLengthNodes::kRule;
  std::vector<double> whole(spans), left(spans), right(spans);
  cells_.reserve(2 * spans + 1);
  speed_lo_.reserve(2 * spans);
  speed_hi_.reserve(2 * spans);
  double estimate = 0;
  for (std::size_t i = 0; i < spans; ++i) {
    const std::size_t k0 = i * IsoArcLengthNodes::kPerSpan;
    double sum[3] = {0, 0, 0};
    for (int part = 0; part < 3; ++part)
      for (int j = 0; j < R; ++j) {
        const std::size_t k = k0 + static_cast<std::size_t>(part * R + j);
        sum[part] += nd.weights()[k] * node_speed(k);
      }
    whole[i] = sum[0];
    left[i] = sum[1];
    right[i] = sum[2];
    estimate += whole[i];
    const double s_lo = node_speed(k0 + 3 * R), s_mid = node_speed(k0 + 3 * R + 1), s_hi = node_speed(k0 + 3 * R + 2);
    cells_.push_back(br[i]);
    cells_.push_back(0.5 * (br[i] + br[i + 1]));
    speed_lo_.insert(speed_lo_.end(), {s_lo, s_mid});
    speed_hi_.insert(speed_hi_.end(), {s_mid, s_hi});
  }
  cells_.push_back(br.back());
  // Acceptance as in ArcLength's adaptive rule (each span gets the share of rel_tol * length
  // proportional to its parameter width; the floor 1e-14 of the span is its rounding level).
  tol_ = rel_tol * estimate;
  const double width = br.back() - br.front();
  cumulative_.assign(cells_.size(), 0.0);
  adaptive_.assign(spans, nullptr);
  for (std::size_t i = 0; i < spans; ++i) {
    double l = left[i], r = right[i];
    const double share = tol_ * (br[i + 1] - br[i]) / width;
    if (!(std::abs(l + r - whole[i]) <= std::max(share, 1e-14 * std::abs(l + r)))) {
      const double rel = std::clamp(share / std::max(whole[i], 1e-300), 1e-15, 0.5);
      auto table = std::make_shared<const ArcLength<3>>(c, br[i], br[i + 1], rel);
      l = table->length_to(cells_[2 * i + 1]);
      r = table->total() - l;
      adaptive_[i] = std::move(table);
    }
    cumulative_[2 * i + 1] = cumulative_[2 * i] + l;
    cumulative_[2 * i + 2] = cumulative_[2 * i + 1] + r;
  }
}

int IsoArcLength::adaptive_spans() const {
  return static_cast<int>(std::count_if(adaptive_.begin(), adaptive_.end(), [](const auto& t) { return t != nullptr; }));
}

double IsoArcLength::speed(double u) const {
  Eigen::Vector3d d[2];
  curve_->derivatives(u, 1, d);
  return d[1].norm();
}

double IsoArcLength::cell_integral(std::size_t cell, double u) const {
  static const struct Rule {
    double x[IsoArcLengthNodes::kRule], w[IsoArcLengthNodes::kRule];
    Rule() { gauss_legendre(IsoArcLengthNodes::kRule, x, w); }
  } rule;
  const double lo = cells_[cell];
  if (u == lo) return 0;
  const double h = 0.5 * (u - lo), m = 0.5 * (u + lo);
  double s = 0;
  for (int j = 0; j < IsoArcLengthNodes::kRule; ++j) s += rule.w[j] * speed(m + h * rule.x[j]);
  return s * h;
}

double IsoArcLength::length_to(double u) const {
  const double a = first(), b = last();
  const double eps = 1e-12 * (b - a);
  if (!(u >= a - eps && u <= b + eps))  // (message built only on failure: hot path)
    throw InvalidGeometry("parameter " + format_number(u) + " outside the curve domain");
  u = std::clamp(u, a, b);
  if (u == b) return cumulative_.back();
  const std::size_t c = static_cast<std::size_t>(std::upper_bound(cells_.begin(), cells_.end(), u) - cells_.begin()) - 1;
  if (const auto& t = adaptive_[c / 2]) return cumulative_[c / 2 * 2] + t->length_to(u);
  return cumulative_[c] + cell_integral(c, u);
}

IsoArcLength::Guess IsoArcLength::guess(double s) const {
  const double L = total();
  if (!(s >= -tol_ && s <= L + tol_)) {
    const ValueRangeText t = format_value_range(s, 0, L);
    throw InvalidGeometry("arc length " + t.value + " outside [0, " + t.hi + "]");
  }
  if (s <= 0) return {0, first(), true};
  if (s >= L) return {0, last(), true};
  std::size_t c =
      static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin()) - 1;
  c = std::min(c, cells_.size() - 2);
  if (const auto& t = adaptive_[c / 2]) {
    const double base = cumulative_[c / 2 * 2];
    return {c, t->param_at(std::clamp(s - base, 0.0, t->total())), true};
  }
  const double lo = cells_[c], hi = cells_[c + 1], s0 = cumulative_[c], len = cumulative_[c + 1] - s0;
  if (len <= 0) return {c, lo, true};
  // Cubic Hermite guess of u(s) on the cell: du/ds = 1 / speed at its ends.
  const double t = (s - s0) / len;
  double u = lo + (hi - lo) * t;
  if (speed_lo_[c] > 0 && speed_hi_[c] > 0) {
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t), h01 = t * t * (3 - 2 * t),
                 h11 = t * t * (t - 1);
    u = h00 * lo + h10 * len / speed_lo_[c] + h01 * hi + h11 * len / speed_hi_[c];
  }
  if (!(u > lo && u < hi)) u = lo + (hi - lo) * t;
  return {c, u, false};
}

double IsoArcLength::param_near(double s) const { return guess(s).u; }

double IsoArcLength::param_at(double s) const {
  const Guess g = guess(s);
  if (g.exact) return g.u;
  const std::size_t c = g.cell;
  const double lo = cells_[c], hi = cells_[c + 1], s0 = cumulative_[c];
  // length_to(u) - s increases with u (derivative: the speed): bracketed Newton to |L(u) - s| <= tol.
  // After the first step the iterate moves by ~the guess's error, a tiny fraction of the cell: L at the
  // new iterate is L at the old one plus the 5-point rule over the step between them (exact far below
  // the tolerance there), not the 10-point rule from the cell's start again.
  static const struct Short {
    double x[5], w[5];
    Short() { gauss_legendre(5, x, w); }
  } rule5;
  double a = lo, b = hi, x = g.u, Lx = s0 + cell_integral(c, x);
  const double xtol = 4e-16 * (std::abs(lo) + std::abs(hi) + (hi - lo));
  for (int it = 0; it < 200; ++it) {
    const double r = Lx - s;
    if (r == 0 || std::abs(r) <= tol_) break;
    (r < 0 ? a : b) = x;
    const double sp = speed(x);
    double next = x - r / sp;
    if (!(sp > 0) || !(next > a && next < b)) next = 0.5 * (a + b);
    if (std::abs(next - x) <= xtol || b - a <= xtol) return next;
    if (std::abs(next - x) <= 0.01 * (hi - lo)) {
      const double h = 0.5 * (next - x), m = 0.5 * (next + x);
      double step = 0;
      for (int j = 0; j < 5; ++j) step += rule5.w[j] * speed(m + h * rule5.x[j]);
      Lx += step * h;
    } else {
      Lx = s0 + cell_integral(c, next);
    }
    x = next;
  }
  return x;
}

}  // namespace cg::blade
