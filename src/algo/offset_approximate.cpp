#include "src/algo/offset_approximate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/algo/fillet_arc.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/fit/approximate.hpp"

namespace cg {

namespace {

// Dense verification parameters per knot span of the fit (relative positions, ends included).
constexpr int kVerifyPerDegree = 8;
constexpr int kMaxRounds = 40;

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

    // Verification against the exact offset at dense parameters of every span.
    CurveEvaluator<2> ev(fit.curve);
    std::vector<double> refine;
    const int dense = kVerifyPerDegree * (q + 1);
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1];
      if (!(b > a)) continue;
      double err = 0;
      for (int k = 0; k <= dense; ++k) {
        const double u = a + (b - a) * k / dense;
        const int side = (k == dense && b == u1) ? -1 : +1;
        err = std::max(err, (ev.point(u) - offset.point(u, side)).norm());
      }
      fit.error = std::max(fit.error, err);
      // Half the tolerance at the check points leaves room for the error between them.
      if (err > 0.5 * tol) {
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
