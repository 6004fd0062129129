#pragma once
// Exact circular arcs as rational quadratic NURBS (The NURBS Book A7.1, section 7.5).
#include <Eigen/Core>

#include "src/core/bspline_curve.hpp"

namespace cg {

/// Arc of the circle (centre, radius) from polar angle `start` sweeping `sweep` radians
/// (counter-clockwise when sweep > 0), parametrised on [a, b]. The arc is split into
/// ceil(|sweep| / 90 deg) equal segments, each a rational quadratic with middle weight
/// cos(dtheta / 2); segments join with double knots (C0 in the parameter, G2 geometrically).
/// Throws InvalidGeometry unless radius > 0, 0 < |sweep| <= 2 pi and a < b.
Curve2 circular_arc(const Eigen::Vector2d& centre, double radius, double start, double sweep, double a = 0.0,
                    double b = 1.0);

}  // namespace cg
