// Surface modification operations against OCCT's Geom_BSplineSurface on random surfaces (polynomial and
// rational, degrees 1..5, repeated interior knots, one in four periodic in u, v or both): insertion in u/v vs
// InsertUKnot/InsertVKnot, refinement vs InsertUKnots/InsertVKnots, degree elevation vs IncreaseDegree,
// transformation vs Transform, periodic -> clamped vs SetU/VNotPeriodic. The shape must be unchanged on a
// 7 x 7 parameter grid.
// Tolerance 1e-12 of the pole scale, as for curves (test_modify_helpers.hpp): each pole row is a curve
// operation with the same alphas.
#define BOOST_TEST_MODULE modify_surfaces_vs_occt
#include <boost/test/unit_test.hpp>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>
#include <sstream>

#include "adaptors/occt_convert.hpp"
#include "src/modify/degree_elevation.hpp"
#include "src/modify/knot_insertion.hpp"
#include "src/modify/periodic_conversion.hpp"
#include "src/modify/transform.hpp"
#include "test_modify_helpers.hpp"

using namespace cg;
using test::kKnotTol;
using test::kPoleTol;

namespace {

constexpr int kCases = 1000;  // per operation and direction

double pole_scale(const BSplineSurface<3>& s) {
  double m = 0;
  for (int i = 0; i < s.num_poles_u(); ++i)
    for (int j = 0; j < s.num_poles_v(); ++j) m = std::max(m, s.pole(i, j).norm());
  return m;
}

// Empty when a and b agree in degrees, periodicity, knots, poles and weights (tolerances as for curves).
std::string surface_difference(const BSplineSurface<3>& a, const BSplineSurface<3>& b) {
  std::ostringstream os;
  if (a.degree_u() != b.degree_u() || a.degree_v() != b.degree_v()) return "degrees differ";
  if (a.is_periodic_u() != b.is_periodic_u() || a.is_periodic_v() != b.is_periodic_v()) return "periodicity differs";
  if (a.num_poles_u() != b.num_poles_u() || a.num_poles_v() != b.num_poles_v()) {
    os << "pole grid " << a.num_poles_u() << "x" << a.num_poles_v() << " vs " << b.num_poles_u() << "x" << b.num_poles_v();
    return os.str();
  }
  for (auto [ka, kb] : {std::make_pair(&a.knots_u(), &b.knots_u()), std::make_pair(&a.knots_v(), &b.knots_v())}) {
    const double ks = test::knot_scale(*kb);
    for (std::size_t i = 0; i < ka->size(); ++i)
      if (std::abs((*ka)[i] - (*kb)[i]) > kKnotTol * ks) return "knots differ";
  }
  const double ps = pole_scale(b);
  for (int i = 0; i < a.num_poles_u(); ++i)
    for (int j = 0; j < a.num_poles_v(); ++j) {
      const double dp = (a.pole(i, j) - b.pole(i, j)).norm(), dw = std::abs(a.weight(i, j) - b.weight(i, j));
      if (dp > kPoleTol * ps || dw > kPoleTol * 5.0) {
        os << "pole (" << i << "," << j << ") differs by " << dp / ps << " relative, weight by " << dw;
        return os.str();
      }
    }
  return "";
}

double shape_deviation(const BSplineSurface<3>& a, const BSplineSurface<3>& b) {
  double e = 0;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) {
      const double u = a.first_u() + (a.last_u() - a.first_u()) * i / 6.0;
      const double v = a.first_v() + (a.last_v() - a.first_v()) * j / 6.0;
      e = std::max(e, (a.point(u, v) - b.point(u, v)).norm());
    }
  return e / pole_scale(a);
}

BSplineSurface<3> random_case_surface(test::Rng& r, int i) {
  const bool rational = i % 2 == 1;
  if ((i / 2) % 4 != 3) return test::random_surface(r, rational);
  const int dirs = r.integer(1, 3);  // periodic in u, v or both
  return test::random_periodic_surface(r, rational, dirs & 1, dirs & 2);
}

