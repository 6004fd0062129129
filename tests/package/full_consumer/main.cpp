// Converts a kernel curve to OCCT and back through the installed adaptors.
#include <cstdio>

#include <Geom_BSplineCurve.hxx>

#include "adaptors/occt_convert.hpp"
#include "src/core/bspline_curve.hpp"

int main() {
  const cg::BSplineCurve<3> c(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, 1, 2});
  const Handle(Geom_BSplineCurve) o = cg::occt::to_occt(c);
  const gp_Pnt q = o->Value(0.5);
  const auto back = cg::occt::from_occt(*o);
  const bool ok = q.Distance(gp_Pnt(0.6, 0.8, 0)) < 1e-15 && (back.point(0.5) - c.point(0.5)).norm() == 0;
  std::printf("full consumer: OCCT C(1/2) = (%.17g, %.17g): %s\n", q.X(), q.Y(), ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
