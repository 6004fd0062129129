// Point and derivative evaluation (de Boor and the batched span cache) against OCCT's
// Geom_BSplineCurve / Geom2d_BSplineCurve / Geom_BSplineSurface on random curves and surfaces,
// clamped and periodic (parameters up to 3 periods outside the base period), derivative orders up
// to p + 1 (DN), and the batched evaluators against de Boor on sorted and shuffled parameters.
// Tolerance 1e-12 relative to the size of the derivative's scale: both sides sum the same
// O(p) products in a different order, so they agree to a few ulps of the largest term; orders >= 3
// get 1e-11 (each order multiplies the rounding of the previous ones by the quotient rule).
#define BOOST_TEST_MODULE evaluation_vs_occt
#include <boost/test/unit_test.hpp>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "adaptors/occt_convert.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/surface_evaluator.hpp"
#include "support/random_geometry.hpp"
#include "support/eval_scales.hpp"
#include "support/random_periodic.hpp"

#include <algorithm>

using namespace cg;
using test::deriv_scale;

namespace {

using occt::to_eigen;

template <int Dim, class OcctCurve>
void compare_curve(const BSplineCurve<Dim>& c, const OcctCurve& oc, test::Rng& r) {
  CurveEvaluator<Dim> ev(c);
  for (int s = 0; s < 8; ++s) {
    const double u = s == 0 ? c.first_param() : s == 1 ? c.last_param() : r.uniform(c.first_param(), c.last_param());
    typename std::conditional<Dim == 3, gp_Pnt, gp_Pnt2d>::type P;
    typename std::conditional<Dim == 3, gp_Vec, gp_Vec2d>::type V1, V2, V3;
    oc.D3(u, P, V1, V2, V3);
    const auto d = c.derivatives(u, 3);
    BOOST_TEST((d[0] - to_eigen(P)).norm() <= 1e-12 * deriv_scale(c, 0));
    BOOST_TEST((d[1] - to_eigen(V1)).norm() <= 1e-12 * deriv_scale(c, 1));
    BOOST_TEST((d[2] - to_eigen(V2)).norm() <= 1e-12 * deriv_scale(c, 2));
    BOOST_TEST((d[3] - to_eigen(V3)).norm() <= 1e-11 * deriv_scale(c, 3));
    typename BSplineCurve<Dim>::Point q, q1, q2;
    ev.d2(u, q, q1, q2);
    BOOST_TEST((q - to_eigen(P)).norm() <= 1e-12 * deriv_scale(c, 0));
    BOOST_TEST((q1 - to_eigen(V1)).norm() <= 1e-12 * deriv_scale(c, 1));
    BOOST_TEST((q2 - to_eigen(V2)).norm() <= 1e-12 * deriv_scale(c, 2));
  }
}

template <int Dim>
using OcctVec = typename std::conditional<Dim == 3, gp_Vec, gp_Vec2d>::type;

// All derivative orders 1..p+1 of de Boor against OCCT's DN, at parameters inside the domain or, for
// periodic curves, up to 3 periods away (both sides wrap).
template <int Dim, class OcctCurve>
void compare_all_orders(const BSplineCurve<Dim>& c, const OcctCurve& oc, test::Rng& r) {
  const int p = c.degree();
  for (int s = 0; s < 4; ++s) {
    double u = r.uniform(c.first_param(), c.last_param());
    if (c.is_periodic()) u += c.period() * r.integer(-3, 3);
    const auto d = c.derivatives(u, p + 1);
    for (int k = 1; k <= p + 1; ++k) {
      const OcctVec<Dim> v = oc.DN(u, k);
      BOOST_TEST((d[static_cast<std::size_t>(k)] - to_eigen(v)).norm() <= (k >= 3 ? 1e-11 : 1e-12) * deriv_scale(c, k),
                 "order " << k << " degree " << p << (c.is_rational() ? " rational" : ""));
    }
  }
}

// Batched evaluator (points, points_d1, points_d2) against de Boor on sorted and shuffled parameters.
template <int Dim>
void compare_batched(const BSplineCurve<Dim>& c, test::Rng& r) {
  using Point = typename BSplineCurve<Dim>::Point;
  std::vector<double> u(32);
  const double a = c.first_param(), T = c.last_param() - a;
  // Periodic: samples off the seam (derivatives are one-sided there), shifted by up to 2 periods.
  const double off = c.is_periodic() ? 0.5 : 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = a + T * (static_cast<double>(i) + off) / (u.size() - 1 + 2 * off);
  if (c.is_periodic())
    for (double& x : u) x += T * r.integer(-2, 2);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) std::shuffle(u.begin(), u.end(), r.gen);
    CurveEvaluator<Dim> ev(c);
    std::vector<Point> P(u.size()), D1(u.size()), D2(u.size()), Q(u.size()), E1(u.size());
    ev.points_d2(u.data(), u.size(), P.data(), D1.data(), D2.data());
    ev.points_d1(u.data(), u.size(), Q.data(), E1.data());
    const std::vector<Point> P0 = ev.points(u);
    for (std::size_t i = 0; i < u.size(); ++i) {
      const auto d = c.derivatives(u[i], 2);
      BOOST_TEST((P[i] - d[0]).norm() <= 1e-12 * deriv_scale(c, 0));
      BOOST_TEST((P0[i] - d[0]).norm() <= 1e-12 * deriv_scale(c, 0));
      BOOST_TEST((Q[i] - d[0]).norm() <= 1e-12 * deriv_scale(c, 0));
      BOOST_TEST((D1[i] - d[1]).norm() <= 1e-12 * deriv_scale(c, 1));
      BOOST_TEST((E1[i] - d[1]).norm() <= 1e-12 * deriv_scale(c, 1));
      BOOST_TEST((D2[i] - d[2]).norm() <= 1e-12 * deriv_scale(c, 2));
    }
  }
}


}  // namespace

