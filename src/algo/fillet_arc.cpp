#include "src/algo/fillet_arc.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg {

Curve2 circular_arc(const Eigen::Vector2d& centre, double radius, double start, double sweep, double a, double b) {
  require(std::isfinite(radius) && radius > 0, "arc radius must be > 0 (got " + format_number(radius) + ")");
  require(std::isfinite(sweep) && std::abs(sweep) > 0 && std::abs(sweep) <= 2 * kPi + 1e-12,
          "arc sweep must be in (0, 2 pi] in magnitude (got " + format_number(sweep) + ")");
  require(std::isfinite(start), "arc start angle must be finite");
  require(a < b, "arc parameter range must satisfy a < b");
  // A7.1: at most 90 deg per segment keeps every middle weight >= cos 45 deg.
  const int segments = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (0.5 * kPi) - 1e-12)));
  const double dt = sweep / segments;
  const double w1 = std::cos(0.5 * dt);
  auto on_circle = [&](double t) { return Eigen::Vector2d(centre + radius * Eigen::Vector2d(std::cos(t), std::sin(t))); };
  std::vector<Eigen::Vector2d> P;
  std::vector<double> W;
  P.push_back(on_circle(start));
  W.push_back(1.0);
  for (int s = 0; s < segments; ++s) {
    const double t0 = start + s * dt, tm = t0 + 0.5 * dt;
    // The tangents at both segment ends meet on the bisector at distance r / cos(dt/2).
    P.push_back(centre + (radius / w1) * Eigen::Vector2d(std::cos(tm), std::sin(tm)));
    W.push_back(w1);
    P.push_back(s + 1 == segments ? on_circle(start + sweep) : on_circle(t0 + dt));
    W.push_back(1.0);
  }
  std::vector<double> U{a, a, a};
  for (int s = 1; s < segments; ++s) {
    const double k = a + (b - a) * s / segments;
    U.push_back(k);
    U.push_back(k);
  }
  U.insert(U.end(), {b, b, b});
  return Curve2(2, U, P, W);
}

}  // namespace cg
