#pragma once
// The edge angle of a two-thread rational Bezier net (Lang & Schroecker 1999, Sec. 2 and 5): thread 0 is
// the given curve k (degree m), thread 1 another m + 1 homogeneous points; the patch of degree (m, 1) has
// x_v(u, 0) = (Y1_c(u) Y0(u) - y_c(u) Y1_w(u)) / Y0(u)^2 (eq. 9 with n = 1, only threads 0 and 1 matter,
// Remark in Sec. 2). The angle between x_u and x_v along the edge is compared with a target
// "performance map" eta(u) = cos(angle) (eq. 17); eta = 0 asks for an orthogonal continuation.
//
// EdgeAngleSampler holds, per quadrature node u_k, everything that does not depend on thread 1, so that
// V_k = Y0_k x_v(u_k) = sum_i B_i(u_k) (q_i,c - x_k q_i,w) is linear in the thread-1 points q_i and a
// change of one point updates every V_k in O(1) (the Monte Carlo inner loop).
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "src/core/bezier_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::ortho {

/// Target cosine eta(u) of the angle between x_u and x_v along the edge (eq. 17), values in (-1, 1).
using PerformanceMap = std::function<double(double)>;
inline double orthogonal_map(double) { return 0.0; }

/// A net of two threads: the fixed curve and thread 1 (homogeneous (w p, w), kernel order).
template <int Dim>
struct ContinuationNet {
  using HPoles = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;
  BezierCurve<Dim> curve;
  HPoles thread1;
  /// The patch of degree (m, 1) on [0, 1]^2. Throws InvalidGeometry if a thread-1 weight is not positive.
  BSplineSurface<Dim> surface() const;
};

/// A start net in the spirit of Sec. 5, Step 1 ("expand it in an arbitrary way"): thread 1 is thread 0
/// translated by `distance` along the left normal of the chord p_m - p_0 (same weights). Deliberately
/// not orthogonal: the angle error at u is the tangent's turn against the chord.
ContinuationNet<2> translated_start_net(const BezierCurve<2>& curve, double distance);

/// Quadrature nodes and the thread-independent data of the score (18).
template <int Dim>
class EdgeAngleSampler {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;
  using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
  using HPoles = Eigen::Matrix<double, Dim + 1, Eigen::Dynamic>;
  using Vectors = Eigen::Matrix<double, Dim, Eigen::Dynamic>;

  /// Composite Gauss-Legendre rule: `panels` equal panels of [0, 1] with `order` <= 64 nodes each
  /// (src/analyze/gauss_legendre.hpp). eta must return values in (-1, 1).
  EdgeAngleSampler(const BezierCurve<Dim>& curve, const PerformanceMap& eta, int panels = 8, int order = 8);

  int size() const { return static_cast<int>(u_.size()); }
  int degree() const { return m_; }
  double node(int k) const { return u_[static_cast<std::size_t>(k)]; }
  double quadrature_weight(int k) const { return w_[static_cast<std::size_t>(k)]; }
  double target(int k) const { return eta_[static_cast<std::size_t>(k)]; }
  double bernstein(int i, int k) const { return B_(i, k); }
  const Point& edge_point(int k) const { return x_[static_cast<std::size_t>(k)]; }
  const Point& unit_tangent(int k) const { return t_[static_cast<std::size_t>(k)]; }

  /// V_k = Y0(u_k) x_v(u_k, 0) for the given thread 1, all k.
  void edge_vectors(const HPoles& thread1, Vectors& V) const;
  /// V_k += B_i(u_k) (dq_c - x_k dq_w): thread-1 point i moved by dq.
  void add_point_change(int i, const HPoint& dq, Vectors& V) const;
  /// cos of the angle between x_u and x_v at node k (1 when x_v vanishes: the trivial continuation).
  double cosine(int k, const Vectors& V) const;
  /// Score (18) as the squared deviation from the performance map: sum_k w_k (cos_k - eta_k)^2.
  /// (As printed, (18) integrates cos^2 - eta^2, whose eta term is a constant: minimising it would ignore
  /// eta. The text describes "the square of the deviation from the function eta", which this is.)
  double score(const Vectors& V) const;

 private:
  int m_ = 0;
  std::vector<double> u_, w_, eta_;
  Eigen::MatrixXd B_;  // (m + 1) x nodes: B_i^m(u_k)
  std::vector<Point, Eigen::aligned_allocator<Point>> x_, t_;
};

/// Angle deviation of a patch from the performance map, measured on the surface itself (the kernel's
/// surface derivatives, independent of the sampler's formula) at `samples` equally spaced u.
struct EdgeAngleStats {
  double max_deviation_deg = 0;  ///< max_u |angle(x_u, x_v) - acos(eta)|
  double rms_deviation_deg = 0;
  double max_abs_cos_error = 0;  ///< max_u |cos - eta|
  double min_speed_ratio = 0;    ///< min_u |x_v| / |x_u| (0: a degenerate, trivial continuation)
};
template <int Dim>
EdgeAngleStats measure_edge_angles(const BSplineSurface<Dim>& patch, const PerformanceMap& eta, int samples = 2001);

/// Degrees between the unit vectors with cosines c and eta: |acos(c) - acos(eta)|.
double angle_deviation_deg(double c, double eta);

extern template struct ContinuationNet<2>;
extern template struct ContinuationNet<3>;
extern template class EdgeAngleSampler<2>;
extern template class EdgeAngleSampler<3>;
extern template EdgeAngleStats measure_edge_angles<2>(const BSplineSurface<2>&, const PerformanceMap&, int);
extern template EdgeAngleStats measure_edge_angles<3>(const BSplineSurface<3>&, const PerformanceMap&, int);

}  // namespace cg::ortho
