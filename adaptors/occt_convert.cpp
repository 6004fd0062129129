#include "adaptors/occt_convert.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "src/core/error.hpp"

namespace cg::occt {
namespace {

// OCCT knot data (distinct values + multiplicities) of one direction. For a periodic direction only
// one period is passed: knots U[p .. p+n-1] and the closing knot t_0 + T with the seam multiplicity.
struct OcctKnots {
  TColStd_Array1OfReal values;
  TColStd_Array1OfInteger mults;
};

OcctKnots knots_to_occt(const std::vector<double>& U, int p, int num_poles, bool periodic) {
  DistinctKnots d;
  if (periodic) {
    const int n = num_poles - p;
    const std::vector<double> period(U.begin() + p, U.begin() + p + n);
    d = distinct_knots(period);
    d.values.push_back(U[static_cast<std::size_t>(p + n)]);
    d.mults.push_back(d.mults.front());
  } else {
    d = distinct_knots(U);
  }
  const int k = static_cast<int>(d.values.size());
  OcctKnots o{TColStd_Array1OfReal(1, k), TColStd_Array1OfInteger(1, k)};
  for (int i = 0; i < k; ++i) {
    o.values.SetValue(i + 1, d.values[static_cast<std::size_t>(i)]);
    o.mults.SetValue(i + 1, d.mults[static_cast<std::size_t>(i)]);
  }
  return o;
}

// Pole index shift of a periodic direction with seam multiplicity m: OCCT's flat knots start p + 1 - m
// knots before the seam, ours (unwrap_periodic_knots) p knots before it, so OCCT pole i is our pole
// (i + m - 1) mod n. Both are the same periodic B-spline; only the numbering of the poles differs.
int seam_shift_ours(const std::vector<double>& U, int p, bool periodic) {
  if (!periodic) return 0;
  int m = 1;
  while (U[static_cast<std::size_t>(p + m)] == U[static_cast<std::size_t>(p)]) ++m;
  return m - 1;
}

// Our flat (unwrapped for periodic) knot vector from OCCT knots and multiplicities.
std::vector<double> knots_from_occt(const TColStd_Array1OfReal& K, const TColStd_Array1OfInteger& M, int p,
                                    bool periodic) {
  std::vector<double> values(K.begin(), K.end());
  std::vector<int> mults(M.begin(), M.end());
  if (!periodic) return flat_knots(values, mults);
  const double T = values.back() - values.front();
  values.pop_back();
  mults.pop_back();
  return unwrap_periodic_knots(p, flat_knots(values, mults), T);
}

// Cartesian poles and weights are passed as stored by OCCT (never as w*P, whose division by w does
// not always give P back), so the conversion is bit-exact both ways.
template <int Dim, class Curve, class PoleArray>
BSplineCurve<Dim> curve_from_occt(const Curve& c) {
  const int p = c.Degree();
  const int n = c.NbPoles();
  std::vector<typename BSplineCurve<Dim>::Point> P(static_cast<std::size_t>(n));
  std::vector<double> W;
  const PoleArray& poles = c.Poles();
  std::vector<double> values(c.Knots().begin(), c.Knots().end());
  std::vector<int> mults(c.Multiplicities().begin(), c.Multiplicities().end());
  const int shift = c.IsPeriodic() ? mults.front() - 1 : 0;  // see seam_shift_ours
  const TColStd_Array1OfReal* w = c.Weights();
  if (w) W.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const int i = (j - shift + n) % n + 1;
    for (int d = 0; d < Dim; ++d) P[static_cast<std::size_t>(j)][d] = poles.Value(i).Coord(d + 1);
    if (w) W[static_cast<std::size_t>(j)] = w->Value(i);
  }
  if (!c.IsPeriodic()) return BSplineCurve<Dim>(p, flat_knots(values, mults), P, W);
  const double T = values.back() - values.front();
  values.pop_back();
  mults.pop_back();
  return BSplineCurve<Dim>::periodic(p, flat_knots(values, mults), T, P, W);
}

template <class CurveHandle, class PoleArray, class Pnt, int Dim>
CurveHandle curve_to_occt(const BSplineCurve<Dim>& c) {
  require(c.num_poles() > 0, "cannot convert an empty curve to OCCT");
  const int p = c.degree();
  const bool periodic = c.is_periodic();
  const int n = c.num_period_poles();
  const int shift = seam_shift_ours(c.knots(), p, periodic);
  PoleArray P(1, n);
  TColStd_Array1OfReal W(1, n);
  for (int i = 0; i < n; ++i) {
    const int j = (i + shift) % n;
    const auto q = c.pole(j);
    Pnt pnt;
    for (int d = 0; d < Dim; ++d) pnt.SetCoord(d + 1, q[d]);
    P.SetValue(i + 1, pnt);
    W.SetValue(i + 1, c.weight(j));
  }
  OcctKnots k = knots_to_occt(c.knots(), p, c.num_poles(), periodic);
  if (c.is_rational()) return new typename CurveHandle::element_type(P, W, k.values, k.mults, p, periodic);
  return new typename CurveHandle::element_type(P, k.values, k.mults, p, periodic);
}

}  // namespace

