// Modification operations: textbook values (The NURBS Book Ex. 5.1, the "insert u = 0.5" example, the
// quadratic -> cubic Bézier elevation from /work/shared/notes/kernel-references.md), properties (Bézier
// segments reproduce the curve, partition of unity of the refined/elevated basis, affine invariance,
// reparametrisation, refinement == repeated insertion, periodic curves stay periodic) and error reporting.
// Tolerances: 1e-12 of the pole scale for shape comparisons (a few ulps of the largest term, see
// test_modify_helpers.hpp); textbook values to the digits they are quoted with.
#define BOOST_TEST_MODULE modify_properties
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "src/core/error.hpp"
#include "src/modify/bezier_decomposition.hpp"
#include "src/modify/degree_elevation.hpp"
#include "src/modify/knot_insertion.hpp"
#include "src/modify/periodic_conversion.hpp"
#include "src/modify/reparametrize.hpp"
#include "src/modify/split.hpp"
#include "src/modify/transform.hpp"
#include "test_modify_helpers.hpp"

using namespace cg;
using test::kPoleTol;

namespace {

// True when f() throws InvalidGeometry whose message contains `needle`.
template <class F>
bool throws_with(F f, const std::string& needle) {
  try {
    f();
  } catch (const InvalidGeometry& e) {
    return std::string(e.what()).find(needle) != std::string::npos;
  }
  return false;
}

const std::vector<Eigen::Vector2d> kBookPoles = {{5, 5}, {10, 10}, {20, 15}, {35, 15}, {45, 10}, {50, 5}};
const std::vector<double> kBookKnots = {0, 0, 0, 0, 0.33, 0.66, 1, 1, 1, 1};

}  // namespace

BOOST_AUTO_TEST_CASE(textbook_example_5_1_alphas) {
  // p = 3, U = {0,0,0,0,1,2,3,4,5,5,5,5}, insert 5/2 (span 5): Q_i = a_i P_i + (1 - a_i) P_{i-1} with
  // a_3 = 5/6, a_4 = 1/2, a_5 = 1/6. With 1D poles P_i = i, Q_i = i - 1 + a_i reads the alphas off.
  std::vector<Eigen::Matrix<double, 1, 1>> P(8);
  for (int i = 0; i < 8; ++i) P[static_cast<std::size_t>(i)][0] = i;
  const BSplineCurve<1> c(3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5}, P);
  const auto q = insert_knot(c, 2.5);
  BOOST_TEST(q.num_poles() == 9);
  const double expected[9] = {0, 1, 2, 2 + 5.0 / 6, 3 + 0.5, 4 + 1.0 / 6, 5, 6, 7};
  for (int i = 0; i < 9; ++i) BOOST_TEST(q.pole(i)[0] == expected[i], boost::test_tools::tolerance(1e-15));
  BOOST_TEST(q.knots() == (std::vector<double>{0, 0, 0, 0, 1, 2, 2.5, 3, 4, 5, 5, 5, 5}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(textbook_insert_half) {
  const BSplineCurve<2> c(3, kBookKnots, kBookPoles);
  const auto q = insert_knot(c, 0.5);
  const std::vector<Eigen::Vector2d> expected = {{5, 5},           {10, 10},          {17.5757576, 13.7878788}, {27.5, 15},
                                                 {37.5373134, 13.7313433}, {45, 10}, {50, 5}};
  BOOST_TEST(q.knots() == (std::vector<double>{0, 0, 0, 0, 0.33, 0.5, 0.66, 1, 1, 1, 1}), boost::test_tools::per_element());
  BOOST_TEST(q.num_poles() == 7);
  for (int i = 0; i < 7; ++i)  // quoted to 7 decimals
    BOOST_TEST((q.pole(i) - expected[static_cast<std::size_t>(i)]).norm() <= 1e-7);
  for (double u : {0.0, 0.1, 0.3, 0.5, 0.6, 0.9, 1.0}) BOOST_TEST((q.point(u) - c.point(u)).norm() <= 1e-12 * 50);
}

BOOST_AUTO_TEST_CASE(textbook_quadratic_to_cubic_bezier) {
  const BSplineCurve<3> c(2, {0, 0, 0, 1, 1, 1}, {{5.2, 5.2, 5}, {5.4, 4.8, 0}, {5.2, 5.2, -5}});
  const auto e = elevate_degree(c, 1);
  BOOST_TEST(e.degree() == 3);
  BOOST_TEST(e.num_poles() == 4);
  // Exact values: Q1 = (P0 + 2 P1) / 3, Q2 = (2 P1 + P2) / 3.
  const std::vector<Eigen::Vector3d> expected = {
      {5.2, 5.2, 5}, {16.0 / 3, 14.8 / 3, 5.0 / 3}, {16.0 / 3, 14.8 / 3, -5.0 / 3}, {5.2, 5.2, -5}};
  for (int i = 0; i < 4; ++i) BOOST_TEST((e.pole(i) - expected[static_cast<std::size_t>(i)]).norm() <= 1e-14);
  BOOST_TEST((e.pole(1) - Eigen::Vector3d(5.333333, 4.933333, 1.666667)).norm() <= 1e-6);  // as quoted
}

BOOST_AUTO_TEST_CASE(bezier_segments_reproduce_the_curve) {
  test::Rng r(201);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_case_curve<3>(r, i);
    const auto d = decompose_to_bezier(c);
    const int p = c.degree();
    // Breaks are the distinct knots of the domain.
    std::vector<double> dom(c.knots().begin() + p, c.knots().begin() + c.num_poles() + 1);
    const auto distinct = distinct_knots(dom).values;
    BOOST_TEST(d.breaks == distinct, boost::test_tools::per_element());
    BOOST_TEST(d.segments.size() + 1 == d.breaks.size());
    const double scale = test::pole_scale(c);
    double err = 0;
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
      BOOST_TEST(d.segments[k].degree() == p);
      // Parameter u first, then its segment parameter t: t's rounding error is a few ulps of 1, which the
      // segment's derivative (~ p |P|) turns into a few ulps of |P|; evaluating at a rounded u instead would
      // multiply ulp(u) by |C'| ~ p |P| / span, far larger on short spans.
      for (double f : {0.0, 0.2, 0.5, 0.77, 1.0}) {
        const double u = f == 1.0 ? d.breaks[k + 1] : d.breaks[k] + f * (d.breaks[k + 1] - d.breaks[k]);
        const double t = (u - d.breaks[k]) / (d.breaks[k + 1] - d.breaks[k]);
        err = std::max(err, (d.segments[k].point(t) - c.point(u)).norm() / scale);
      }
    }
    BOOST_TEST(err <= kPoleTol, "case " << i << " error " << err);
  }
}