BOOST_AUTO_TEST_CASE(curves_3d_random) {
  test::Rng r(1);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 1);
    const auto oc = occt::to_occt(c);
    compare_curve(c, *oc, r);
    compare_all_orders(c, *oc, r);
  }
}

BOOST_AUTO_TEST_CASE(curves_2d_random) {
  test::Rng r(2);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    const auto oc = occt::to_occt(c);
    compare_curve(c, *oc, r);
    compare_all_orders(c, *oc, r);
  }
}

BOOST_AUTO_TEST_CASE(surfaces_random) {
  test::Rng r(3);
  for (int i = 0; i < 1000; ++i) {
    const auto s = test::random_surface(r, i % 2 == 1);
    const auto os = occt::to_occt(s);
    SurfaceEvaluator<3> ev(s);
    for (int k = 0; k < 5; ++k) {
      const double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
      gp_Pnt P;
      gp_Vec Du, Dv, Duu, Dvv, Duv;
      os->D2(u, v, P, Du, Dv, Duu, Dvv, Duv);
      const auto d = s.derivatives<2>(u, v);
      // Each partial against its own scale deriv_scale(s, k, l) = |P| (p wr / h)^(k+l) wr (as for
      // curves, per direction), at 1e-12: a few ulps of the largest term of the sums.
      auto tol = [&](int k, int l) { return 1e-12 * test::deriv_scale(s, k, l); };
      BOOST_TEST((d.S() - to_eigen(P)).norm() <= tol(0, 0));
      BOOST_TEST((s.point(u, v) - to_eigen(P)).norm() <= tol(0, 0));
      BOOST_TEST((d.S_u() - to_eigen(Du)).norm() <= tol(1, 0));
      BOOST_TEST((d.S_v() - to_eigen(Dv)).norm() <= tol(0, 1));
      BOOST_TEST((d.S_uu() - to_eigen(Duu)).norm() <= tol(2, 0));
      BOOST_TEST((d.S_vv() - to_eigen(Dvv)).norm() <= tol(0, 2));
      BOOST_TEST((d.S_uv() - to_eigen(Duv)).norm() <= tol(1, 1));
      Eigen::Vector3d q, qu, qv;
      ev.d1(u, v, q, qu, qv);
      BOOST_TEST((q - to_eigen(P)).norm() <= tol(0, 0));
      BOOST_TEST((qu - to_eigen(Du)).norm() <= tol(1, 0));
      BOOST_TEST((qv - to_eigen(Dv)).norm() <= tol(0, 1));
    }
  }
}


BOOST_AUTO_TEST_CASE(periodic_curves_3d_and_2d) {
  test::Rng r(4);
  for (int i = 0; i < 1000; ++i) {
    const bool rational = i % 2 == 1;
    const auto c3 = test::random_periodic_bspline<3>(r, rational);
    const auto o3 = occt::to_occt(c3);
    compare_all_orders(c3, *o3, r);
    const auto c2 = test::random_periodic_bspline<2>(r, rational);
    compare_all_orders(c2, *occt::to_occt(c2), r);
    // Points at wrapped parameters: de Boor and the evaluator against OCCT.
    CurveEvaluator<3> ev(c3);
    for (int k = 0; k < 3; ++k) {
      const double u = r.uniform(c3.first_param(), c3.last_param()) + c3.period() * r.integer(-3, 3);
      gp_Pnt P;
      o3->D0(u, P);
      BOOST_TEST((ev.point(u) - to_eigen(P)).norm() <= 1e-12 * deriv_scale(c3, 0));
      BOOST_TEST((c3.point(u) - to_eigen(P)).norm() <= 1e-12 * deriv_scale(c3, 0));
    }
  }
}