Handle(Geom_BSplineCurve) to_occt(const BSplineCurve<3>& c) {
  return curve_to_occt<Handle(Geom_BSplineCurve), TColgp_Array1OfPnt, gp_Pnt>(c);
}
Handle(Geom2d_BSplineCurve) to_occt(const BSplineCurve<2>& c) {
  return curve_to_occt<Handle(Geom2d_BSplineCurve), TColgp_Array1OfPnt2d, gp_Pnt2d>(c);
}
BSplineCurve<3> from_occt(const Geom_BSplineCurve& c) { return curve_from_occt<3, Geom_BSplineCurve, TColgp_Array1OfPnt>(c); }
BSplineCurve<2> from_occt(const Geom2d_BSplineCurve& c) {
  return curve_from_occt<2, Geom2d_BSplineCurve, TColgp_Array1OfPnt2d>(c);
}

Handle(Geom_BSplineSurface) to_occt(const BSplineSurface<3>& s) {
  require(s.num_poles_u() > 0, "cannot convert an empty surface to OCCT");
  const int nu = s.is_periodic_u() ? s.num_poles_u() - s.degree_u() : s.num_poles_u();
  const int nv = s.is_periodic_v() ? s.num_poles_v() - s.degree_v() : s.num_poles_v();
  const int su = seam_shift_ours(s.knots_u(), s.degree_u(), s.is_periodic_u());
  const int sv = seam_shift_ours(s.knots_v(), s.degree_v(), s.is_periodic_v());
  TColgp_Array2OfPnt P(1, nu, 1, nv);
  TColStd_Array2OfReal W(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = (i + su) % nu, b = (j + sv) % nv;
      const auto q = s.pole(a, b);
      P.SetValue(i + 1, j + 1, gp_Pnt(q.x(), q.y(), q.z()));
      W.SetValue(i + 1, j + 1, s.weight(a, b));
    }
  OcctKnots ku = knots_to_occt(s.knots_u(), s.degree_u(), s.num_poles_u(), s.is_periodic_u());
  OcctKnots kv = knots_to_occt(s.knots_v(), s.degree_v(), s.num_poles_v(), s.is_periodic_v());
  if (s.is_rational())
    return new Geom_BSplineSurface(P, W, ku.values, kv.values, ku.mults, kv.mults, s.degree_u(), s.degree_v(),
                                   s.is_periodic_u(), s.is_periodic_v());
  return new Geom_BSplineSurface(P, ku.values, kv.values, ku.mults, kv.mults, s.degree_u(), s.degree_v(),
                                 s.is_periodic_u(), s.is_periodic_v());
}

BSplineSurface<3> from_occt(const Geom_BSplineSurface& s) {
  const int pu = s.UDegree(), pv = s.VDegree();
  const bool peru = s.IsUPeriodic(), perv = s.IsVPeriodic();
  const int nu = s.NbUPoles(), nv = s.NbVPoles();
  const int tu = peru ? nu + pu : nu, tv = perv ? nv + pv : nv;
  const TColgp_Array2OfPnt& P = s.Poles();
  const TColStd_Array2OfReal* W = s.Weights();
  // Cartesian poles as stored (bit-exact, see curve_from_occt), periodic directions unwrapped.
  TColStd_Array1OfReal UK(1, s.NbUKnots()), VK(1, s.NbVKnots());
  TColStd_Array1OfInteger UM(1, s.NbUKnots()), VM(1, s.NbVKnots());
  s.UKnots(UK);
  s.VKnots(VK);
  s.UMultiplicities(UM);
  s.VMultiplicities(VM);
  const int su = peru ? UM.First() - 1 : 0, sv = perv ? VM.First() - 1 : 0;  // see seam_shift_ours
  std::vector<std::vector<Eigen::Vector3d>> poles(static_cast<std::size_t>(tu), std::vector<Eigen::Vector3d>(static_cast<std::size_t>(tv)));
  std::vector<std::vector<double>> weights;
  if (W) weights.assign(static_cast<std::size_t>(tu), std::vector<double>(static_cast<std::size_t>(tv)));
  for (int i = 0; i < tu; ++i)
    for (int j = 0; j < tv; ++j) {
      const int a = ((i - su) % nu + nu) % nu + 1, b = ((j - sv) % nv + nv) % nv + 1;
      const gp_Pnt& q = P.Value(a, b);
      poles[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = Eigen::Vector3d(q.X(), q.Y(), q.Z());
      if (W) weights[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = W->Value(a, b);
    }
  return BSplineSurface<3>::from_poles(pu, pv, knots_from_occt(UK, UM, pu, peru), knots_from_occt(VK, VM, pv, perv),
                                       poles, weights, peru, perv);
}

}  // namespace cg::occt
