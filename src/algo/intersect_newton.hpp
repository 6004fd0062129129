#pragma once
// Newton refinements used by curve-curve intersection (the shared iterations of src/core/newton.hpp)
// on the B-spline curves themselves (span-cached evaluation with analytic first and second derivatives). Parameters are clamped to the curve domains
// after each step, so the iterates never leave them.
#include <Eigen/Core>

#include "src/core/curve_evaluator.hpp"

namespace cg::detail {

/// Newton on F(s, t) = A(s) - B(t) = 0 with the 2x2 Jacobian [A'(s), -B'(t)]. Returns true when the
/// iteration settled with |F| <= residual_tol; s, t hold the last iterate either way.
bool refine_crossing(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double residual_tol);

/// Newton on the tangential-contact system G(s, t) = ((A - B) . A', A' x B') = 0: the points where
/// the tangents are parallel and the gap is normal to them, i.e. the local extremum of |A - B| at a
/// touching or near-touching contact. Unlike min |A - B|^2, whose Hessian is singular at an exact
/// tangency (parameters only to sqrt(eps)), this system is regular when the signed curvatures differ.
/// Returns true when the iteration settled; `gap` receives |A(s) - B(t)|.
bool refine_tangency(CurveEvaluator<2>& a, CurveEvaluator<2>& b, double& s, double& t, double& gap);

/// Foot of the perpendicular from x to the curve near t within [lo, hi] (Newton on (C - x) . C' = 0,
/// clamped); returns the distance |C(t) - x| at the result.
double project_point(CurveEvaluator<2>& c, const Eigen::Vector2d& x, double& t, double lo, double hi);

}  // namespace cg::detail
