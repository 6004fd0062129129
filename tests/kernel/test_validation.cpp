// Input validation of the core data classes and evaluators: every invalid definition or parameter
// throws cg::InvalidGeometry whose message names the problem (checked by a substring), parameters
// within the documented tolerance (1e-12 of the domain length) are accepted, and periodic geometry
// wraps parameters from any period onto the base period (1e-12 relative to the pole scale: the
// wrapped parameter differs from the original by a few ulps of u, times |C'|).
#define BOOST_TEST_MODULE validation
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/core/knots.hpp"
#include "src/core/surface_evaluator.hpp"
#include "support/eval_scales.hpp"
#include "support/random_geometry.hpp"
#include "support/random_periodic.hpp"

using namespace cg;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// True when f throws InvalidGeometry whose message contains `what`; reports the message otherwise.
bool throws_with(const std::function<void()>& f, const std::string& what) {
  try {
    f();
  } catch (const InvalidGeometry& e) {
    const std::string msg = e.what();
    if (msg.find(what) != std::string::npos) return true;
    BOOST_TEST_MESSAGE("message \"" << msg << "\" does not contain \"" << what << "\"");
    return false;
  } catch (...) {
    BOOST_TEST_MESSAGE("threw something other than InvalidGeometry");
    return false;
  }
  BOOST_TEST_MESSAGE("did not throw (expected \"" << what << "\")");
  return false;
}

const std::vector<V2> kPoles{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
const std::vector<double> kKnots{0, 0, 0, 0, 1, 1, 1, 1};  // cubic Bezier on [0, 1]

BSplineCurve<2> cubic() { return BSplineCurve<2>(3, kKnots, kPoles); }

std::vector<std::vector<V3>> grid(int nu, int nv) {
  std::vector<std::vector<V3>> P(static_cast<std::size_t>(nu), std::vector<V3>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = V3(i, j, (i * j) % 3);
  return P;
}

BSplineSurface<3> bicubic() { return BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 5), grid(5, 5)); }

}  // namespace

BOOST_AUTO_TEST_CASE(knot_vector_errors) {
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 0, 0.7, 0.5, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}); },
                         "non-decreasing"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 1, 1, 1, 1}, kPoles); }, "knot count 7"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, kPoles); }, "knot count 9"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 0, kNaN, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}); },
                         "not finite"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 0, 0, 0, 0, 0}, kPoles); }, "empty parameter domain"));
  // Interior multiplicity 3 > degree 2 would make the curve discontinuous.
  BOOST_TEST(throws_with([] { BSplineCurve<2>(2, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}}); },
                         "multiplicity 3, allowed at most 2"));
  // End multiplicity degree + 2 is too much as well.
  BOOST_TEST(throws_with([] { BSplineCurve<2>(1, {0, 0, 0, 1, 1}, {{0, 0}, {1, 1}, {2, 2}}); }, "multiplicity 3"));
  // Interior multiplicity == degree is valid.
  BOOST_CHECK_NO_THROW(BSplineCurve<2>(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}));
}

BOOST_AUTO_TEST_CASE(pole_weight_and_degree_errors) {
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, {{0, 0}, {1, 2}, {3, 2}, {4, 0}, {5, 1}}); },
                         "knot count 8 must equal poles + degree + 1 = 9"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 2}}); }, "at least degree + 1 = 4 poles, got 2"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, kPoles, {1, 1, 1}); }, "weight count 3 must equal pole count 4"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, kPoles, {1, 0.0, 1, 1}); }, "must be positive"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, kPoles, {1, -2, 1, 1}); }, "must be positive"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, kPoles, {1, kNaN, 1, 1}); }, "positive and finite"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, kPoles, {1, kInf, 1, 1}); }, "positive and finite"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(3, kKnots, {{0, 0}, {1, kNaN}, {3, 2}, {4, 0}}); }, "pole 1 is not finite"));
  BOOST_TEST(throws_with([] { BSplineCurve<2>(0, {0, 1, 2, 3}, {{0, 0}, {1, 1}, {2, 2}}); }, "degree 0 out of range [1, 25]"));
  std::vector<V2> many(40, V2(1, 1));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>(26, uniform_clamped_knots(25, 40), many); }, "degree 26 out of range [1, 25]"));
  BOOST_CHECK_NO_THROW(BSplineCurve<2>(25, uniform_clamped_knots(25, 40), many));
}

