// Ownership of the geometry inside evaluators, projectors, casters, offsets and arc-length tables:
// each is built from a TEMPORARY curve or surface, the temporary is destroyed and the heap churned
// (freed blocks refilled with NaN), then its answers must equal those of one built from a live object.
// Before they owned their geometry, these read freed memory (heap-use-after-free under the sanitizers,
// NaN or garbage in Release). Equality is exact: both compute the same operations on equal data.
#define BOOST_TEST_MODULE ownership
#include <boost/test/unit_test.hpp>

#include <type_traits>
#include <vector>

#include "src/algo/offset_exact.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/algo/ray_curve.hpp"
#include "src/algo/ray_surface.hpp"
#include "src/analyze/arc_length.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/surface_evaluator.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

// Reuses recently freed heap blocks of common sizes and fills them with NaN.
void churn_heap() {
  std::vector<std::vector<double>> junk;
  for (int size = 1; size <= 2048; size = size * 3 / 2 + 1)
    for (int k = 0; k < 4; ++k) junk.emplace_back(static_cast<std::size_t>(size), std::nan(""));
}

BSplineCurve<2> curve2(unsigned long seed) {
  test::Rng r(seed);
  return test::random_curve<2>(r, 3, 9, true);
}
BSplineCurve<3> curve3(unsigned long seed) {
  test::Rng r(seed);
  return test::random_curve<3>(r, 3, 9, true);
}
BSplineSurface<3> surface(unsigned long seed) {
  test::Rng r(seed);
  return test::random_surface(r, true);
}

}  // namespace

BOOST_AUTO_TEST_CASE(evaluators_and_tables_outlive_a_temporary) {
  const auto live = curve3(1);
  CurveEvaluator<3> ev(curve3(1));
  ArcLength<3> len(curve3(1));
  const auto slive = surface(2);
  SurfaceEvaluator<3> sev(surface(2));
  churn_heap();
  CurveEvaluator<3> ref(live);
  SurfaceEvaluator<3> sref(slive);
  for (int k = 0; k <= 10; ++k) {
    const double u = live.first_param() + (live.last_param() - live.first_param()) * k / 10;
    BOOST_TEST((ev.point(u) - ref.point(u)).norm() == 0.0);
    const double v = slive.first_u() + (slive.last_u() - slive.first_u()) * k / 10;
    const double w = slive.first_v() + (slive.last_v() - slive.first_v()) * k / 10;
    BOOST_TEST((sev.point(v, w) - sref.point(v, w)).norm() == 0.0);
  }
  BOOST_TEST(len.total() == ArcLength<3>(live).total());
  BOOST_TEST(len.param_at(0.5 * len.total()) == ArcLength<3>(live).param_at(0.5 * len.total()));
  // A copy is independent of its source (value semantics).
  ArcLength<3> copy = len;
  { ArcLength<3> gone(curve3(5)); copy = gone; }
  churn_heap();
  BOOST_TEST(copy.total() == ArcLength<3>(curve3(5)).total());
}

BOOST_AUTO_TEST_CASE(projectors_casters_and_offsets_outlive_a_temporary) {
  const auto c2 = curve2(3);
  const auto c3 = curve3(4);
  const auto s = surface(6);
  CurveProjector<3> cp(curve3(4));
  SurfaceProjector sp(surface(6));
  RayCurveCaster<2> rc(curve2(3));
  RaySurfaceCaster rs(surface(6));
  ExactOffset off(curve2(3), 0.25);
  churn_heap();
  CurveProjector<3> cp_ref(c3);
  SurfaceProjector sp_ref(s);
  RayCurveCaster<2> rc_ref(c2);
  RaySurfaceCaster rs_ref(s);
  ExactOffset off_ref(c2, 0.25);
  test::Rng r(7);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d P(r.uniform(-12, 12), r.uniform(-12, 12), r.uniform(-12, 12));
    BOOST_TEST(cp.project(P).distance == cp_ref.project(P).distance);
    BOOST_TEST(sp.project(P).distance == sp_ref.project(P).distance);
    const Eigen::Vector3d d = s.point(0.5 * (s.first_u() + s.last_u()), 0.5 * (s.first_v() + s.last_v())) - P;
    BOOST_TEST(rs.first_hit(P, d).ray_param == rs_ref.first_hit(P, d).ray_param);
    const Eigen::Vector2d o(r.uniform(-12, 12), r.uniform(-12, 12));
    const Eigen::Vector2d d2 = c2.point(0.5 * (c2.first_param() + c2.last_param())) - o;
    BOOST_TEST(rc.first_hit(o, d2).ray_param == rc_ref.first_hit(o, d2).ray_param);
    const double u = r.uniform(c2.first_param(), c2.last_param());
    BOOST_TEST((off.point(u) - off_ref.point(u)).norm() == 0.0);
  }
}

// Construction from a shared curve shares it (no copy): the evaluator's curve IS the shared object.
BOOST_AUTO_TEST_CASE(shared_geometry_is_not_copied) {
  auto shared = std::make_shared<const BSplineCurve<2>>(curve2(8));
  CurveEvaluator<2> ev(shared);
  BOOST_TEST(&ev.curve() == shared.get());
  CurveEvaluator<2> copy = ev;  // independent cache, same immutable curve
  BOOST_TEST(&copy.curve() == shared.get());
  BOOST_TEST((copy.point(shared->first_param()) - ev.point(shared->first_param())).norm() == 0.0);
}