BOOST_AUTO_TEST_CASE(partition_of_unity_after_every_operation) {
  // All poles equal to c0 (random weights): the curve is c0 everywhere iff the basis sums to one, so
  // every pole of every derived representation must be c0 again.
  test::Rng r(202);
  for (int i = 0; i < 300; ++i) {
    auto base = test::random_case_curve<2>(r, i);
    const Eigen::Vector2d c0(r.uniform(-10, 10), r.uniform(-10, 10));
    auto h = base.homogeneous_poles();
    for (int k = 0; k < h.cols(); ++k) h.col(k).head<2>() = h(2, k) * c0;
    const auto c = BSplineCurve<2>::from_homogeneous(base.degree(), base.knots(), h, base.is_periodic());
    const double tol = 1e-13 * c0.norm();
    auto all_c0 = [&](const BSplineCurve<2>& q) {
      double e = 0;
      for (int k = 0; k < q.num_poles(); ++k) e = std::max(e, (q.pole(k) - c0).norm());
      return e <= tol;
    };
    const double u = r.uniform(c.first_param(), c.last_param());
    BOOST_TEST(all_c0(insert_knot(c, u, 1)));
    BOOST_TEST(all_c0(refine_knots(c, std::vector<double>(static_cast<std::size_t>(std::min(2, c.degree())), u))));
    BOOST_TEST(all_c0(elevate_degree(c, r.integer(1, 3))));
    const auto halves = split(c, u);
    BOOST_TEST(all_c0(halves.first));
    BOOST_TEST(all_c0(halves.second));
    for (const auto& s : decompose_to_bezier(c).segments)
      for (int k = 0; k <= s.degree(); ++k) BOOST_TEST((s.pole(k) - c0).norm() <= tol);
  }
}