BOOST_AUTO_TEST_CASE(surface_definition_errors) {
  auto P = grid(5, 5);
  P[2].pop_back();
  BOOST_TEST(throws_with([&] { BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 5), P); },
                         "surface pole row 2 has 4 poles, expected 5"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 5), grid(5, 5),
                                                std::vector<std::vector<double>>(4, std::vector<double>(5, 1.0))); },
                         "weight rows"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 5), grid(5, 5),
                                                std::vector<std::vector<double>>(5, std::vector<double>(4, 1.0))); },
                         "weight row"));
  std::vector<std::vector<double>> W(5, std::vector<double>(5, 1.0));
  W[1][3] = 0.0;
  BOOST_TEST(throws_with([&] { BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 5), grid(5, 5), W); },
                         "must be positive"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(3, 3, uniform_clamped_knots(3, 5), uniform_clamped_knots(3, 6), grid(5, 5)); },
                         "knot count"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(0, 3, {0, 1, 2, 3, 4, 5}, uniform_clamped_knots(3, 5), grid(5, 5)); },
                         "degree 0"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(3, 3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1}, uniform_clamped_knots(3, 5),
                                                grid(8, 5)); },
                         "multiplicity 4"));
  BOOST_TEST(throws_with([] {
    BSplineSurface<3>::from_homogeneous(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, BSplineSurface<3>::HPoles::Ones(4, 3));
  }, "nu * nv"));
}

BOOST_AUTO_TEST_CASE(curve_parameters_outside_the_domain) {
  const auto c = cubic();
  const double eps = 1e-12;  // documented tolerance, relative to the domain length 1
  for (double u : {-1e-9, 1.0 + 1e-9, 5.0, -3.0, kNaN, kInf, -kInf}) {
    BOOST_TEST(throws_with([&] { c.point(u); }, u != u || std::isinf(u) ? "not finite" : "outside the curve domain [0"));
    BOOST_TEST(throws_with([&] { c.derivatives(u, 2); }, u != u || std::isinf(u) ? "not finite" : "outside"));
    CurveEvaluator<2> ev(c);
    BOOST_TEST(throws_with([&] { ev.point(u); }, "outside the curve domain"));
    V2 P, D1, D2;
    BOOST_TEST(throws_with([&] { ev.d1(u, P, D1); }, "outside"));
    BOOST_TEST(throws_with([&] { ev.d2(u, P, D1, D2); }, "outside"));
    // Batched: a bad parameter after good ones still throws.
    const double us[3] = {0.2, 0.5, u};
    V2 out[3];
    BOOST_TEST(throws_with([&] { ev.points(us, 3, out); }, "outside"));
  }
  // Just inside the tolerance: accepted, and the value is the end point (to 1e-12 of the pole scale 4).
  CurveEvaluator<2> ev(c);
  for (double u : {-0.5 * eps, 1.0 + 0.5 * eps}) {
    const V2 end = u < 0.5 ? kPoles.front() : kPoles.back();
    BOOST_CHECK_NO_THROW(c.point(u));
    BOOST_TEST((c.point(u) - end).norm() <= 1e-12 * 4);
    BOOST_TEST((ev.point(u) - end).norm() <= 1e-12 * 4);
    BOOST_TEST((c.derivatives(u, 1)[0] - end).norm() <= 1e-12 * 4);
  }
  // Just outside it: rejected.
  BOOST_TEST(throws_with([&] { c.point(1.0 + 2 * eps); }, "outside"));
  BOOST_TEST(throws_with([&] { ev.point(-2 * eps); }, "outside"));
  BOOST_TEST(throws_with([&] { c.derivatives(0.5, -1); }, "derivative order"));
}

