#pragma once
// Global B-spline curve interpolation (The NURBS Book 9.2.1-9.2.2, A9.1) and its periodic variant.
//
// All variants reduce to one square collocation system: each row states C^(k)(t) = value for a
// given parameter t and derivative order k. The system is banded and totally positive for knots
// satisfying Schoenberg-Whitney, so an LU factorisation without special pivoting is stable; it is
// solved with Eigen::SparseLU (linear cost in the number of points).
#include <Eigen/Core>
#include <vector>

#include "src/core/bspline_curve.hpp"

namespace cg {

template <int Dim>
using PointList = std::vector<Eigen::Matrix<double, Dim, 1>>;

/// How the parameters of the data points are chosen (The NURBS Book eq. 9.4-9.6).
enum class ParamMethod {
  Uniform,      ///< equally spaced
  ChordLength,  ///< proportional to the distance between consecutive points
  Centripetal   ///< proportional to the square root of that distance (Lee 1989)
};

/// Parameters of the points on [0, 1], first 0 and last 1 (eq. 9.4-9.6).
/// closed = true: the points are a closed loop without repetition of the first point; the chord
/// from the last point back to the first counts too, so params[k] in [0, 1) and the period is 1.
/// Throws InvalidGeometry for fewer than 2 points or coincident consecutive points (within 1e-14 of
/// the polygon size, also last-to-first when closed).
template <int Dim>
std::vector<double> interpolation_parameters(const PointList<Dim>& points, ParamMethod method, bool closed = false);

/// Clamped knot vector by averaging p consecutive parameters (eq. 9.8): for n + 1 parameters,
/// degree p, n + p + 2 knots on [params.front(), params.back()].
std::vector<double> averaged_knots(const std::vector<double>& params, int degree);

/// Clamped knot vector for interpolation with both end derivatives given (eq. 9.22): n + 3 poles
/// for n + 1 parameters, interior knots averaged over windows of p parameters.
std::vector<double> averaged_knots_end_derivatives(const std::vector<double>& params, int degree);

/// Global interpolation (A9.1): the curve of degree p through points[k] at parameter params[k] with
/// the given clamped knot vector (points.size() + degree + 1 knots). Throws InvalidGeometry when the
/// sizes do not match or the parameters violate Schoenberg-Whitney (singular system).
template <int Dim>
BSplineCurve<Dim> interpolate(const PointList<Dim>& points, int degree, const std::vector<double>& params,
                              const std::vector<double>& knots);

/// Global interpolation with parameters by `method` on [0, 1] and knots by averaging (eq. 9.8).
/// Throws InvalidGeometry for degree outside [1, 25], fewer than degree + 1 points or coincident
/// consecutive points.
template <int Dim>
BSplineCurve<Dim> interpolate(const PointList<Dim>& points, int degree, ParamMethod method = ParamMethod::ChordLength);

/// Interpolation with first derivatives D0 = C'(t_0), Dn = C'(t_n) given at both ends (9.2.2): two
/// extra poles P1 = Q0 + (u_{p+1} / p) D0 and P_{n+1} = Qn - ((1 - u_{m-p-1}) / p) Dn (for [0,1]),
/// solved together with the point rows. Derivatives are with respect to the curve parameter, so
/// their length matters: for parameters on [0, 1], D ~ (polygon length) * unit tangent is natural.
/// Needs at least max(2, degree - 1) points (n + 3 >= p + 1 poles).
template <int Dim>
BSplineCurve<Dim> interpolate_end_derivatives(const PointList<Dim>& points, const Eigen::Matrix<double, Dim, 1>& d0,
                                              const Eigen::Matrix<double, Dim, 1>& dn, int degree,
                                              ParamMethod method = ParamMethod::ChordLength);

/// As above with explicit parameters and knots (points.size() + 2 + degree + 1 knots).
template <int Dim>
BSplineCurve<Dim> interpolate_end_derivatives(const PointList<Dim>& points, const Eigen::Matrix<double, Dim, 1>& d0,
                                              const Eigen::Matrix<double, Dim, 1>& dn, int degree,
                                              const std::vector<double>& params, const std::vector<double>& knots);

/// Knots of one period for periodic interpolation at periodic parameters t_0 = 0 < ... < t_{n-1} < 1
/// (period 1): odd degree, knots at the parameters; even degree, knots midway between consecutive
/// parameters (so every basis function peaks near one data point and the cyclic system is
/// well-conditioned; the classic periodic spline choice).
std::vector<double> periodic_interpolation_knots(const std::vector<double>& params, int degree);

/// Closed interpolation: a PERIODIC curve (BSplineCurve::periodic, period 1, C^(p-1) everywhere
/// including the seam) through the closed list of points (the first point NOT repeated at the end).
/// Point k lies at parameter interpolation_parameters(points, method, true)[k] (mod 1); the domain is
/// [t_0, t_0 + 1] with t_0 the first knot of periodic_interpolation_knots (0 for odd degree).
/// Throws InvalidGeometry for fewer than degree + 1 points, coincident consecutive points
/// (including last-first) or degree outside [1, 25].
template <int Dim>
BSplineCurve<Dim> interpolate_closed(const PointList<Dim>& points, int degree,
                                     ParamMethod method = ParamMethod::ChordLength);

/// Closed interpolation with explicit periodic parameters in [t, t + 1) (strictly increasing) and
/// one period of knots (size = points.size()), period 1.
template <int Dim>
BSplineCurve<Dim> interpolate_closed(const PointList<Dim>& points, int degree, const std::vector<double>& params,
                                     const std::vector<double>& period_knots);

#define CG_FIT_INTERPOLATE_EXTERN(D)                                                                                  \
  extern template std::vector<double> interpolation_parameters<D>(const PointList<D>&, ParamMethod, bool);            \
  extern template BSplineCurve<D> interpolate<D>(const PointList<D>&, int, const std::vector<double>&,                \
                                                 const std::vector<double>&);                                         \
  extern template BSplineCurve<D> interpolate<D>(const PointList<D>&, int, ParamMethod);                              \
  extern template BSplineCurve<D> interpolate_end_derivatives<D>(                                                     \
      const PointList<D>&, const Eigen::Matrix<double, D, 1>&, const Eigen::Matrix<double, D, 1>&, int, ParamMethod); \
  extern template BSplineCurve<D> interpolate_end_derivatives<D>(                                                     \
      const PointList<D>&, const Eigen::Matrix<double, D, 1>&, const Eigen::Matrix<double, D, 1>&, int,               \
      const std::vector<double>&, const std::vector<double>&);                                                        \
  extern template BSplineCurve<D> interpolate_closed<D>(const PointList<D>&, int, ParamMethod);                       \
  extern template BSplineCurve<D> interpolate_closed<D>(const PointList<D>&, int, const std::vector<double>&,         \
                                                        const std::vector<double>&);
CG_FIT_INTERPOLATE_EXTERN(1)
CG_FIT_INTERPOLATE_EXTERN(2)
CG_FIT_INTERPOLATE_EXTERN(3)
#undef CG_FIT_INTERPOLATE_EXTERN

}  // namespace cg
