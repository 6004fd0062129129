// Point and derivative evaluation (de Boor and the batched span cache) against OCCT's
// Geom_BSplineCurve / Geom2d_BSplineCurve / Geom_BSplineSurface on random curves and surfaces.
// Tolerance 1e-12 relative to the size of the derivative's scale: both sides sum the same
// O(p) products in a different order, so they agree to a few ulps of the largest term.
#define BOOST_TEST_MODULE evaluation_vs_occt
#include <boost/test/unit_test.hpp>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "adaptors/occt_convert.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/surface_evaluator.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

Eigen::Vector3d to_eigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
Eigen::Vector3d to_eigen(const gp_Pnt& v) { return {v.X(), v.Y(), v.Z()}; }
Eigen::Vector2d to_eigen(const gp_Vec2d& v) { return {v.X(), v.Y()}; }
Eigen::Vector2d to_eigen(const gp_Pnt2d& v) { return {v.X(), v.Y()}; }

// Scale of the k-th derivative: |P| * (p / shortest non-empty span)^k, times a weight-ratio factor.
template <int Dim>
double deriv_scale(const BSplineCurve<Dim>& c, int k) {
  double h = c.last_param() - c.first_param();
  const auto& U = c.knots();
  for (std::size_t i = 0; i + 1 < U.size(); ++i)
    if (U[i + 1] > U[i]) h = std::min(h, U[i + 1] - U[i]);
  double wr = 1;
  if (c.is_rational()) {
    const auto w = c.weights();
    wr = *std::max_element(w.begin(), w.end()) / *std::min_element(w.begin(), w.end());
  }
  return test::pole_scale(c) * std::pow(c.degree() * wr / h, k) * std::pow(wr, 1);
}

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

}  // namespace

BOOST_AUTO_TEST_CASE(curves_3d_random) {
  test::Rng r(1);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 1);
    compare_curve(c, *occt::to_occt(c), r);
  }
}

BOOST_AUTO_TEST_CASE(curves_2d_random) {
  test::Rng r(2);
  for (int i = 0; i < 1000; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    compare_curve(c, *occt::to_occt(c), r);
  }
}

BOOST_AUTO_TEST_CASE(surfaces_random) {
  test::Rng r(3);
  for (int i = 0; i < 1000; ++i) {
    const auto s = test::random_surface(r, i % 2 == 1);
    const auto os = occt::to_occt(s);
    SurfaceEvaluator<3> ev(s);
    double scale = 0;
    for (int a = 0; a < s.num_poles_u(); ++a)
      for (int b = 0; b < s.num_poles_v(); ++b) scale = std::max(scale, s.pole(a, b).norm());
    for (int k = 0; k < 5; ++k) {
      const double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
      gp_Pnt P;
      gp_Vec Du, Dv, Duu, Dvv, Duv;
      os->D2(u, v, P, Du, Dv, Duu, Dvv, Duv);
      Eigen::Vector3d d[9];
      s.derivatives(u, v, 2, d);
      BOOST_TEST((d[0] - to_eigen(P)).norm() <= 1e-12 * scale);
      BOOST_TEST((s.point(u, v) - to_eigen(P)).norm() <= 1e-12 * scale);
      const double ds = scale * 1e3;  // derivative scale: (degree * weight ratio / span)^k
      BOOST_TEST((d[3] - to_eigen(Du)).norm() <= 1e-12 * ds);
      BOOST_TEST((d[1] - to_eigen(Dv)).norm() <= 1e-12 * ds);
      BOOST_TEST((d[6] - to_eigen(Duu)).norm() <= 1e-12 * ds * 1e3);
      BOOST_TEST((d[2] - to_eigen(Dvv)).norm() <= 1e-12 * ds * 1e3);
      BOOST_TEST((d[4] - to_eigen(Duv)).norm() <= 1e-12 * ds * 1e3);
      Eigen::Vector3d q, qu, qv;
      ev.d1(u, v, q, qu, qv);
      BOOST_TEST((q - to_eigen(P)).norm() <= 1e-12 * scale);
      BOOST_TEST((qu - to_eigen(Du)).norm() <= 1e-12 * ds);
      BOOST_TEST((qv - to_eigen(Dv)).norm() <= 1e-12 * ds);
    }
  }
}