BOOST_AUTO_TEST_CASE(surface_parameters_outside_the_domain) {
  const auto s = bicubic();
  SurfaceEvaluator<3> ev(s);
  const double eps = 1e-12;
  for (const auto& uv : std::vector<std::array<double, 2>>{{-1e-9, 0.5}, {0.5, 1 + 1e-9}, {2, 2}, {kNaN, 0.5}, {0.5, kInf}}) {
    const bool finite = std::isfinite(uv[0]) && std::isfinite(uv[1]);
    const std::string what = finite ? "outside" : "not finite";
    BOOST_TEST(throws_with([&] { s.point(uv[0], uv[1]); }, what));
    V3 d[4];
    BOOST_TEST(throws_with([&] { s.derivatives(uv[0], uv[1], 1, d); }, what));
    BOOST_TEST(throws_with([&] { ev.point(uv[0], uv[1]); }, what));
    V3 P, Su, Sv;
    BOOST_TEST(throws_with([&] { ev.d1(uv[0], uv[1], P, Su, Sv); }, what));
    const double pairs[4] = {0.5, 0.5, uv[0], uv[1]};
    V3 out[2];
    BOOST_TEST(throws_with([&] { ev.points(pairs, 2, out); }, what));
  }
  // Messages say which parameter.
  BOOST_TEST(throws_with([&] { s.point(0.5, 3.0); }, "surface parameter v = 3"));
  BOOST_TEST(throws_with([&] { s.point(-3.0, 0.5); }, "surface parameter u = -3"));
  // Within the tolerance: accepted and equal to the corner pole (to 1e-12 of the pole scale ~6).
  BOOST_TEST((s.point(1 + 0.5 * eps, -0.5 * eps) - V3(4, 0, 0)).norm() <= 1e-12 * 6);
  BOOST_TEST((ev.point(1 + 0.5 * eps, -0.5 * eps) - V3(4, 0, 0)).norm() <= 1e-12 * 6);
  BOOST_TEST(throws_with([&] { ev.point(1 + 2 * eps, 0.5); }, "outside"));
  BOOST_TEST(throws_with([&] { s.derivatives(0.5, 0.5, 26, nullptr); }, "derivative order"));
}

BOOST_AUTO_TEST_CASE(empty_geometry) {
  const BSplineCurve<3> empty;
  BOOST_TEST(throws_with([&] { empty.point(0.0); }, "empty curve"));
  BOOST_TEST(throws_with([&] { empty.derivatives(0.0, 1); }, "empty curve"));
  BOOST_TEST(throws_with([&] { CurveEvaluator<3> ev(empty); }, "non-empty curve"));
  const BSplineSurface<3> no_surface;
  BOOST_TEST(throws_with([&] { no_surface.point(0.0, 0.0); }, "empty surface"));
  BOOST_TEST(throws_with([&] { SurfaceEvaluator<3> ev(no_surface); }, "non-empty surface"));
  BOOST_TEST(throws_with([] { BSplineSurface<3>(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, std::vector<std::vector<V3>>{}); },
                         "surface needs poles"));
}

BOOST_AUTO_TEST_CASE(periodic_definition_errors) {
  const std::vector<V2> P{{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(3, {0, 1, 2}, 4, P); }, "as many knots per period as poles (4), got 3"));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(4, {0, 1, 2, 3}, 4, P); }, "needs at least 5 poles, got 4"));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(3, {0, 1, 2, 4.5}, 4, P); }, "within one period"));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(3, {0, 1, 2, 3}, -4, P); }, "period must be positive"));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(3, {0, 2, 1, 3}, 4, P); }, "non-decreasing"));
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::periodic(0, {0, 1, 2, 3}, 4, P); }, "degree 0 out of range"));
  // Unwrapped data whose wrap poles do not repeat the first ones.
  const auto c = BSplineCurve<2>::periodic(2, {0, 1, 2, 3}, 4, P);
  auto H = c.homogeneous_poles();
  BOOST_CHECK_NO_THROW(BSplineCurve<2>::from_homogeneous(2, c.knots(), H, true));
  H(0, c.num_poles() - 1) += 1e-3;
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::from_homogeneous(2, c.knots(), H, true); }, "repeat the first"));
  auto U = c.knots();
  U.back() += 1e-3;
  BOOST_TEST(throws_with([&] { BSplineCurve<2>::from_homogeneous(2, U, c.homogeneous_poles(), true); }, "continue by the period"));
}

