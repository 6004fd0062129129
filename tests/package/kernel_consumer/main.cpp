// Evaluates and projects onto a quarter circle with the installed kernel; fails to compile if an OCCT
// header directory is on the include path.
#if __has_include(<Standard.hxx>)
#error "OCCT headers are visible to a kernel-only consumer"
#endif
#include <cmath>
#include <cstdio>

#include "src/algo/project_point_curve.hpp"
#include "src/core/bspline_curve.hpp"

int main() {
  const cg::BSplineCurve<2> arc(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, 1, 2});
  const Eigen::Vector2d p = arc.point(0.5);  // (3/5, 4/5), The NURBS Book Ex. 4.1
  const auto foot = cg::project_point_on_curve(arc, Eigen::Vector2d(2 * p.x(), 2 * p.y()));
  const bool ok = std::abs(p.x() - 0.6) < 1e-15 && std::abs(p.y() - 0.8) < 1e-15 && std::abs(foot.distance - 1) < 1e-14;
  std::printf("kernel consumer: C(1/2) = (%.17g, %.17g), distance %.17g: %s\n", p.x(), p.y(), foot.distance,
              ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
