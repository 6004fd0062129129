#pragma once
// Arc-length tables of the iso-curves v = const of the wall surface, built many times (every span a
// cooling feature touches gets its own section, span_section.hpp).
//
// Every iso-curve has the surface's u-knots, so the Gauss nodes of its table sit at the same u on every
// span: the B-spline basis functions and their derivatives at the nodes are computed once
// (IsoArcLengthNodes) and the speed |C'(u)| at a node of any iso-curve is a sum of p + 1 homogeneous
// poles (The NURBS Book eq. 4.8 for the rational derivative). The quadrature is the first level of
// ArcLength's adaptive rule (src/analyze/arc_length.hpp): per knot span, the 10-point Gauss-Legendre
// rule on the span against the sum over its two halves, accepted when they agree to the span's share
// of rel_tol * length (or 1e-14 of the span); a span that fails is integrated by ArcLength's adaptive
// rule. The result is ArcLength's table to rounding, at a fraction of its cost.
//
// Queries inside a half span (cell) use the 10-point rule on [cell start, u]: the cell is at most half
// of a span whose 10-point rule was already within the tolerance. The inverse starts from the cubic
// Hermite interpolant of u(s) on the cell (slopes 1 / speed at the cell ends) and polishes it by
// bracketed Newton (derivative = the speed) to |length - s| <= rel_tol * length.
#include <memory>
#include <vector>

#include "src/analyze/arc_length.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade {

/// Basis functions at the Gauss nodes of one knot vector (shared by all iso-curves of a surface).
class IsoArcLengthNodes {
 public:
  /// From any curve with the knots and degree of the iso-curves (e.g. one of them).
  explicit IsoArcLengthNodes(const BSplineCurve<3>& curve);

  static constexpr int kRule = 10;                 // Gauss-Legendre points per panel
  static constexpr int kPerSpan = 3 * kRule + 3;  // whole span, left half, right half; start, middle, end
  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return knots_; }
  const std::vector<double>& breaks() const { return breaks_; }  // distinct knots in [first, last]
  const std::vector<double>& weights() const { return weights_; }  // per node, times half the panel width
  // Node k: the first pole index and the basis values and first derivatives of its p + 1 poles.
  int first_pole(std::size_t k) const { return first_pole_[k]; }
  const double* basis(std::size_t k) const { return &basis_[2 * k * static_cast<std::size_t>(degree_ + 1)]; }

 private:
  int degree_ = 0;
  std::vector<double> knots_, breaks_, weights_, basis_;
  std::vector<int> first_pole_;
};

/// Arc length table of one iso-curve (which must outlive it), with ArcLength<3>'s interface.
class IsoArcLength {
 public:
  /// Throws InvalidGeometry when the curve's knots or degree differ from the nodes'.
  IsoArcLength(const BSplineCurve<3>& curve, std::shared_ptr<const IsoArcLengthNodes> nodes,
               double rel_tol = 1e-12);
  /// Builds its own nodes (one table only: no saving over ArcLength<3>).
  explicit IsoArcLength(const BSplineCurve<3>& curve) : IsoArcLength(curve, std::make_shared<IsoArcLengthNodes>(curve)) {}

  double first() const { return cells_.front(); }
  double last() const { return cells_.back(); }
  double total() const { return cumulative_.back(); }
  /// Length from first() to u (u clamped to [first(), last()] within 1e-12 of its length).
  double length_to(double u) const;
  /// Parameter u with length_to(u) = s to rel_tol * total(). Throws InvalidGeometry outside [0, total()].
  double param_at(double s) const;
  /// param_at without its Newton polish: the cubic Hermite interpolant of u(s) on the half knot span
  /// (exact where param_at is: the ends and the adaptive spans). Within 1e-4 of the length (the wall's
  /// iso-curves of both examples: worst 7.9e-5, test_iso_arc_length) at a seventh of the cost: for
  /// scans that look for a neighbourhood and refine it exactly, never for a placement.
  double param_near(double s) const;
  /// Knot spans where the 10-point rule missed the tolerance (integrated adaptively instead).
  int adaptive_spans() const;

 private:
  struct Guess {
    std::size_t cell;
    double u;
    bool exact;  // u is the answer (an end, a degenerate cell or an adaptive span's inverse)
  };
  Guess guess(double s) const;  // throws outside [0, total()]
  double speed(double u) const;
  double cell_integral(std::size_t cell, double u) const;  // from the cell's start to u
  const BSplineCurve<3>* curve_;
  double tol_ = 0;                  // absolute tolerance
  std::vector<double> cells_;       // half knot spans: start, middle, start of the next ... last
  std::vector<double> cumulative_;  // length from first() to cells_[i]
  std::vector<double> speed_lo_, speed_hi_;  // per cell: speed at its start and end (limits from inside)
  /// Per knot span: ArcLength's adaptive table where the 10-point rule missed the tolerance, else null.
  std::vector<std::shared_ptr<const ArcLength<3>>> adaptive_;
};

}  // namespace cg::blade