BOOST_AUTO_TEST_CASE(affine_invariance_general_matrix) {
  test::Rng r(203);
  for (int i = 0; i < 300; ++i) {
    const auto c = test::random_case_curve<3>(r, i);
    Eigen::Matrix3d A;
    for (int k = 0; k < 9; ++k) A(k / 3, k % 3) = r.uniform(-2, 2);  // shear and non-uniform scale included
    const Eigen::Vector3d t(r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5));
    const auto m = transformed(c, A, t);
    BOOST_TEST(m.is_periodic() == c.is_periodic());
    const double scale = test::pole_scale(m) + A.norm() * test::pole_scale(c);
    BOOST_TEST(test::max_relative_deviation([&](double u) { return m.point(u); },
                                            [&](double u) { return (A * c.point(u) + t).eval(); }, c.first_param(),
                                            c.last_param(), scale) <= kPoleTol);
    for (int k = 0; k < c.num_poles(); ++k) BOOST_TEST(m.weight(k) == c.weight(k));
    // The Eigen::Transform overload is the same map.
    Eigen::Transform<double, 3, Eigen::Affine> T = Eigen::Transform<double, 3, Eigen::Affine>::Identity();
    T.linear() = A;
    T.translation() = t;
    BOOST_TEST(test::representation_difference(transformed(c, T), m) == "");
  }
  // 1D and 2D instantiations.
  std::vector<Eigen::Matrix<double, 1, 1>> P1(4);
  for (int k = 0; k < 4; ++k) P1[static_cast<std::size_t>(k)][0] = k * k;
  const BSplineCurve<1> c1(2, {0, 0, 0, 0.5, 1, 1, 1}, P1, {1, 2, 1, 3});
  const auto m1 = transformed(c1, Eigen::Matrix<double, 1, 1>(-2.0), Eigen::Matrix<double, 1, 1>(3.0));
  BOOST_TEST(std::abs(m1.point(0.3)[0] - (-2.0 * c1.point(0.3)[0] + 3.0)) <= 1e-14 * 20);
}

BOOST_AUTO_TEST_CASE(reparametrisation_and_reversal) {
  test::Rng r(204);
  for (int i = 0; i < 500; ++i) {
    const auto c = test::random_case_curve<2>(r, i);
    const double a = r.uniform(-100, 100), b = a + r.uniform(1e-3, 50);
    const auto m = reparametrized(c, a, b);
    BOOST_TEST(m.first_param() == a);
    BOOST_TEST(m.is_periodic() == c.is_periodic());
    if (!c.is_periodic()) BOOST_TEST(m.last_param() == b);
    // Same poles, knots mapped affinely; then the same points at corresponding knots (exact parameters:
    // a rounded interior parameter would be amplified by |C'| ~ p |P| / span, see the Bezier test).
    const double f = c.first_param(), l = c.last_param();
    BOOST_TEST((m.homogeneous_poles() - c.homogeneous_poles()).norm() == 0.0);
    const double ktol = 1e-14 * (std::abs(a) + std::abs(b));
    double kerr = 0, perr = 0;
    for (std::size_t k = 0; k < c.knots().size(); ++k) {
      kerr = std::max(kerr, std::abs(m.knots()[k] - (a + (c.knots()[k] - f) * (b - a) / (l - f))));
      const double u = c.knots()[k], sk = m.knots()[k];
      if (u >= f && u <= l && sk >= m.first_param() && sk <= m.last_param())
        perr = std::max(perr, (m.point(sk) - c.point(u)).norm() / test::pole_scale(c));
    }
    BOOST_TEST(kerr <= ktol);
    BOOST_TEST(perr <= kPoleTol);
    // Reversing twice gives the curve back.
    BOOST_TEST(test::representation_difference(reversed(reversed(c)), c) == "");
  }
}