// A parameter inside the domain of knots U (degree p), an existing knot of multiplicity < p in 30% of
// the cases; returns its current multiplicity in `s`.
double random_param(test::Rng& r, const std::vector<double>& U, int p, double a, double b, int& s) {
  std::vector<double> existing;
  for (double k : distinct_knots(std::vector<double>(U.begin() + p, U.end() - p)).values)
    if (k > a && k < b && knot_multiplicity(U, k) < p) existing.push_back(k);
  double u = r.uniform(a, b);
  if (!existing.empty() && r.coin(0.3)) u = existing[static_cast<std::size_t>(r.integer(0, static_cast<int>(existing.size()) - 1))];
  s = knot_multiplicity(U, u);
  return u;
}

template <class Op>
void run(unsigned long seed, Op op) {
  test::Rng r(seed);
  for (int i = 0; i < kCases; ++i) {
    const auto s = random_case_surface(r, i);
    BOOST_TEST_CONTEXT("case " << i << " degrees " << s.degree_u() << "," << s.degree_v()
                               << (s.is_periodic_u() ? " u-periodic" : "") << (s.is_periodic_v() ? " v-periodic" : "")
                               << (s.is_rational() ? " rational" : "")) {
      op(r, s);
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(knot_insertion_u_and_v_vs_occt) {
  run(101, [](test::Rng& r, const BSplineSurface<3>& s) {
    int su = 0, sv = 0;
    const double u = random_param(r, s.knots_u(), s.degree_u(), s.first_u(), s.last_u(), su);
    const double v = random_param(r, s.knots_v(), s.degree_v(), s.first_v(), s.last_v(), sv);
    const int tu = r.integer(1, s.degree_u() - su), tv = r.integer(1, s.degree_v() - sv);
    const auto mu = insert_knot_u(s, u, tu);
    const auto mv = insert_knot_v(s, v, tv);
    auto ou = occt::to_occt(s), ov = occt::to_occt(s);
    ou->InsertUKnot(u, tu, 0.0, true);
    ov->InsertVKnot(v, tv, 0.0, true);
    BOOST_TEST(surface_difference(mu, occt::from_occt(*ou)) == "");
    BOOST_TEST(surface_difference(mv, occt::from_occt(*ov)) == "");
    BOOST_TEST(shape_deviation(s, mu) <= kPoleTol);
    BOOST_TEST(shape_deviation(s, mv) <= kPoleTol);
  });
}

BOOST_AUTO_TEST_CASE(knot_refinement_u_and_v_vs_occt) {
  run(102, [](test::Rng& r, const BSplineSurface<3>& s) {
    for (bool in_u : {true, false}) {
      const auto& U = in_u ? s.knots_u() : s.knots_v();
      const int p = in_u ? s.degree_u() : s.degree_v();
      const double a = in_u ? s.first_u() : s.first_v(), b = in_u ? s.last_u() : s.last_v();
      std::vector<double> values;
      for (int k = r.integer(1, 4); k > 0; --k) {
        int m = 0;
        const double x = random_param(r, U, p, a, b, m);
        if (m < p && std::find(values.begin(), values.end(), x) == values.end()) values.push_back(x);
      }
      std::sort(values.begin(), values.end());
      std::vector<double> X;
      TColStd_Array1OfReal K(1, static_cast<int>(values.size()));
      TColStd_Array1OfInteger M(1, static_cast<int>(values.size()));
      for (std::size_t k = 0; k < values.size(); ++k) {
        const int m = r.integer(1, p - knot_multiplicity(U, values[k]));
        X.insert(X.end(), static_cast<std::size_t>(m), values[k]);
        K.SetValue(static_cast<int>(k) + 1, values[k]);
        M.SetValue(static_cast<int>(k) + 1, m);
      }
      const auto mine = in_u ? refine_knots_u(s, X) : refine_knots_v(s, X);
      auto o = occt::to_occt(s);
      if (in_u) o->InsertUKnots(K, M, 0.0, true);
      else o->InsertVKnots(K, M, 0.0, true);
      BOOST_TEST(surface_difference(mine, occt::from_occt(*o)) == "");
      BOOST_TEST(shape_deviation(s, mine) <= kPoleTol);
    }
  });
}

BOOST_AUTO_TEST_CASE(degree_elevation_u_and_v_vs_occt) {
  run(103, [](test::Rng& r, const BSplineSurface<3>& s) {
    const int tu = r.integer(1, 3), tv = r.integer(1, 3);
    const auto mu = elevate_degree_u(s, tu);
    const auto mv = elevate_degree_v(s, tv);
    BOOST_TEST(shape_deviation(s, mu) <= kPoleTol);
    BOOST_TEST(shape_deviation(s, mv) <= kPoleTol);
    BOOST_TEST(mu.degree_u() == s.degree_u() + tu);
    BOOST_TEST(mv.degree_v() == s.degree_v() + tv);
    // OCCT's periodic IncreaseDegree is unreliable (see the curve test): periodic surfaces are compared in
    // clamped form, OCCT clamping first (SetU/VNotPeriodic + Segment).
    auto reference = [&](int du, int dv) {
      auto o = occt::to_occt(s);
      if (s.is_periodic_u() || s.is_periodic_v()) {
        if (s.is_periodic_u()) o->SetUNotPeriodic();
        if (s.is_periodic_v()) o->SetVNotPeriodic();
        o->Segment(s.first_u(), s.last_u(), s.first_v(), s.last_v());
      }
      o->IncreaseDegree(s.degree_u() + du, s.degree_v() + dv);
      return occt::from_occt(*o);
    };
    const bool periodic = s.is_periodic_u() || s.is_periodic_v();
    BOOST_TEST(surface_difference(periodic ? to_non_periodic(mu) : mu, reference(tu, 0)) == "");
    BOOST_TEST(surface_difference(periodic ? to_non_periodic(mv) : mv, reference(0, tv)) == "");
    BOOST_TEST(mu.is_periodic_u() == s.is_periodic_u());
    BOOST_TEST(mv.is_periodic_v() == s.is_periodic_v());
  });
}

BOOST_AUTO_TEST_CASE(transform_vs_occt) {
  run(104, [](test::Rng& r, const BSplineSurface<3>& s) {
    gp_Trsf rot, scale, move;
    rot.SetRotation(gp_Ax1(gp_Pnt(r.uniform(-5, 5), 0, 1), gp_Dir(r.uniform(-1, 1), r.uniform(-1, 1), 1)), r.uniform(-3, 3));
    scale.SetScale(gp_Pnt(1, r.uniform(-5, 5), 2), r.uniform(0.2, 4));
    move.SetTranslation(gp_Vec(r.uniform(-20, 20), r.uniform(-20, 20), r.uniform(-20, 20)));
    const gp_Trsf T = move * scale * rot;
    Eigen::Matrix3d A;
    Eigen::Vector3d t;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(i, j) = T.Value(i + 1, j + 1);
      t[i] = T.Value(i + 1, 4);
    }
    const auto mine = transformed(s, A, t);
    auto o = occt::to_occt(s);
    o->Transform(T);
    BOOST_TEST(surface_difference(mine, occt::from_occt(*o)) == "");
    const double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
    BOOST_TEST((mine.point(u, v) - (A * s.point(u, v) + t)).norm() <= kPoleTol * pole_scale(mine));
  });
}

BOOST_AUTO_TEST_CASE(periodic_to_clamped_vs_occt) {
  test::Rng r(105);
  for (int i = 0; i < kCases; ++i) {
    const int dirs = r.integer(1, 3);
    const auto s = test::random_periodic_surface(r, i % 2 == 1, dirs & 1, dirs & 2);
    const auto mine = to_non_periodic(s);
    auto o = occt::to_occt(s);
    if (s.is_periodic_u()) o->SetUNotPeriodic();  // keeps unclamped end knots; Segment clamps them
    if (s.is_periodic_v()) o->SetVNotPeriodic();
    o->Segment(s.first_u(), s.last_u(), s.first_v(), s.last_v());
    BOOST_TEST(!mine.is_periodic_u());
    BOOST_TEST(!mine.is_periodic_v());
    BOOST_TEST(surface_difference(mine, occt::from_occt(*o)) == "");
    BOOST_TEST(shape_deviation(s, mine) <= kPoleTol);
  }
}
