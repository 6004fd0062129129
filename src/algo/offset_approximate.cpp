#include "src/algo/offset_approximate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/algo/fillet_arc.hpp"
#include "src/analyze/derivative_bounds.hpp"
#include "src/core/bezier_ops.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/fit/approximate.hpp"

namespace cg {

namespace {

// Initial verification intervals per knot span of the fit, per degree + 1.
constexpr int kVerifyPerDegree = 8;
constexpr int kMaxRounds = 40;
// Bisection depth of one verification interval before the span counts as failed (refit with a knot).
constexpr int kMaxBisections = 10;

// Poles of the degree-p Bézier form of `c` on [a, b] (inside one knot span of c) into out.
void bezier_on(const Curve2& c, double a, double b, double* out) {
  const auto& U = c.knots();
  const int p = c.degree();
  const int s = find_span(U.data(), c.num_poles() - 1, p, 0.5 * (a + b));
  span_bezier_poles(p, U.data(), s, c.homogeneous_poles().col(s - p).data(), 3, out);
  const double lo = U[static_cast<std::size_t>(s)], len = U[static_cast<std::size_t>(s) + 1] - lo;
  restrict_bezier(p, 3, out, std::max(0.0, (a - lo) / len), std::min(1.0, (b - lo) / len));
}

// An upper bound of |F(u) - O(u)| over the fit span [a, b] (inside one base knot span, so F and the
// offset O = C + d N are smooth there), or a value above tol when none <= tol is found. The span is cut
// into intervals [x0, x1] of length h; on each, the error E = F - O is its linear interpolation between
// the end values plus a remainder of at most sqrt(2) h^2 / 8 sup|E''| (per coordinate h^2/8 sup|E_i''|,
// Atkinson, An Introduction to Numerical Analysis 3.2), so
//   |E| <= max(|E(x0)|, |E(x1)|) + sqrt(2) h^2 / 8 (sup|F''| + sup|O''|).
// sup|F''| and the base's sup|C''| and sup|C'''| over the span come from the convex hulls of the span's
// Bézier forms (bezier_derivative_bounds; computed once per span: on tiny intervals the differences of
// the poles would drown in rounding). With the tangent angle theta, N'' = -theta'' T - theta'^2 N gives
//   |O''| <= |C''| + |d| (|C'''| / |C'| + 3 |C''|^2 / |C'|^2),  inf |C'| >= |C'(mid)| - h/2 sup|C''|
// on each interval. An interval whose bound exceeds tol while its end errors are below tol / 2 is
// bisected (the remainder shrinks 4x), up to kMaxBisections times.
double verified_span_error(const Curve2& F, ExactOffset& off, double a, double b, double u1, double tol) {
  const Curve2& base = off.base();
  const int q = F.degree(), p = base.degree();
  double bez[(kMaxDegree + 1) * 3];
  bezier_on(F, a, b, bez);
  const double f2 = bezier_derivative_bounds<2>(bez, q, b - a).sup[2];
  bezier_on(base, a, b, bez);
  const DerivativeBounds bc = bezier_derivative_bounds<2>(bez, p, b - a);
  const double c2 = bc.sup[2], c3 = bc.sup[3], d = std::abs(off.distance());
  auto error_at = [&](double u) { return (F.point(u) - off.point(u, (u == b && b == u1) ? -1 : +1)).norm(); };
  auto bound = [&](double x0, double x1, double e0, double e1) {
    const double h = x1 - x0;
    Eigen::Vector2d D[2];
    base.derivatives(0.5 * (x0 + x1), 1, D);
    const double m1 = D[1].norm() - 0.5 * h * c2;
    if (!(m1 > 0)) return std::numeric_limits<double>::infinity();
    const double o2 = c2 + d * (c3 / m1 + 3 * c2 * c2 / (m1 * m1));
    return std::max(e0, e1) + std::sqrt(2.0) * h * h / 8 * (f2 + o2);
  };
  struct Interval {
    double x0, x1, e0, e1;
    int depth;
  };
  std::vector<Interval> work;
  const int n = kVerifyPerDegree * (q + 1);
  double prev = error_at(a);
  for (int k = 1; k <= n; ++k) {
    const double x0 = a + (b - a) * (k - 1) / n, x1 = k == n ? b : a + (b - a) * k / n;
    const double e1 = error_at(x1);
    work.push_back({x0, x1, prev, e1, 0});
    prev = e1;
  }
  double worst = 0;
  while (!work.empty()) {
    const Interval iv = work.back();
    work.pop_back();
    const double bnd = bound(iv.x0, iv.x1, iv.e0, iv.e1);
    if (bnd <= tol || std::max(iv.e0, iv.e1) > 0.5 * tol || iv.depth >= kMaxBisections) {
      worst = std::max(worst, bnd);
      if (worst > tol) return worst;  // the span fails: it gets a new knot
      continue;
    }
    const double m = 0.5 * (iv.x0 + iv.x1), em = error_at(m);
    work.push_back({iv.x0, m, iv.e0, em, iv.depth + 1});
    work.push_back({m, iv.x1, em, iv.e1, iv.depth + 1});
  }
  return worst;
}

}  // namespace

OffsetFit fit_offset_stretch(ExactOffset& offset, double u0, double u1, double tol) {
  const Curve2& base = offset.base();
  require(tol > 0 && std::isfinite(tol), "offset tolerance must be > 0");
  require(u0 < u1 && u0 >= base.first_param() && u1 <= base.last_param(),
          "offset stretch [u0, u1] must satisfy first <= u0 < u1 <= last of the base curve");
  const int p = base.degree();
  const int q = std::min(std::max(p, 3), kMaxDegree);

  // Interior knots: the base knots inside (u0, u1) keep their continuity (one order less).
  std::vector<double> interior;
  {
    const auto dk = distinct_knots(base.knots());
    for (std::size_t i = 0; i < dk.values.size(); ++i) {
      const double k = dk.values[i];
      // A knot within rounding of an end (a cusp snapped next to it) would make an empty span.
      if (!(k > u0 + 1e-12 * (u1 - u0) && k < u1 - 1e-12 * (u1 - u0))) continue;
      const int continuity = p - dk.mults[i] - 1;
      const int mult = std::clamp(q - continuity, 1, q);
      interior.insert(interior.end(), static_cast<std::size_t>(mult), k);
    }
  }

  PointList<2> pts;
  std::vector<double> params, knots;
  for (int round = 0; round < kMaxRounds; ++round) {
    knots.assign(static_cast<std::size_t>(q + 1), u0);
    knots.insert(knots.end(), interior.begin(), interior.end());
    knots.insert(knots.end(), static_cast<std::size_t>(q + 1), u1);

    // q + 1 interior samples per non-empty span: more data than the <= q poles each span adds, and
    // every span holds data, so the normal equations stay definite (Schoenberg-Whitney).
    params.clear();
    pts.clear();
    params.push_back(u0);
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1];
      if (!(b > a)) continue;
      for (int k = 1; k <= q + 1; ++k) params.push_back(a + (b - a) * k / (q + 2));
      params.push_back(b);
    }
    pts.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) pts.push_back(offset.point(params[i], i + 1 == params.size() ? -1 : +1));

    OffsetFit fit{fit_least_squares<2>(pts, params, q, knots), 0.0};

    // Verification against the exact offset, a bound on every span (see verified_span_error).
    std::vector<double> refine;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1];
      if (!(b > a)) continue;
      const double err = verified_span_error(fit.curve, offset, a, b, u1, tol);
      fit.error = std::max(fit.error, err);
      if (err > tol) {
        if (b - a <= 1e-12 * (u1 - u0))
          throw AlgorithmFailure("offset fit cannot reach tolerance " + format_number(tol) +
                                 " (span length at the rounding level near u = " + format_number(a) + ")");
        refine.push_back(0.5 * (a + b));
      }
    }
    if (refine.empty()) return fit;
    interior.insert(interior.end(), refine.begin(), refine.end());
    std::sort(interior.begin(), interior.end());
  }
  throw AlgorithmFailure("offset fit did not reach tolerance " + format_number(tol) + " in " +
                         std::to_string(kMaxRounds) + " refinement rounds");
}

