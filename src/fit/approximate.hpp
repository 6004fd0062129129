#pragma once
// Least-squares B-spline curve approximation (The NURBS Book 9.4.1, A9.7 without weights/derivative
// constraints) and a tolerance-driven driver that refines the knot vector where the error is largest.
#include <Eigen/Core>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/fit/interpolate.hpp"

namespace cg {

/// Clamped knot vector for a least-squares fit with num_poles poles to data at `params` (eq. 9.68-9.69):
/// every knot span contains data parameters. That alone does not make the fit unique: with num_poles
/// close to params.size() the matrix can be singular (seen in random trials); up to half as many poles
/// as points it was regular in 20000 random trials. Requires degree + 1 <= num_poles <= params.size().
std::vector<double> approximation_knots(const std::vector<double>& params, int degree, int num_poles);

/// Least-squares fit (9.4.1): the curve of degree p on `knots` whose end poles are the first and last
/// data points and whose interior poles minimise sum_k |C(params[k]) - points[k]|^2 over the interior
/// points. Throws InvalidGeometry if sizes mismatch, params are not non-decreasing on the knot domain,
/// or the data do not determine the poles (Schoenberg-Whitney fails, or the least-squares matrix is
/// numerically rank deficient / conditioned beyond 1e10).
template <int Dim>
BSplineCurve<Dim> fit_least_squares(const PointList<Dim>& points, const std::vector<double>& params, int degree,
                                    const std::vector<double>& knots);

template <int Dim>
struct ApproximationResult {
  BSplineCurve<Dim> curve;
  std::vector<double> params;  ///< parameter of each data point on `curve`
  double max_error = 0;        ///< max_k |C(params[k]) - points[k]| (an upper bound of the distance)
  bool tolerance_met = false;  ///< max_error <= tolerance (false only if max_poles stopped the refinement)
};

struct ApproximationOptions {
  ParamMethod method = ParamMethod::ChordLength;
  /// Upper bound on the pole count (0 = number of points, where the fit becomes interpolation).
  int max_poles = 0;
  /// Rounds of parameter correction (Hoschek: each data parameter moved to the foot point of its
  /// point on the current fit, then refitted) after every refinement; 0 keeps the initial parameters.
  int parameter_corrections = 5;
};

/// Approximation to a tolerance: starts from a single Bezier segment (degree + 1 poles) and inserts a
/// knot in every span whose data error exceeds `tolerance` (midway between the span's two middle data
/// parameters, only where Schoenberg-Whitney stays satisfied), refitting by fit_least_squares (sparse
/// QR) until max_error <= tolerance, with parameter correction between refinements (options). A refit
/// whose residual grows (impossible in exact arithmetic, the spaces are nested: rounding in an
/// ill-conditioned system) is rejected. When refinement stalls or reaches one pole per point, falls
/// back to interpolation (error ~0). End points are reproduced exactly. Throws InvalidGeometry for
/// fewer than degree + 1 points, coincident consecutive points, degree outside [1, 25] or tolerance <= 0.
template <int Dim>
ApproximationResult<Dim> approximate(const PointList<Dim>& points, int degree, double tolerance,
                                     const ApproximationOptions& options = {});

/// Closed variant: a PERIODIC curve (period 1, C^(p-1) at the seam) fitted in the least-squares sense
/// to a closed point list (first point not repeated), refined as above; falls back to
/// interpolate_closed when refinement stalls. Throws as approximate().
template <int Dim>
ApproximationResult<Dim> approximate_closed(const PointList<Dim>& points, int degree, double tolerance,
                                            const ApproximationOptions& options = {});

#define CG_FIT_APPROXIMATE_EXTERN(D)                                                                         \
  extern template BSplineCurve<D> fit_least_squares<D>(const PointList<D>&, const std::vector<double>&, int, \
                                                       const std::vector<double>&);                          \
  extern template ApproximationResult<D> approximate<D>(const PointList<D>&, int, double,                    \
                                                        const ApproximationOptions&);                        \
  extern template ApproximationResult<D> approximate_closed<D>(const PointList<D>&, int, double,             \
                                                               const ApproximationOptions&);
CG_FIT_APPROXIMATE_EXTERN(1)
CG_FIT_APPROXIMATE_EXTERN(2)
CG_FIT_APPROXIMATE_EXTERN(3)
#undef CG_FIT_APPROXIMATE_EXTERN

}  // namespace cg