BOOST_AUTO_TEST_CASE(periodic_wrapping) {
  test::Rng r(21);
  for (int i = 0; i < 200; ++i) {
    const auto c = test::random_periodic_bspline<3>(r, i % 2 == 1);
    CurveEvaluator<3> ev(c);
    const double scale = test::pole_scale(c), T = c.period();
    BOOST_TEST(c.is_closed());
    for (int k = 0; k < 5; ++k) {
      const double u = r.uniform(c.first_param(), c.last_param());
      const V3 base = c.point(u);
      for (int m : {-7, -1, 1, 3}) {
        const double w = u + m * T;
        // The wrapped parameter is off by a few ulps of |w| <= 8 T + 3: error <= |C'| * 1e-15 * |w|.
        const double tol = 1e-12 * scale * (1 + std::abs(w)) * c.degree() / T * 10;
        BOOST_TEST((c.point(w) - base).norm() <= tol);
        BOOST_TEST((ev.point(w) - base).norm() <= tol);
      }
    }
    for (double bad : {kNaN, kInf, -kInf}) {
      BOOST_TEST(throws_with([&] { c.point(bad); }, "not finite"));
      BOOST_TEST(throws_with([&] { ev.point(bad); }, "not finite"));
    }
  }
  for (int i = 0; i < 100; ++i) {
    const bool pu = i % 2 == 0, pv = i % 3 != 0;
    const auto s = test::random_periodic_surface(r, i % 4 < 2, pu, pv);
    SurfaceEvaluator<3> ev(s);
    const double Tu = s.last_u() - s.first_u(), Tv = s.last_v() - s.first_v();
    const double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
    const V3 base = s.point(u, v);
    const double wu = pu ? u - 2 * Tu : u, wv = pv ? v + 3 * Tv : v;
    const double scale = test::pole_scale(s);
    // Surface derivative scale bound as in test_evaluation_vs_occt: pole scale * 1e3 per unit of u.
    const double tol = 1e-12 * scale * 1e3 * (1 + std::abs(wu) + std::abs(wv));
    BOOST_TEST((s.point(wu, wv) - base).norm() <= tol);
    BOOST_TEST((ev.point(wu, wv) - base).norm() <= tol);
    if (!pu) BOOST_TEST(throws_with([&] { s.point(u + 2 * Tu, v); }, "outside"));
    if (!pv) BOOST_TEST(throws_with([&] { ev.point(u, v - 2 * Tv); }, "outside"));
  }
}

// A negative derivative order is invalid input like any other: a cg::Error subclass naming the
// argument ("order") and the allowed range, never std::length_error from a vector of size order + 1.
BOOST_AUTO_TEST_CASE(negative_derivative_order_is_a_cg_error) {
  const BSplineCurve<2> c = cubic();
  BOOST_TEST(throws_with([&] { c.derivatives(0.5, -2); }, "order -2"));
  BOOST_TEST(throws_with([&] { c.derivatives(0.5, -2); }, "[0, "));
  V2 out[4];
  BOOST_TEST(throws_with([&] { c.derivatives(0.5, -1, out); }, "order -1"));
  const BSplineSurface<3> s(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, grid(3, 3));
  V3 sd[9];
  BOOST_TEST(throws_with([&] { s.derivatives(0.5, 0.5, -2, sd); }, "order -2"));
  BOOST_TEST(throws_with([&] { s.derivatives(0.5, 0.5, -2, sd); }, "[0, 25]"));
}

// Numbers in messages have 4 significant digits ("1e-12", never "0.000000"), and a value just outside
// its domain gets the digits that tell it from the bound ("1.0000001 outside [0, 1]", not "1").
BOOST_AUTO_TEST_CASE(messages_print_numbers_for_people) {
  const BSplineCurve<2> c = cubic();
  CurveEvaluator<2> ev(c);
  BOOST_TEST(throws_with([&] { ev.point(1.5); }, "tolerance 1e-12"));
  BOOST_TEST(throws_with([&] { c.point(1.0000001); }, "parameter 1.0000001 outside"));
  const BSplineSurface<3> s(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, grid(3, 3));
  BOOST_TEST(throws_with([&] { s.point(0.5, -3e-9); }, "v = -3e-09 outside [0, 1]"));
}