RawOffset approximate_raw_offset(const Curve2& base, double distance, double tol) {
  require(distance != 0 && std::isfinite(distance), "offset distance must be finite and non-zero");
  require(tol > 0 && std::isfinite(tol), "offset tolerance must be > 0");
  const OffsetBreakpoints bp = offset_breakpoints(base, distance);
  ExactOffset off(base, distance);
  RawOffset raw;
  raw.distance = distance;
  raw.closed = bp.closed;

  // Joints: ends, cusps and corners (indices into bp.params).
  std::vector<int> joints{0, static_cast<int>(bp.params.size()) - 1};
  for (int c : bp.cusps) joints.push_back(c);
  for (const auto& c : bp.corners) joints.push_back(c.index);
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
  for (int c : bp.cusps) raw.cusps.push_back(bp.params[static_cast<std::size_t>(c)]);

  auto corner_arc = [&](const OffsetBreakpoints::Corner& c) {
    const double u = bp.params[static_cast<std::size_t>(c.index)];
    const bool seam = c.index == 0;
    // The offset direction d N before the corner; it turns with the tangent by c.angle.
    const Eigen::Vector2d dir = distance * off.normal(seam ? base.last_param() : u, -1);
    RawOffsetPiece piece;
    piece.kind = RawOffsetPiece::Kind::corner_arc;
    piece.u0 = piece.u1 = u;
    piece.start_angle = std::atan2(dir.y(), dir.x());
    piece.sweep = c.angle;
    piece.curve = circular_arc(base.point(u), std::abs(distance), piece.start_angle, piece.sweep);
    return piece;
  };

  const double span = base.last_param() - base.first_param();
  for (std::size_t j = 0; j + 1 < joints.size(); ++j) {
    const int ia = joints[j], ib = joints[j + 1];
    for (const auto& c : bp.corners)
      if (c.index == ia && ia != 0) raw.pieces.push_back(corner_arc(c));
    const double u0 = bp.params[static_cast<std::size_t>(ia)], u1 = bp.params[static_cast<std::size_t>(ib)];
    // A stretch at the rounding level (a cusp on a knot) has an offset of length ~|O'| 1e-13.
    if (u1 - u0 <= 1e-13 * span) continue;
    OffsetFit fit = fit_offset_stretch(off, u0, u1, tol);
    RawOffsetPiece piece;
    piece.kind = RawOffsetPiece::Kind::offset;
    piece.u0 = u0;
    piece.u1 = u1;
    piece.curve = std::move(fit.curve);
    piece.error = fit.error;
    raw.max_error = std::max(raw.max_error, fit.error);
    raw.pieces.push_back(std::move(piece));
  }
  // The seam corner of a closed base joins the last stretch to the first one.
  for (const auto& c : bp.corners)
    if (c.index == 0) raw.pieces.push_back(corner_arc(c));
  return raw;
}

}  // namespace cg
