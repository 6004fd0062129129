#pragma once
// Point inversion / projection onto B-spline and NURBS curves: the GLOBAL closest point, curve ends
// included, with every parameter that attains the minimum.
//
// Method (branch and bound over Bézier pieces, then Newton):
//  1. Each knot span is kept in Bézier form (bounding_spans.hpp). By the convex hull property the
//     distance from P to the box of a piece's Cartesian poles is a lower bound of the distance to the
//     piece; pieces whose bound exceeds the best distance found are discarded.
//  2. A surviving piece is examined exactly: with D = A - wP (homogeneous numerator minus weight times
//     P), f(t) = C'(t).(C(t) - P) = h(t) / w(t)^3 with h = w D.D' - w' D.D, a polynomial of degree
//     3p-1 (2p-1 when polynomial) whose Bernstein coefficients follow from products of Bernstein
//     polynomials (Farouki & Rajan 1988). By the variation diminishing property (The NURBS Book 1.3)
//     no sign change of the coefficients means no interior critical point of the distance; exactly
//     one change from - to + means exactly one interior minimum, found by Newton's method on f with
//     f' = C''.(C-P) + |C'|^2 (The NURBS Book 6.1, eq. 6.3) inside a sign bracket (bisection
//     safeguard). Otherwise the piece is split by de Casteljau (A1.5) and both halves are examined.
//  3. A piece on which |f| is so small that the distance varies by less than the tolerance is
//     "flat" (e.g. a circle seen from its centre); its end points stand for it.
//  4. Every distinct minimum is polished by a damped Newton iteration on |C - P|^2 / 2
//     (newton::minimize, wrapping across the seam of a periodic curve), so a flat piece's end point
//     (within ~sqrt(tolerance) of the foot) becomes exact to rounding as well.
// No fixed sampling is used, so no minimum can be missed; the result is exact to rounding (distance)
// and to ~1e-15 relative (parameter, except at degenerate minima where the distance is flat).
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "src/algo/bounding_spans.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/newton.hpp"

namespace cg {

template <int Dim>
struct CurveProjection {
  using Point = Eigen::Matrix<double, Dim, 1>;
  /// False only when no curve point lies within the search radius (max_distance).
  bool found = false;
  /// Parameter of the closest point; among several equal minima, the one with the smallest distance.
  double param = 0.0;
  Point point = Point::Zero();
  /// Euclidean distance |point - P|.
  double distance = std::numeric_limits<double>::infinity();
  /// Number of distinct closest points (farther apart than merge_tolerance()) whose distance is within
  /// tolerance() of the minimum. A continuum of minima (circle centre) is represented by the end
  /// points of the Bézier pieces on which the distance is constant.
  int num_minima = 0;
  bool several_minima() const { return num_minima > 1; }
};

/// Projection with all minimising parameters (sorted ascending), as returned by project_point_on_curve.
template <int Dim>
struct CurveProjectionAll : CurveProjection<Dim> {
  std::vector<double> params;
};

/// Precomputed projection onto one curve (Bézier pieces, their boxes, a span-cached evaluator) for
/// many points. It owns a copy of the curve (through its evaluator), so it never dangles; a query
/// mutates work buffers, so one projector per thread. No heap allocation per query once the buffers
/// have grown.
template <int Dim>
class CurveProjector {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;

  /// tolerance: distance tolerance for equal minima and for pruning (<= 0: 1e-12 * (1 + diagonal of
  /// the curve's box), i.e. a few hundred ulps of the coordinates).
  explicit CurveProjector(const BSplineCurve<Dim>& curve, double tolerance = 0.0);

  /// Closest point of the curve to P. With a finite max_distance, only points within it are sought
  /// (found = false when there is none), which is faster for far points.
  CurveProjection<Dim> project(const Point& P, double max_distance = std::numeric_limits<double>::infinity());
  /// As project, and writes every minimising parameter (one per distinct closest point) to params.
  CurveProjection<Dim> project_all(const Point& P, std::vector<double>& params,
                                   double max_distance = std::numeric_limits<double>::infinity());

  double tolerance() const { return tol_; }
  double merge_tolerance() const { return merge_tol_; }
  const BSplineCurve<Dim>& curve() const { return ev_.curve(); }

 private:
  struct Candidate {
    double u, dist;
    Point point;
  };
  struct Piece {
    double a, b;
    int depth;
  };
  void consider(double u, double dist, const Point& point);
  void examine(const double* hp, double a, double b, int depth);
  void newton(double lo, double hi, double u0);
  Candidate polish(const Candidate& c);
  CurveProjection<Dim> run(const Point& P, double max_distance, std::vector<double>* params);

  CurveEvaluator<Dim> ev_;
  int p_ = 0, nspan_ = 0, hdeg_ = 0;
  bool rational_ = false;
  double tol_ = 0, merge_tol_ = 0, scale_ = 0;  // scale_: largest |coordinate| of the poles
  std::vector<double> span_a_, span_b_, span_poles_;  // span_poles_: (p+1)(Dim+1) per span
  std::vector<BoundingBox<Dim>> span_box_;
  std::vector<Point> knot_points_;    // C at span boundaries, nspan + 1
  std::vector<double> binom_p_, binom_p1_, inv_binom_h_;
  // Per-query state and work buffers (reused).
  Point P_;
  double best_ = 0;
  bool have_best_ = false;
  std::vector<Candidate> cands_;
  std::vector<std::pair<double, int>> order_;
  std::vector<Piece> stack_;
  std::vector<double> pool_;  // poles of the pieces on stack_, one block per entry
};

/// Local foot of P on the curve of `ev` from u: damped Newton on |C(u) - P|^2 / 2 (newton::minimize,
/// gradient (C - P).C', Hessian |C'|^2 + (C - P).C'') on `domain` (clamped, or wrapped when periodic),
/// accepting steps that raise the squared distance by at most value_noise (its rounding level). Returns
/// the end parameter. The shared refinement of CurveProjector and of curve-curve intersection.
template <int Dim>
double refine_foot(CurveEvaluator<Dim>& ev, const Eigen::Matrix<double, Dim, 1>& P, double u,
                   const newton::Domain<1>& domain, int max_iterations = 40, double value_noise = 0.0);

/// One-shot projection (builds a CurveProjector): closest point and all minimising parameters.
template <int Dim>
CurveProjectionAll<Dim> project_point_on_curve(const BSplineCurve<Dim>& curve,
                                               const Eigen::Matrix<double, Dim, 1>& P);

extern template class CurveProjector<1>;
extern template class CurveProjector<2>;
extern template class CurveProjector<3>;

}  // namespace cg