BOOST_AUTO_TEST_CASE(refinement_equals_repeated_insertion_and_periodic_stays_periodic) {
  test::Rng r(205);
  for (int i = 0; i < 500; ++i) {
    const auto c = test::random_case_curve<3>(r, i);
    std::vector<double> X;
    for (int k = r.integer(1, 4); k > 0; --k) X.push_back(r.uniform(c.first_param(), c.last_param()));
    std::sort(X.begin(), X.end());
    auto seq = c;
    for (double x : X) seq = insert_knot(seq, x);
    const auto ref = refine_knots(c, X);
    BOOST_TEST(test::representation_difference(ref, seq) == "");
    BOOST_TEST(ref.is_periodic() == c.is_periodic());
    BOOST_TEST(ref.num_poles() == c.num_poles() + static_cast<int>(X.size()));
    if (c.is_periodic()) {
      // The seam knot itself can be inserted; it stays the first knot of the period.
      const int s = knot_multiplicity(c.knots(), c.first_param());
      if (s < c.degree()) {
        const auto q = insert_knot(c, c.first_param());
        BOOST_TEST(q.is_periodic());
        BOOST_TEST(knot_multiplicity(q.knots(), q.first_param()) == s + 1);
        BOOST_TEST(test::max_relative_deviation([&](double u) { return q.point(u); }, [&](double u) { return c.point(u); },
                                                c.first_param(), c.last_param(), test::pole_scale(c)) <= kPoleTol);
      }
      // A parameter one period away is the same knot.
      const double u = r.uniform(c.first_param(), c.last_param());
      BOOST_TEST(test::representation_difference(insert_knot(c, u + c.period()), insert_knot(c, u)) == "");
    }
  }
}

BOOST_AUTO_TEST_CASE(errors_name_the_quantity) {
  const BSplineCurve<2> c(3, kBookKnots, kBookPoles);
  const auto twice = insert_knot(c, 0.33, 2);  // 0.33 now has multiplicity 3 = degree
  BOOST_TEST(throws_with([&] { insert_knot(twice, 0.33); }, "multiplicity 4"));
  BOOST_TEST(throws_with([&] { insert_knot(c, 0.5, 4); }, "more than the degree 3"));
  BOOST_TEST(throws_with([&] { insert_knot(c, 0.0); }, "multiplicity"));  // clamped end knot
  BOOST_TEST(throws_with([&] { insert_knot(c, 1.5); }, "outside the domain"));
  BOOST_TEST(throws_with([&] { insert_knot(c, -0.1); }, "outside the domain"));
  BOOST_TEST(throws_with([&] { insert_knot(c, std::numeric_limits<double>::quiet_NaN()); }, "not finite"));
  BOOST_TEST(throws_with([&] { insert_knot(c, 0.5, 0); }, "must be >= 1"));
  BOOST_TEST(throws_with([&] { refine_knots(c, {0.6, 0.4}); }, "non-decreasing"));
  BOOST_TEST(throws_with([&] { refine_knots(c, {0.5, 0.5, 0.5, 0.5}); }, "multiplicity 4"));
  BOOST_TEST(throws_with([&] { elevate_degree(c, 0); }, "must be >= 1"));
  BOOST_TEST(throws_with([&] { elevate_degree(c, kMaxDegree); }, "exceeds the maximum"));
  BOOST_TEST(throws_with([&] { split(c, 0.0); }, "strictly inside"));
  BOOST_TEST(throws_with([&] { split(c, 1.0); }, "strictly inside"));
  BOOST_TEST(throws_with([&] { segment(c, 0.5, 0.5); }, "a < b"));
  BOOST_TEST(throws_with([&] { segment(c, 0.2, 1.5); }, "outside the domain"));
  BOOST_TEST(throws_with([&] { reparametrized(c, 2.0, 1.0); }, "a < b"));
  BOOST_TEST(throws_with([&] { transformed(c, Eigen::Matrix2d(Eigen::Matrix2d::Constant(std::nan(""))), Eigen::Vector2d(Eigen::Vector2d::Zero())); },
                         "non-finite"));
  const auto periodic = BSplineCurve<2>::periodic(2, {0, 1, 2, 3}, 4.0, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  BOOST_TEST(throws_with([&] { segment(periodic, 0.5, 4.6); }, "exceeds the period"));
  BOOST_TEST(segment(periodic, 3.5, 4.5).last_param() == 4.5);  // across the seam is fine
  test::Rng r(206);
  const auto s = test::random_surface(r, true);
  BOOST_TEST(throws_with([&] { insert_knot_u(s, s.first_u()); }, "multiplicity"));
  BOOST_TEST(throws_with([&] { insert_knot_v(s, s.last_v() + 1); }, "outside the domain"));
  BOOST_TEST(throws_with([&] { elevate_degree_v(s, 0); }, "must be >= 1"));
}