BOOST_AUTO_TEST_CASE(batched_evaluator_matches_de_boor) {
  test::Rng r(6);
  for (int i = 0; i < 1000; ++i) {
    const bool rational = i % 2 == 1;
    // Degrees 1..7 use the compile-time-degree loops; 8..12 the generic one.
    const int p = i % 10 == 9 ? r.integer(8, 12) : r.integer(1, 7);
    compare_batched(test::random_curve<3>(r, p, r.integer(p + 1, p + 12), rational), r);
    compare_batched(test::random_curve<2>(r, p, r.integer(p + 1, p + 12), rational), r);
    compare_batched(test::random_curve<1>(r, p, r.integer(p + 1, p + 12), rational), r);
    if (i % 4 == 0) compare_batched(test::random_periodic_bspline<3>(r, rational), r);
  }
}

BOOST_AUTO_TEST_CASE(surfaces_higher_orders_and_periodic) {
  test::Rng r(7);
  for (int i = 0; i < 1000; ++i) {
    const bool rational = i % 2 == 1, pu = (i / 2) % 2 == 1, pv = (i / 4) % 2 == 1;
    const auto s = test::random_periodic_surface(r, rational, pu, pv);
    const auto os = occt::to_occt(s);
    for (int k = 0; k < 3; ++k) {
      double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
      if (pu) u += (s.last_u() - s.first_u()) * r.integer(-3, 3);
      if (pv) v += (s.last_v() - s.first_v()) * r.integer(-3, 3);
      const auto d = s.derivatives<3>(u, v);
      // Mixed partials S^(a,b), a + b <= 3, against DN, each against deriv_scale(s, a, b): 1e-12 up
      // to order 2, 1e-11 at order 3 (as for curves: the quotient rule compounds the rounding).
      for (int a = 0; a <= 3; ++a)
        for (int b = 0; a + b <= 3; ++b) {
          const Eigen::Vector3d ref = a + b == 0 ? [&] { gp_Pnt P; os->D0(u, v, P); return to_eigen(P); }()
                                                 : to_eigen(os->DN(u, v, a, b));
          BOOST_TEST((d(a, b) - ref).norm() <= (a + b >= 3 ? 1e-11 : 1e-12) * test::deriv_scale(s, a, b),
                     "S^(" << a << "," << b << ") degrees " << s.degree_u() << "," << s.degree_v());
        }
      BOOST_TEST((d.S_uuv() - to_eigen(os->DN(u, v, 2, 1))).norm() <= 1e-11 * test::deriv_scale(s, 2, 1));
      BOOST_TEST((d.S_vvv() - to_eigen(os->DN(u, v, 0, 3))).norm() <= 1e-11 * test::deriv_scale(s, 0, 3));
    }
  }
}

BOOST_AUTO_TEST_CASE(batched_surface_points_match_de_boor) {
  // Grid walked row by row (the row cache), then the same pairs shuffled; equal and unequal degrees
  // (compile-time and generic loops), periodic directions with wrapped parameters.
  test::Rng r(8);
  for (int i = 0; i < 1000; ++i) {
    const bool pu = i % 3 == 1, pv = i % 5 == 1;
    const auto s = test::random_periodic_surface(r, i % 2 == 1, pu, pv);
    const double scale = test::pole_scale(s);
    const int g = 9;
    std::vector<double> uv;
    for (int a = 0; a < g; ++a)
      for (int b = 0; b < g; ++b) {
        double u = s.first_u() + (s.last_u() - s.first_u()) * a / (g - 1);
        double v = s.first_v() + (s.last_v() - s.first_v()) * b / (g - 1);
        if (pu) u += (s.last_u() - s.first_u()) * (a % 3 - 1);
        if (pv) v += (s.last_v() - s.first_v()) * (b % 3 - 1);
        uv.push_back(u);
        uv.push_back(v);
      }
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        std::vector<std::size_t> order(uv.size() / 2);
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::shuffle(order.begin(), order.end(), r.gen);
        std::vector<double> sh;
        for (std::size_t k : order) {
          sh.push_back(uv[2 * k]);
          sh.push_back(uv[2 * k + 1]);
        }
        uv = sh;
      }
      SurfaceEvaluator<3> ev(s);
      std::vector<Eigen::Vector3d> P(uv.size() / 2);
      ev.points(uv.data(), P.size(), P.data());
      for (std::size_t k = 0; k < P.size(); ++k)
        BOOST_TEST((P[k] - s.point(uv[2 * k], uv[2 * k + 1])).norm() <= 1e-12 * scale);
    }
  }
}
