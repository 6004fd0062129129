#pragma once
// The subdivision / Bézier-clipping engine behind intersect_curves and self_intersections (see
// intersect_curves.hpp for the method). Internal: one engine per call, not thread-safe.
#include <vector>

#include "src/algo/intersect_bezier_piece.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/core/curve_evaluator.hpp"

namespace cg::detail {

class CurvePairIntersector {
 public:
  /// self = true: a and b are the same curve, pieces are passed with x before y in parameter, and the
  /// shared end of consecutive pieces (and the seam of a closed curve) is not an intersection.
  CurvePairIntersector(const BSplineCurve<2>& a, const BSplineCurve<2>& b, double tol, bool self);

  const std::vector<BezierPiece2>& pieces_a() const { return pieces_a_; }
  const std::vector<BezierPiece2>& pieces_b() const { return pieces_b_; }

  /// Every meeting of piece x (of a) with piece y (of b).
  void intersect_pieces(const BezierPiece2& x, const BezierPiece2& y);
  /// Self mode: the loops within one piece (split until each part's tangent cone is narrow).
  void self_intersect_piece(const BezierPiece2& x);

  /// Merged, deduplicated and sorted result (self mode: trivial contacts along the curve removed).
  CurveCurveIntersections finish();

 private:
  void process(BezierPiece2 x, BezierPiece2 y);
  void process_near_miss(BezierPiece2 x, BezierPiece2 y);
  void count_work();
  bool isolated_crossing(const BezierPiece2& x, const BezierPiece2& y);
  void leaf(const BezierPiece2& x, const BezierPiece2& y);
  void end_touches(const BezierPiece2& x, const BezierPiece2& y);
  void end_touch(double s, bool s_fixed, double t);
  bool crossed_extremum(double s, double t);
  bool record_overlap(const BezierPiece2& x, const BezierPiece2& y);
  /// True when piece x (of `on`) lies within tol of `other` restricted to [lo, hi] (starting near y),
  /// monotonically along it from other(t0) to other(t1).
  bool covered(CurveEvaluator<2>& on, const BezierPiece2& x, CurveEvaluator<2>& other, const BezierPiece2& y,
               double lo, double hi, double& t0, double& t1);
  void split_and_push(const BezierPiece2& x, const BezierPiece2& y, double size_x, double size_y, bool near);
  void record(double s, double t, ContactKind kind);
  bool trivial_self_contact(double s, double t);

  struct Task {
    BezierPiece2 x, y;
    bool near;  // known not to meet: only tangential near-contacts within tol are sought
  };
  const BSplineCurve<2>& a_;
  const BSplineCurve<2>& b_;
  CurveEvaluator<2> ea_, eb_;
  std::vector<BezierPiece2> pieces_a_, pieces_b_;
  std::vector<double> ends_a_, ends_b_;  // curve ends and corners (tangent jumps), sorted
  bool self_, closed_;
  double a0_, a1_, b0_, b1_;
  double scale_, tol_, margin_, crossing_tol_, leaf_, near_floor_, trivial_radius_;
  long work_ = 0;  // piece-pair iterations, bounded by a budget
  std::vector<Task> stack_;
  std::vector<CurveCurvePoint> points_;
  std::vector<CurveCurveOverlap> overlaps_;
};

}  // namespace cg::detail
