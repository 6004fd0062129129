// Round trips through adaptors/occt_convert: ours -> OCCT -> ours and OCCT -> ours -> OCCT must give
// back the identical representation, compared BIT FOR BIT (degree, periodic and rational flags,
// knots, multiplicities, poles, weights), for random curves (2D and 3D, degrees 1..7, polynomial
// and rational, repeated knots, periodic with seam multiplicity 1..degree) and surfaces (periodic in
// u and/or v). Converted periodic geometry must also evaluate like OCCT's, including parameters
// several periods outside the base period (wrapping); tolerance 1e-12 relative to the derivative's
// scale (both sides sum the same O(p) products in a different order and wrap u by different
// formulas, each a few ulps).
#define BOOST_TEST_MODULE adaptors
#include <boost/test/unit_test.hpp>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cstdint>
#include <cstring>

#include "adaptors/occt_convert.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/surface_evaluator.hpp"
#include "support/eval_scales.hpp"
#include "support/random_geometry.hpp"
#include "support/random_periodic.hpp"

using namespace cg;
using test::deriv_scale;

namespace {

bool same_bits(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

template <class A, class B>
bool same_bits(const A& a, const B& b, int n) {
  for (int i = 0; i < n; ++i)
    if (!same_bits(a[i], b[i])) return false;
  return true;
}

// ---- ours vs ours -------------------------------------------------------------------------------

template <int Dim>
bool identical(const BSplineCurve<Dim>& a, const BSplineCurve<Dim>& b) {
  if (a.degree() != b.degree() || a.is_periodic() != b.is_periodic() || a.is_rational() != b.is_rational() ||
      a.num_poles() != b.num_poles() || a.knots().size() != b.knots().size())
    return false;
  if (!same_bits(a.knots(), b.knots(), static_cast<int>(a.knots().size()))) return false;
  for (int i = 0; i < a.num_poles(); ++i) {
    if (!same_bits(a.pole(i), b.pole(i), Dim) || !same_bits(a.weight(i), b.weight(i))) return false;
    const auto ha = a.homogeneous_poles().col(i), hb = b.homogeneous_poles().col(i);
    if (!same_bits(ha, hb, Dim + 1)) return false;
  }
  return true;
}

bool identical(const BSplineSurface<3>& a, const BSplineSurface<3>& b) {
  if (a.degree_u() != b.degree_u() || a.degree_v() != b.degree_v() || a.is_periodic_u() != b.is_periodic_u() ||
      a.is_periodic_v() != b.is_periodic_v() || a.is_rational() != b.is_rational() ||
      a.num_poles_u() != b.num_poles_u() || a.num_poles_v() != b.num_poles_v() ||
      a.knots_u().size() != b.knots_u().size() || a.knots_v().size() != b.knots_v().size())
    return false;
  if (!same_bits(a.knots_u(), b.knots_u(), static_cast<int>(a.knots_u().size())) ||
      !same_bits(a.knots_v(), b.knots_v(), static_cast<int>(a.knots_v().size())))
    return false;
  for (int i = 0; i < a.num_poles_u(); ++i)
    for (int j = 0; j < a.num_poles_v(); ++j)
      if (!same_bits(a.pole(i, j), b.pole(i, j), 3) || !same_bits(a.weight(i, j), b.weight(i, j)) ||
          !same_bits(a.homogeneous_pole(i, j), b.homogeneous_pole(i, j), 4))
        return false;
  return true;
}

// ---- OCCT vs OCCT -------------------------------------------------------------------------------

double coord(const gp_Pnt& p, int d) { return p.Coord(d + 1); }
double coord(const gp_Pnt2d& p, int d) { return p.Coord(d + 1); }

template <int Dim, class Curve>
bool identical_occt(const Curve& a, const Curve& b) {
  if (a.Degree() != b.Degree() || a.IsPeriodic() != b.IsPeriodic() || a.IsRational() != b.IsRational() ||
      a.NbKnots() != b.NbKnots() || a.NbPoles() != b.NbPoles())
    return false;
  for (int i = 1; i <= a.NbKnots(); ++i)
    if (!same_bits(a.Knot(i), b.Knot(i)) || a.Multiplicity(i) != b.Multiplicity(i)) return false;
  for (int i = 1; i <= a.NbPoles(); ++i) {
    for (int d = 0; d < Dim; ++d)
      if (!same_bits(coord(a.Pole(i), d), coord(b.Pole(i), d))) return false;
    if (!same_bits(a.Weight(i), b.Weight(i))) return false;
  }
  return true;
}

bool identical_occt(const Geom_BSplineSurface& a, const Geom_BSplineSurface& b) {
  if (a.UDegree() != b.UDegree() || a.VDegree() != b.VDegree() || a.IsUPeriodic() != b.IsUPeriodic() ||
      a.IsVPeriodic() != b.IsVPeriodic() || a.IsURational() != b.IsURational() ||
      a.IsVRational() != b.IsVRational() || a.NbUKnots() != b.NbUKnots() || a.NbVKnots() != b.NbVKnots() ||
      a.NbUPoles() != b.NbUPoles() || a.NbVPoles() != b.NbVPoles())
    return false;
  for (int i = 1; i <= a.NbUKnots(); ++i)
    if (!same_bits(a.UKnot(i), b.UKnot(i)) || a.UMultiplicity(i) != b.UMultiplicity(i)) return false;
  for (int i = 1; i <= a.NbVKnots(); ++i)
    if (!same_bits(a.VKnot(i), b.VKnot(i)) || a.VMultiplicity(i) != b.VMultiplicity(i)) return false;
  for (int i = 1; i <= a.NbUPoles(); ++i)
    for (int j = 1; j <= a.NbVPoles(); ++j) {
      for (int d = 0; d < 3; ++d)
        if (!same_bits(coord(a.Pole(i, j), d), coord(b.Pole(i, j), d))) return false;
      if (!same_bits(a.Weight(i, j), b.Weight(i, j))) return false;
    }
  return true;
}

// ---- random OCCT geometry built directly with OCCT's constructors -------------------------------

struct KnotArrays {
  TColStd_Array1OfReal values;
  TColStd_Array1OfInteger mults;
};

KnotArrays knot_arrays(const std::vector<double>& values, const std::vector<int>& mults) {
  const int k = static_cast<int>(values.size());
  KnotArrays a{TColStd_Array1OfReal(1, k), TColStd_Array1OfInteger(1, k)};
  for (int i = 0; i < k; ++i) {
    a.values.SetValue(i + 1, values[static_cast<std::size_t>(i)]);
    a.mults.SetValue(i + 1, mults[static_cast<std::size_t>(i)]);
  }
  return a;
}

// Knots of one direction, periodic (OCCT form, seam multiplicity >= 1) or clamped with repeats.
KnotArrays random_occt_knots(test::Rng& r, int p, bool periodic, int& num_poles) {
  if (periodic) {
    const test::PeriodicKnots k = test::random_periodic_knots(r, p);
    num_poles = k.num_poles();
    return knot_arrays(k.values, k.mults);
  }
  num_poles = r.integer(p + 1, p + 10);
  const DistinctKnots d = distinct_knots(test::random_knots(r, p, num_poles));
  return knot_arrays(d.values, d.mults);
}

template <int Dim>
using OcctCurve = typename std::conditional<Dim == 3, Geom_BSplineCurve, Geom2d_BSplineCurve>::type;
template <int Dim>
using OcctPoles = typename std::conditional<Dim == 3, TColgp_Array1OfPnt, TColgp_Array1OfPnt2d>::type;
template <int Dim>
using OcctPnt = typename std::conditional<Dim == 3, gp_Pnt, gp_Pnt2d>::type;

template <int Dim>
opencascade::handle<OcctCurve<Dim>> random_occt_curve(test::Rng& r, bool rational, bool periodic) {
  const int p = r.integer(1, 7);
  int n = 0;
  const KnotArrays k = random_occt_knots(r, p, periodic, n);
  OcctPoles<Dim> P(1, n);
  TColStd_Array1OfReal W(1, n);
  for (int i = 1; i <= n; ++i) {
    OcctPnt<Dim> q;
    for (int d = 0; d < Dim; ++d) q.SetCoord(d + 1, r.uniform(-10, 10));
    P.SetValue(i, q);
    W.SetValue(i, r.uniform(0.2, 5.0));
  }
  if (rational) return new OcctCurve<Dim>(P, W, k.values, k.mults, p, periodic);
  return new OcctCurve<Dim>(P, k.values, k.mults, p, periodic);
}

Handle(Geom_BSplineSurface) random_occt_surface(test::Rng& r, bool rational, bool periodic_u, bool periodic_v) {
  const int pu = r.integer(1, 5), pv = r.integer(1, 5);
  int nu = 0, nv = 0;
  const KnotArrays ku = random_occt_knots(r, pu, periodic_u, nu);
  const KnotArrays kv = random_occt_knots(r, pv, periodic_v, nv);
  TColgp_Array2OfPnt P(1, nu, 1, nv);
  TColStd_Array2OfReal W(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      P.SetValue(i, j, gp_Pnt(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10)));
      W.SetValue(i, j, r.uniform(0.2, 5.0));
    }
  if (rational)
    return new Geom_BSplineSurface(P, W, ku.values, kv.values, ku.mults, kv.mults, pu, pv, periodic_u, periodic_v);
  return new Geom_BSplineSurface(P, ku.values, kv.values, ku.mults, kv.mults, pu, pv, periodic_u, periodic_v);
}

// ---- evaluation against OCCT --------------------------------------------------------------------

using occt::to_eigen;

// Ours (de Boor, batched evaluator) against OCCT's D2 at parameters up to 3 periods outside the base
// period (periodic curves) or inside the domain.
template <int Dim>
void check_curve_evaluation(const BSplineCurve<Dim>& c, const OcctCurve<Dim>& oc, test::Rng& r) {
  CurveEvaluator<Dim> ev(c);
  const double a = c.first_param(), T = c.period();
  for (int s = 0; s < 6; ++s) {
    double u = s == 0 ? a : s == 1 ? c.last_param() : r.uniform(a, a + T);
    if (c.is_periodic() && s >= 2) u += T * r.integer(-3, 3);
    OcctPnt<Dim> P;
    typename std::conditional<Dim == 3, gp_Vec, gp_Vec2d>::type V1, V2;
    oc.D2(u, P, V1, V2);
    const auto d = c.derivatives(u, 2);
    typename BSplineCurve<Dim>::Point q, q1, q2;
    ev.d2(u, q, q1, q2);
    const double s0 = 1e-12 * deriv_scale(c, 0), s1 = 1e-12 * deriv_scale(c, 1), s2 = 1e-12 * deriv_scale(c, 2);
    BOOST_TEST((d[0] - to_eigen(P)).norm() <= s0);
    BOOST_TEST((q - to_eigen(P)).norm() <= s0);
    // At u = last of a periodic curve OCCT takes the left limit, we wrap to the first span (right
    // limit): derivatives of order > p - seam multiplicity jump there, so only compare the point.
    if (c.is_periodic() && s == 1) continue;
    BOOST_TEST((d[1] - to_eigen(V1)).norm() <= s1);
    BOOST_TEST((d[2] - to_eigen(V2)).norm() <= s2);
    BOOST_TEST((q1 - to_eigen(V1)).norm() <= s1);
    BOOST_TEST((q2 - to_eigen(V2)).norm() <= s2);
  }
}

void check_surface_evaluation(const BSplineSurface<3>& s, const Geom_BSplineSurface& os, test::Rng& r) {
  SurfaceEvaluator<3> ev(s);
  const double scale = test::pole_scale(s);
  const double Tu = s.last_u() - s.first_u(), Tv = s.last_v() - s.first_v();
  for (int k = 0; k < 5; ++k) {
    double u = r.uniform(s.first_u(), s.last_u()), v = r.uniform(s.first_v(), s.last_v());
    if (s.is_periodic_u()) u += Tu * r.integer(-3, 3);
    if (s.is_periodic_v()) v += Tv * r.integer(-3, 3);
    gp_Pnt P;
    gp_Vec Du, Dv;
    os.D1(u, v, P, Du, Dv);
    const auto d = s.derivatives<1>(u, v);
    // Derivative scales as for curves, per direction (eval_scales.hpp).
    const double su = test::deriv_scale(s, 1, 0), sv = test::deriv_scale(s, 0, 1);
    BOOST_TEST((d.S() - to_eigen(P)).norm() <= 1e-12 * scale);
    BOOST_TEST((d.S_u() - to_eigen(Du)).norm() <= 1e-12 * su);
    BOOST_TEST((d.S_v() - to_eigen(Dv)).norm() <= 1e-12 * sv);
    BOOST_TEST((ev.point(u, v) - to_eigen(P)).norm() <= 1e-12 * scale);
    Eigen::Vector3d q, qu, qv;
    ev.d1(u, v, q, qu, qv);
    BOOST_TEST((q - to_eigen(P)).norm() <= 1e-12 * scale);
    BOOST_TEST((qu - to_eigen(Du)).norm() <= 1e-12 * su);
    BOOST_TEST((qv - to_eigen(Dv)).norm() <= 1e-12 * sv);
  }
}

template <int Dim>
void curve_round_trips(unsigned long seed) {
  test::Rng r(seed);
  for (int i = 0; i < 1000; ++i) {
    const bool rational = i % 2 == 1, periodic = i % 4 >= 2;
    // ours -> OCCT -> ours
    const BSplineCurve<Dim> c =
        periodic ? test::random_periodic_bspline<Dim>(r, rational) : test::random_curve<Dim>(r, rational);
    const auto oc = occt::to_occt(c);
    BOOST_TEST(oc->IsPeriodic() == periodic);
    BOOST_TEST(oc->IsRational() == rational);
    BOOST_TEST(identical(c, occt::from_occt(*oc)), "ours -> OCCT -> ours, case " << i);
    if (periodic) check_curve_evaluation<Dim>(c, *oc, r);
    // OCCT -> ours -> OCCT
    const auto o = random_occt_curve<Dim>(r, rational, periodic);
    const BSplineCurve<Dim> mine = occt::from_occt(*o);
    BOOST_TEST(mine.is_periodic() == periodic);
    BOOST_TEST(identical_occt<Dim>(*o, *occt::to_occt(mine)), "OCCT -> ours -> OCCT, case " << i);
    check_curve_evaluation<Dim>(mine, *o, r);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(curve_3d_round_trips_are_exact) { curve_round_trips<3>(11); }

BOOST_AUTO_TEST_CASE(curve_2d_round_trips_are_exact) { curve_round_trips<2>(12); }

BOOST_AUTO_TEST_CASE(seam_multiplicity_above_one_survives) {
  // Periodic cubic with seam multiplicity 2 and an interior knot of multiplicity 3 (= degree).
  const std::vector<double> values{0.0, 1.0, 2.5, 4.0}, mults_v{2, 3, 1, 2};
  const auto k = knot_arrays(values, std::vector<int>(mults_v.begin(), mults_v.end()));
  const int n = 2 + 3 + 1;
  TColgp_Array1OfPnt P(1, n);
  for (int i = 1; i <= n; ++i) P.SetValue(i, gp_Pnt(std::cos(i), std::sin(2.0 * i), 0.1 * i));
  const Handle(Geom_BSplineCurve) o = new Geom_BSplineCurve(P, k.values, k.mults, 3, true);
  const BSplineCurve<3> c = occt::from_occt(*o);
  BOOST_TEST(c.is_periodic());
  BOOST_TEST(c.num_period_poles() == n);
  BOOST_TEST(c.num_poles() == n + 3);
  // Unwrapped knots: U[p + j] = t_{j mod n} + floor(j / n) T with period knots {0,0,1,1,1,2.5}, T = 4.
  const std::vector<double> expected{-3, -3, -1.5, 0, 0, 1, 1, 1, 2.5, 4, 4, 5, 5};
  BOOST_TEST(c.knots() == expected, boost::test_tools::per_element());
  BOOST_TEST(identical_occt<3>(*o, *occt::to_occt(c)));
  test::Rng r(5);
  check_curve_evaluation<3>(c, *o, r);
}

BOOST_AUTO_TEST_CASE(surface_round_trips_are_exact) {
  test::Rng r(13);
  for (int i = 0; i < 1000; ++i) {
    const bool rational = i % 2 == 1, pu = (i / 2) % 2 == 1, pv = (i / 4) % 2 == 1;
    const BSplineSurface<3> s = test::random_periodic_surface(r, rational, pu, pv);
    const auto os = occt::to_occt(s);
    BOOST_TEST(os->IsUPeriodic() == pu);
    BOOST_TEST(os->IsVPeriodic() == pv);
    BOOST_TEST(identical(s, occt::from_occt(*os)), "ours -> OCCT -> ours, case " << i);
    if (pu || pv) check_surface_evaluation(s, *os, r);
    const auto o = random_occt_surface(r, rational, pu, pv);
    const BSplineSurface<3> mine = occt::from_occt(*o);
    BOOST_TEST(identical_occt(*o, *occt::to_occt(mine)), "OCCT -> ours -> OCCT, case " << i);
    check_surface_evaluation(mine, *o, r);
  }
}
