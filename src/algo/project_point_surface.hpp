#pragma once
// Point inversion / projection onto B-spline and NURBS surfaces: the GLOBAL closest point, boundary
// included.
//
// Method (branch and bound over Bézier patches, Newton in 2D, boundary curves):
//  1. The global minimum lies at an interior critical point of the distance, on the surface boundary,
//     or on a crease (an iso-line at a knot of multiplicity >= degree, where the surface is only C0;
//     in a periodic direction the seam is such a knot when its multiplicity is >= degree). Boundary
//     and crease iso-curves are projected with CurveProjector (global, exact).
//  2. Each knot patch is kept in Bézier form. A patch is discarded when a lower bound of its distance
//     exceeds the best distance: the distance to the box of its poles, or min_j (Q_j - P).n for a unit
//     direction n (both from the convex hull property).
//  3. With D = A - wP, S_u.(S - P) = h_u / w^3 where h_u = w D.D_u - w_u D.D is a bivariate polynomial
//     whose Bernstein coefficients follow from products of Bernstein polynomials (likewise h_v). When
//     all coefficients of h_u (or h_v) have one strict sign, the patch has no critical point (closed
//     patch) and is discarded (its minimum is on a boundary or crease, handled by step 1).
//  4. When the symmetric part of the Jacobian of (h_u, h_v) is positive definite on the whole patch
//     (bounded by Bernstein coefficients), the patch has at most one critical point; once Newton
//     converges inside the patch, the patch is resolved.
//  5. Otherwise Newton's method on grad(|S-P|^2 / 2) = 0 with the analytic Hessian
//     [S_u.S_u + S_uu.r, S_u.S_v + S_uv.r; ., S_v.S_v + S_vv.r] (The NURBS Book 6.1, eq. 6.6), damped
//     (Levenberg-Marquardt, newton::minimize), clamped to the domain and wrapped across a periodic
//     seam, gives a candidate, and the patch is split by de Casteljau along its longer direction. A
//     patch on which the distance varies by less than the tolerance (bounded from h_u, h_v) is flat:
//     its corners represent it.
//  6. Every distinct minimum found is polished by the same Newton iteration, so a foot point that came
//     from a flat patch's corner (within ~sqrt(tolerance) of the true foot) is exact to rounding too.
//     Result parameters of a periodic direction lie in [first, last).
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <vector>

#include "src/algo/bounding_spans.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/newton.hpp"

namespace cg {

struct SurfaceProjection {
  /// False only when no surface point lies within the search radius.
  bool found = false;
  double u = 0.0, v = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /// Euclidean distance |point - P|.
  double distance = std::numeric_limits<double>::infinity();
  /// Distinct closest points (farther apart than the merge tolerance) within the tolerance of the
  /// minimum; a continuum (sphere centre) is represented by patch corners.
  int num_minima = 0;
  bool several_minima() const { return num_minima > 1; }
};

/// Precomputed projection onto one surface for many points. It shares ownership of a copy of the
/// surface (never dangles); a query mutates work buffers, so one projector per thread.
class SurfaceProjector {
 public:
  /// tolerance <= 0: 1e-12 * (1 + diagonal of the surface's box).
  explicit SurfaceProjector(const BSplineSurface<3>& surface, double tolerance = 0.0);
  ~SurfaceProjector();
  SurfaceProjector(const SurfaceProjector&) = delete;
  SurfaceProjector& operator=(const SurfaceProjector&) = delete;

  SurfaceProjection project(const Eigen::Vector3d& P,
                            double max_distance = std::numeric_limits<double>::infinity());
  /// As project, and writes the (u, v) of every distinct closest point to params.
  SurfaceProjection project_all(const Eigen::Vector3d& P, std::vector<Eigen::Vector2d>& params,
                                double max_distance = std::numeric_limits<double>::infinity());

  double tolerance() const { return tol_; }
  const BSplineSurface<3>& surface() const { return *s_; }
  /// The iso-curves projected as boundaries and creases (fixed_u, value), for inspection.
  std::vector<std::pair<bool, double>> iso_curves() const;

 private:
  struct Candidate {
    double u, v, dist;
    Eigen::Vector3d point;
  };
  struct Piece {
    double u0, u1, v0, v1;
    int depth;
  };
  // An iso-curve (boundary or crease): fixed u (along_v) or fixed v, projected by its own projector.
  struct IsoCurve {
    bool fixed_u;
    double value;
    CurveProjector<3> proj;  // owns its curve
  };
  void consider(double u, double v, double dist, const Eigen::Vector3d& point);
  void examine(const double* hp, const Piece& piece);
  bool has_critical_point(const double* D, const double* w, bool along_u, double& variation,
                          std::vector<double>& out, int& rows, int& cols);
  bool single_critical_point() const;
  bool newton(double u, double v, Eigen::Vector2d& uv);
  Candidate polish(const Candidate& c);
  SurfaceProjection run(const Eigen::Vector3d& P, double max_distance, std::vector<Eigen::Vector2d>* params);

  std::shared_ptr<const BSplineSurface<3>> s_;
  int pu_ = 0, pv_ = 0, npatch_ = 0;
  bool rational_ = false;
  double tol_ = 0, merge_tol_ = 0, scale_ = 0;  // scale_: largest |coordinate| of the poles
  double umin_ = 0, umax_ = 0, vmin_ = 0, vmax_ = 0;
  newton::Domain<2> domain_;           // (u, v): clamped, or wrapped in a periodic direction
  newton::MinimizeOptions<2> newton_;  // the damped Newton iteration of steps 5 and 6
  std::vector<Piece> patch_dom_;
  std::vector<double> patch_poles_;  // (pu+1)(pv+1) x 4 per patch
  std::vector<BoundingBox<3>> patch_box_;
  std::vector<IsoCurve> iso_;
  std::vector<double> bu_, bv_, bu1_, bv1_;  // binomials C(pu,k), pu*C(pu-1,k), ...
  // Work buffers for the Bernstein products (sized in the constructor).
  std::vector<double> Ds_, Dd_, ws_, wd_, X_, Y_;
  std::vector<double> hu_, hv_;  // unscaled Bernstein coefficients of h_u, h_v of the current patch
  int hu_rows_ = 0, hu_cols_ = 0, hv_rows_ = 0, hv_cols_ = 0;
  std::vector<std::vector<double>> inv_binom_;  // 1 / C(n, k)
  Eigen::Vector3d P_;
  double best_ = 0, best_u_ = 0, best_v_ = 0;
  Eigen::Vector3d best_point_ = Eigen::Vector3d::Zero();
  bool have_best_ = false;
  std::vector<Candidate> cands_;
  std::vector<std::pair<double, int>> order_;
  std::vector<Piece> stack_;
  std::vector<double> pool_;
};

/// One-shot projection (builds a SurfaceProjector).
SurfaceProjection project_point_on_surface(const BSplineSurface<3>& surface, const Eigen::Vector3d& P);

}  // namespace cg
