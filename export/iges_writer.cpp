#include "export/iges_writer.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools_NurbsConvertModification.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Bnd_Box2d.hxx>
#include <ElCLib.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <BRep_Builder.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Plane.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <GeomConvert.hxx>
#include <BRepTools.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <Standard_ExtCharacter.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TCollection_HExtendedString.hxx>
#include <IGESData_IGESEntity.hxx>
#include <Transfer_FinderProcess.hxx>
#include <TransferBRep_ShapeMapper.hxx>
#include <TransferBRep.hxx>
#include <IGESBasic_Name.hxx>
#include <TopoDS.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Standard_Version.hxx>

#include "adaptors/occt_convert.hpp"
#include "export/atomic_file.hpp"
#include "src/core/constants.hpp"
#include "src/fit/approximate.hpp"
#include "export/part_document.hpp"
#include "export/version.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <tuple>
#include <vector>

namespace cg::io {
namespace {

void set_param(const char* name, const char* value) {
  if (!Interface_Static::SetCVal(name, value)) throw ExportError(std::string("cannot set the IGES parameter ") + name);
}
void set_param(const char* name, int value) {
  if (!Interface_Static::SetIVal(name, value)) throw ExportError(std::string("cannot set the IGES parameter ") + name);
}

// The parameter u of GeomConvert's periodic B-spline form of a cylinder or cone at angle `phi`: its
// three equal spans [a, a + D] (D = 2 pi / 3, knots at the angles a) are rational quadratic arcs, on
// which tan((phi - m) / 2) = tan(D / 4) (2 (u - a) / D - 1), m the span's middle angle.
double converted_angle_parameter(double phi) {
  const double period = 2 * kPi, span = period / 3;
  const double turns = std::floor(phi / period), local = phi - turns * period;
  const double a = std::min(2.0, std::floor(local / span)) * span, m = a + span / 2;
  return turns * period + m + span / 2 * std::tan((local - m) / 2) / std::tan(span / 4);
}

// An edge's old pcurve c2 as a function of the parameter t of the edge's converted 3D curve: c2 at t
// itself when the conversion kept the parametrisation (a B-spline, Bezier or line 3D curve, or none),
// else c2 at the old parameter the point C(t) of the converted curve has (`old_parameter`, e.g. the
// angle of C(t) on the edge's circle).
struct PcurveMap {
  const Geom2d_Curve& c2;
  std::function<double(double)> old_parameter;  ///< empty: the identity
  gp_Pnt2d Value(double t) const { return c2.Value(old_parameter ? old_parameter(t) : t); }
};

// Knots for the fit of the mapped pcurve: c2's own, plus a knot of multiplicity p - 1 where the angle
// crosses a span boundary of the converted surface (the map is only C1 there: its second derivative
// jumps; found by bisection between 16 samples per span), plus knots so that no span sweeps more than
// pi / 16 of angle (c2's own spans are often one per loop piece).
std::vector<double> mapped_pcurve_knots(const PcurveMap& c2, double first, double last, std::vector<double> knots, int p) {
  const double third = 2 * kPi / 3;
  auto sector = [&](double t) { return std::floor(c2.Value(t).X() / third); };
  const int samples = 16 * (static_cast<int>(knots.size()) - 2 * p - 1);
  for (int i = 0; i < samples; ++i) {
    double a = first + (last - first) * i / samples, z = first + (last - first) * (i + 1) / samples;
    const double sa = sector(a);
    if (sector(z) == sa) continue;
    for (int k = 0; k < 60 && z - a > 1e-15 * (1 + std::abs(z)); ++k) (sector(0.5 * (a + z)) == sa ? a : z) = 0.5 * (a + z);
    const double t = 0.5 * (a + z);
    if (t - first > 1e-9 * (last - first) && last - t > 1e-9 * (last - first))
      knots.insert(std::upper_bound(knots.begin(), knots.end(), t), static_cast<std::size_t>(p - 1), t);
  }
  std::vector<double> refined;
  for (std::size_t k = static_cast<std::size_t>(p); k + static_cast<std::size_t>(p) + 1 < knots.size(); ++k) {
    const double a = knots[k], z = knots[k + 1];
    if (!(z > a)) continue;
    const int n = static_cast<int>(std::ceil(std::abs(c2.Value(z).X() - c2.Value(a).X()) / (kPi / 16)));
    for (int i = 1; i < n; ++i) refined.push_back(a + (z - a) * i / n);
  }
  for (double t : refined) knots.insert(std::upper_bound(knots.begin(), knots.end(), t), t);
  return knots;
}

// 2 (p + 1) sample parameters per non-empty span of `knots`, each span's ends shared.
std::vector<double> span_samples(const std::vector<double>& knots, int p) {
  std::vector<double> params;
  for (std::size_t k = static_cast<std::size_t>(p); k + static_cast<std::size_t>(p) + 1 < knots.size(); ++k) {
    const double a = knots[k], z = knots[k + 1];
    if (!(z > a)) continue;
    const int n = 2 * (p + 1);
    for (int i = params.empty() ? 0 : 1; i <= n; ++i) params.push_back(a + (z - a) * i / n);
  }
  return params;
}

// The pcurve c2 (on a cylinder or cone, u the angle; initial knots `knots` of degree p over
// [first, last], the parameter of the new 3D curve) carried over to `now`, the periodic B-spline form
// of that surface (NewSurface): u mapped exactly (converted_angle_parameter) at the samples, fitted by
// least squares (degree at least 3) on mapped_pcurve_knots, a knot added in every span where the fit
// is off, up to 8 rounds; accepted when the fitted pcurve puts every check point (the samples and the
// midpoints between them) on `now` within a tenth of the edge's tolerance of where c2 put it on the
// cylinder. Null otherwise: then OCCT's projection (ProjLib_ComputeApproxOnPolarSurface, ~30 ms per
// film-hole edge) does it.
Handle(Geom2d_Curve) angular_pcurve(const PcurveMap& c2, double first, double last, std::vector<double> knots, int p,
                                    const Geom_Surface& old, const Geom_Surface& now, double tol) {
  knots = mapped_pcurve_knots(c2, first, last, std::move(knots), p);
  for (int round = 0; round < 8; ++round) {
    const std::vector<double> params = span_samples(knots, p);
    PointList<2> points;
    for (double t : params) {
      const gp_Pnt2d q = c2.Value(t);
      points.emplace_back(converted_angle_parameter(q.X()), q.Y());
    }
    BSplineCurve<2> fit;
    try {
      fit = fit_least_squares<2>(points, params, p, knots);
    } catch (const InvalidGeometry&) {
      return {};
    }
    std::vector<double> insert;
    for (std::size_t i = 0; i + 1 < params.size(); ++i)
      for (double t : {params[i], 0.5 * (params[i] + params[i + 1])}) {
        const gp_Pnt2d q = c2.Value(t);
        const auto w = fit.point(t);
        if (old.Value(q.X(), q.Y()).Distance(now.Value(w.x(), w.y())) > 0.1 * tol) {
          const auto span = std::upper_bound(knots.begin(), knots.end(), t);
          const double mid = 0.5 * (*(span - 1) + *span);
          if (insert.empty() || insert.back() != mid) insert.push_back(mid);
        }
      }
    if (insert.empty()) return occt::to_occt(fit);
    for (double u : insert) knots.insert(std::upper_bound(knots.begin(), knots.end(), u), u);
  }
  return {};
}

// OCCT writes analytic surfaces as IGES analytic entities (planes 108, cylinders as surfaces of
// revolution 120): convert every surface and curve to its exact rational B-spline form first, so the
// file holds only 144/142/128/126. The face names follow the conversion history.
// BRepTools_NurbsConvertModification recomputes every pcurve on a face it converts -- B-spline faces
// included, whose surface it only copies -- by projecting the edge's 3D curve onto the surface
// (ProjLib_ComputeApproxOnPolarSurface) and then measures the new tolerance; on the cooled blade, with
// its film-hole loops of up to 512 spans, that was ~70 % of the IGES time. On a B-spline face whose
// edge keeps its parametrisation (3D curve absent, a B-spline, Bezier or line: converted without
// reparametrisation) the existing pcurve is still exact: it is kept, in B-spline form. Everything
// else (analytic surfaces, conic edges whose parameter changes) goes through OCCT's conversion.
// Surfaces closed around an axis (cylinders, cones, spheres, tori: hole and pin walls; surfaces of
// revolution: hub and casing end walls) become
// PERIODIC B-splines here, over the face's v range: OCCT's own conversion trims such a face's full
// circle to a closed non-periodic B-spline whose domain ([-pi/8, 15 pi/8] on a film hole) leaves part
// of the face's pcurves outside it (see surface_holding_loops). Planes and everything else go through
// OCCT's conversion.
class KeepBSplineFaces : public BRepTools_NurbsConvertModification {
 public:
  // `shape`: the shape to be converted. Its edges on a plane keep OCCT's pcurves on every face: OCCT
  // carries the plane's pcurve over to the new 3D curve from what its own conversion of the edge's
  // other pcurves recorded, and with our circle fit on the cylinder side it made an invalid B-spline on
  // the plane (a cylinder chamber's planar cap, tests/export/test_handoff_outputs).
  explicit KeepBSplineFaces(const TopoDS_Shape& shape) {
    for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) {
      TopLoc_Location loc;
      const Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(fx.Current()), loc);
      if (s.IsNull() || !s->IsKind(STANDARD_TYPE(Geom_Plane))) continue;
      for (TopExp_Explorer ex(fx.Current(), TopAbs_EDGE); ex.More(); ex.Next()) planar_edges_.Add(ex.Current());
    }
  }

  Standard_Boolean NewSurface(const TopoDS_Face& f, Handle(Geom_Surface)& s, TopLoc_Location& l, Standard_Real& tol,
                              Standard_Boolean& rev_wires, Standard_Boolean& rev_face) override {
    TopLoc_Location loc;
    const Handle(Geom_Surface) e = BRep_Tool::Surface(f, loc);
    if (!angular(*e)) return BRepTools_NurbsConvertModification::NewSurface(f, s, l, tol, rev_wires, rev_face);
    double u0, u1, v0, v1, su0, su1, sv0, sv1;
    BRepTools::UVBounds(f, u0, u1, v0, v1);
    e->Bounds(su0, su1, sv0, sv1);  // a revolved meridian ends where it ends
    v0 = std::max(v0, sv0);
    v1 = std::min(v1, sv1);
    const Handle(Geom_Surface) trimmed =
        e->IsVPeriodic() ? Handle(Geom_Surface)(e) : new Geom_RectangularTrimmedSurface(e, v0, v1, /*UTrim=*/false);
    s = GeomConvert::SurfaceToBSplineSurface(trimmed);
    l = loc;
    tol = BRep_Tool::Tolerance(f);
    rev_wires = rev_face = false;
    return Standard_True;
  }

  Standard_Boolean NewCurve2d(const TopoDS_Edge& e, const TopoDS_Face& f, const TopoDS_Edge& new_e, const TopoDS_Face& new_f,
                              Handle(Geom2d_Curve)& c, Standard_Real& tol) override {
    TopLoc_Location sl, cl;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f, sl);
    double f3 = 0, l3 = 0, f2 = 0, l2 = 0;
    const Handle(Geom_Curve) c3 = BRep_Tool::Curve(e, cl, f3, l3);
    const Handle(Geom2d_Curve) c2 = BRep_Tool::CurveOnSurface(e, f, f2, l2);
    const bool usable = !BRep_Tool::Degenerated(e) && !c2.IsNull() && (c3.IsNull() || keeps_parameter(c3));
    if (usable && s->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) {
      c = c2->IsKind(STANDARD_TYPE(Geom2d_BSplineCurve)) ? Handle(Geom2d_Curve)::DownCast(c2->Copy())
                                                           : Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(c2, f2, l2));
      tol = BRep_Tool::Tolerance(e);
      return Standard_True;
    }
    if (usable && (s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) || s->IsKind(STANDARD_TYPE(Geom_ConicalSurface)) ||
                   s->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution)))) {
      TopLoc_Location nl;
      const Handle(Geom_Surface) now = BRep_Tool::Surface(new_f, nl);
      Handle(Geom2d_BSplineCurve) b = Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(Handle(Geom2d_Curve)::DownCast(c2->Copy()), f2, l2));
      if (b->Degree() < 3) b->IncreaseDegree(3);
      c = angular_pcurve({*c2, {}}, f2, l2, occt::from_occt(*b).knots(), b->Degree(), *s, *now, BRep_Tool::Tolerance(e));
      if (!c.IsNull()) {
        tol = BRep_Tool::Tolerance(e);
        return Standard_True;
      }
    }
    if (!planar_edges_.Contains(e) && circle_pcurve(e, f, new_e, new_f, c)) {
      tol = BRep_Tool::Tolerance(e);
      return Standard_True;
    }
    return BRepTools_NurbsConvertModification::NewCurve2d(e, f, new_e, new_f, c, tol);
  }

  // A circle's edge on a cylinder or cone (a hole's or pin's rim): its 3D curve is now a rational
  // B-spline C whose parameter t is not the angle, so the old pcurve is mapped at the angle of C(t)
  // on the circle (exact: ElCLib), unwrapped about the linear guess between the edge's ends, and
  // fitted as above on C's knots. False when it does not apply or the fit is not accepted.
  static bool circle_pcurve(const TopoDS_Edge& e, const TopoDS_Face& f, const TopoDS_Edge& new_e, const TopoDS_Face& new_f,
                            Handle(Geom2d_Curve)& c) {
    TopLoc_Location sl;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f, sl);
    if (!s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) && !s->IsKind(STANDARD_TYPE(Geom_ConicalSurface))) return false;
    if (BRep_Tool::Degenerated(e) || !BRep_Tool::SameParameter(e) || !BRep_Tool::SameRange(e)) return false;
    double f3 = 0, l3 = 0, f2 = 0, l2 = 0, fn = 0, ln = 0;
    Handle(Geom_Curve) c3 = BRep_Tool::Curve(e, f3, l3);
    const Handle(Geom2d_Curve) c2 = BRep_Tool::CurveOnSurface(e, f, f2, l2);
    const Handle(Geom_BSplineCurve) cn = Handle(Geom_BSplineCurve)::DownCast(BRep_Tool::Curve(new_e, fn, ln));
    if (c3.IsNull() || c2.IsNull() || cn.IsNull() || f2 != f3 || l2 != l3 || !(ln > fn) || !(l3 > f3)) return false;
    while (c3->IsKind(STANDARD_TYPE(Geom_TrimmedCurve))) c3 = Handle(Geom_TrimmedCurve)::DownCast(c3)->BasisCurve();
    const Handle(Geom_Circle) circle = Handle(Geom_Circle)::DownCast(c3);
    if (circle.IsNull()) return false;
    const gp_Circ circ = circle->Circ();
    auto angle = [=](double t) {
      if (t <= fn) return f3;
      if (t >= ln) return l3;
      const double guess = f3 + (l3 - f3) * (t - fn) / (ln - fn), raw = ElCLib::Parameter(circ, cn->Value(t));
      return raw + 2 * kPi * std::round((guess - raw) / (2 * kPi));
    };
    // C's distinct knots in (fn, ln) as simple knots of a cubic.
    const int p = 3;
    std::vector<double> knots(p + 1, fn);
    for (int k = 1; k <= cn->NbKnots(); ++k)
      if (cn->Knot(k) > fn && cn->Knot(k) < ln) knots.push_back(cn->Knot(k));
    knots.insert(knots.end(), p + 1, ln);
    TopLoc_Location nl;
    const Handle(Geom_Surface) now = BRep_Tool::Surface(new_f, nl);
    c = angular_pcurve({*c2, angle}, fn, ln, knots, p, *s, *now, BRep_Tool::Tolerance(e));
    return !c.IsNull();
  }

 private:
  // Closed around an axis, u the angle: GeomConvert makes the full turn three equal rational arcs.
  static bool angular(const Geom_Surface& s) {
    return (s.IsKind(STANDARD_TYPE(Geom_ElementarySurface)) || s.IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))) &&
           s.IsUPeriodic();
  }
  static bool keeps_parameter(Handle(Geom_Curve) c) {
    while (c->IsKind(STANDARD_TYPE(Geom_TrimmedCurve))) c = Handle(Geom_TrimmedCurve)::DownCast(c)->BasisCurve();
    return c->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) || c->IsKind(STANDARD_TYPE(Geom_BezierCurve)) ||
           c->IsKind(STANDARD_TYPE(Geom_Line));
  }

  TopTools_IndexedMapOfShape planar_edges_;
};

// BRepBuilderAPI_NurbsConvert (the modifier and its vertex tolerance correction) with the modification above.
class NurbsConvertKeepingBSplines : public BRepBuilderAPI_NurbsConvert {
 public:
  explicit NurbsConvertKeepingBSplines(const TopoDS_Shape& shape) {
    myModification = new KeepBSplineFaces(shape);
    Perform(shape);
  }
};

// OCCT's IGES writer makes a periodic B-spline surface non-periodic itself (GeomToIGES_GeomSurface): it
// moves the origin to the knot at or below the face's smallest parameter and shifts the pcurves by
// whole periods. A face whose loops span the whole period from a parameter between two knots (a pin or
// film hole's wall, bounded by its seam) then reaches past the end of the written surface by up to one
// knot span: OCCT's reader leaves those ~0.05 mm of each such loop unmatched, and sewing the faces back
// left 84 free edges on the built-in example. So every periodic surface is opened here, exactly, at the
// face's own smallest parameter (a knot inserted there, the origin moved to it, the knots translated by
// the whole periods between the two), and the writer sees a non-periodic surface whose domain holds
// every pcurve of its face as it is. The pcurves are re-attached unchanged to the new surface.
struct ParameterRange {
  double first = 0, last = 0;
};

// The pcurves of every edge of a face (a seam has two: c2 is the reversed edge's).
struct FacePcurve {
  TopoDS_Edge edge;
  Handle(Geom2d_Curve) c1, c2;
  double first = 0, last = 0;
};

std::vector<FacePcurve> face_pcurves(const TopoDS_Face& face) {
  std::vector<FacePcurve> out;
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(face, TopAbs_EDGE, edges);
  for (int k = 1; k <= edges.Extent(); ++k) {
    FacePcurve p;
    p.edge = TopoDS::Edge(edges(k).Oriented(TopAbs_FORWARD));
    p.c1 = BRep_Tool::CurveOnSurface(p.edge, face, p.first, p.last);
    if (BRep_Tool::IsClosed(p.edge, face))
      p.c2 = BRep_Tool::CurveOnSurface(TopoDS::Edge(p.edge.Reversed()), face, p.first, p.last);
    if (!p.c1.IsNull()) out.push_back(p);
  }
  return out;
}

// A box that holds the pcurve c on [first, last]: the poles of a B-spline over exactly its own
// domain (no segment copy), OCCT's cheap bound otherwise (BndLib_Add2dCurve::Add, also pole based).
Bnd_Box2d outer_box(const Handle(Geom2d_Curve)& c, double first, double last) {
  Bnd_Box2d box;
  const Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(c);
  if (!b.IsNull() && b->FirstParameter() == first && b->LastParameter() == last)
    for (int i = 1; i <= b->NbPoles(); ++i) box.Add(b->Pole(i));
  else
    BndLib_Add2dCurve::Add(c, first, last, 0.0, box);
  return box;
}

// The range of the face's pcurves in u (v), both pcurves of a seam included, by their exact extrema
// (the pole box of a B-spline pcurve can overshoot the seam it ends on). Points on the pcurves (17 per
// pcurve, ends included) bound each extremum from inside, pole boxes from outside; only a pcurve whose
// pole box reaches beyond the points of all pcurves gets OCCT's exact extrema
// (BndLib_Add2dCurve::AddOptimal, a global optimiser: it was ~20 % of the IGES stage when run on every
// pcurve of the built-in example), so the result is the same extrema at a fraction of the cost.
std::pair<ParameterRange, ParameterRange> pcurve_ranges(const std::vector<FacePcurve>& pcurves) {
  struct Piece {
    Handle(Geom2d_Curve) c;
    double first, last;
    Bnd_Box2d outer;
  };
  std::vector<Piece> pieces;
  Bnd_Box2d inner;
  for (const FacePcurve& p : pcurves)
    for (const Handle(Geom2d_Curve)& c : {p.c1, p.c2}) {
      if (c.IsNull()) continue;
      for (int k = 0; k <= 16; ++k) inner.Add(c->Value(k == 16 ? p.last : p.first + (p.last - p.first) * k / 16.0));
      pieces.push_back({c, p.first, p.last, outer_box(c, p.first, p.last)});
    }
  double u0, v0, u1, v1;
  inner.Get(u0, v0, u1, v1);
  Bnd_Box2d exact;
  exact.Update(u0, v0, u1, v1);
  for (const Piece& q : pieces) {
    double a0, b0, a1, b1;
    q.outer.Get(a0, b0, a1, b1);
    if (a0 < u0 || b0 < v0 || a1 > u1 || b1 > v1) BndLib_Add2dCurve::AddOptimal(q.c, q.first, q.last, 0.0, exact);
  }
  exact.Get(u0, v0, u1, v1);
  return {{u0, u1}, {v0, v1}};
}

enum class Direction { U, V };

// Opens `s` (periodic in `d`) at parameter `at`: afterwards it is clamped and non-periodic on
// [at, at + period], the same surface at the same parameters (Segment keeps the parametrisation; the
// knots are then translated by the whole periods between `at` and its image in the stored period).
void open_periodic(Geom_BSplineSurface& s, Direction d, double at, double period) {
  double u0, u1, v0, v1;
  s.Bounds(u0, u1, v0, v1);
  const bool u = d == Direction::U;
  const double inside = ElCLib::InPeriod(at, u ? u0 : v0, (u ? u0 : v0) + period);
  if (u) s.Segment(inside, inside + period, v0, v1);
  else s.Segment(u0, u1, inside, inside + period);
  TColStd_Array1OfReal knots(1, u ? s.NbUKnots() : s.NbVKnots());
  if (u) s.UKnots(knots);
  else s.VKnots(knots);
  const double shift = at - inside;
  if (shift == 0) return;
  for (int k = knots.Lower(); k <= knots.Upper(); ++k) knots(k) += shift;
  if (u) s.SetUKnots(knots);
  else s.SetVKnots(knots);
}

// The surface to write for a face on `old`: opened (open_periodic) at the face's loops in every direction
// where `old` is periodic, or closed with pcurves beyond its domain (OCCT's NurbsConvert makes a full
// cylinder a closed non-periodic B-spline over [-pi/8, 15 pi/8] and leaves the hole's pcurves on
// [0, 2 pi]: in memory OCCT evaluates past the end, in a file the last eighth of the loop is off the
// surface). Null when the face needs no change.
Handle(Geom_BSplineSurface) surface_holding_loops(const Handle(Geom_BSplineSurface)& old,
                                                  const std::vector<FacePcurve>& pcurves) {
  const auto [ur, vr] = pcurve_ranges(pcurves);
  double u0, u1, v0, v1;
  old->Bounds(u0, u1, v0, v1);
  const double eps = Precision::PConfusion();
  const bool open_u = old->IsUPeriodic() || (old->IsUClosed() && (ur.first < u0 - eps || ur.last > u1 + eps));
  const bool open_v = old->IsVPeriodic() || (old->IsVClosed() && (vr.first < v0 - eps || vr.last > v1 + eps));
  if (!open_u && !open_v) return {};
  const Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(old->Copy());
  for (const auto& [d, range, open] : {std::tuple{Direction::U, ur, open_u}, std::tuple{Direction::V, vr, open_v}}) {
    if (!open) continue;
    const bool u = d == Direction::U;
    if (u && !s->IsUPeriodic()) s->SetUPeriodic();
    if (!u && !s->IsVPeriodic()) s->SetVPeriodic();
    const double period = u ? s->UPeriod() : s->VPeriod();
    if (range.last - range.first > period * (1 + 1e-12)) return {};
    // Centred in the period where the face leaves room, so no pcurve ends on the new boundary by rounding.
    const double margin = 0.5 * (period - (range.last - range.first));
    open_periodic(*s, d, range.first - (margin > 1e-9 * period ? margin : 0.0), period);
  }
  return s;
}

// The new surface gives the points the old one gave along every pcurve of the face (17 samples per
// pcurve, within `tol` mm): the check that opening kept the face where it was.
bool same_along_pcurves(const Geom_Surface& old, const Geom_Surface& now, const std::vector<FacePcurve>& pcurves,
                        double tol) {
  for (const FacePcurve& p : pcurves)
    for (const Handle(Geom2d_Curve)& c : {p.c1, p.c2}) {
      if (c.IsNull()) continue;
      for (int k = 0; k <= 16; ++k) {
        const gp_Pnt2d uv = c->Value(p.first + (p.last - p.first) * k / 16.0);
        if (old.Value(uv.X(), uv.Y()).Distance(now.Value(uv.X(), uv.Y())) > tol) return false;
      }
    }
  return true;
}

// Every face whose surface must be opened for the IGES writer gets the opened surface, its pcurves
// re-attached unchanged (they are stored per surface). A face the check rejects keeps its surface.
void open_periodic_faces(const brep::NamedBody& body) {
  BRep_Builder b;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(body.geometry.shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i).Oriented(TopAbs_FORWARD));
    TopLoc_Location loc;
    const Handle(Geom_BSplineSurface) old = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face, loc));
    if (old.IsNull()) continue;
    const std::vector<FacePcurve> pcurves = face_pcurves(face);
    const Handle(Geom_BSplineSurface) s = surface_holding_loops(old, pcurves);
    if (s.IsNull()) continue;
    if (!same_along_pcurves(*old, *s, pcurves, 1e-9 + 0.1 * BRep_Tool::Tolerance(face)))
      throw ExportError("IGES: the surface of a face of body \"" + body.name + "\" could not be made non-periodic");
    b.UpdateFace(face, s, loc, BRep_Tool::Tolerance(face));
    for (const FacePcurve& p : pcurves) {
      const double tol = BRep_Tool::Tolerance(p.edge);
      if (p.c2.IsNull()) b.UpdateEdge(p.edge, p.c1, face, tol);
      else b.UpdateEdge(p.edge, p.c1, p.c2, face, tol);
      b.Range(p.edge, face, p.first, p.last);
    }
  }
}

// The conversion runs on a copy of the topology (geometry shared): OCCT's modifier updates the vertices
// and edges it keeps (their parameters on the new curves), and other exporters read the part meanwhile.
brep::Part nurbs_part(const brep::Part& part) {
  brep::Part out;
  for (const brep::NamedBody& body : part) {
    BRepBuilderAPI_Copy copy(body.geometry.shape, /*copyGeom=*/false, /*copyMesh=*/false);
    NurbsConvertKeepingBSplines convert(copy.Shape());
    if (!convert.IsDone()) throw ExportError("IGES: conversion of body \"" + body.name + "\" to B-splines failed");
    brep::NamedBody b{body.name, {convert.Shape(), {}}};
    open_periodic_faces(b);
    for (const brep::NamedFace& f : body.geometry.faces)
      b.geometry.faces.push_back({TopoDS::Face(convert.ModifiedShape(copy.ModifiedShape(f.face))), f.name});
    out.push_back(std::move(b));
  }
  return out;
}

// The names OCCT's IGESCAFControl_Writer writes in name mode (WriteNames: an 8-character label on the
// entity, right-aligned, and a name property, 406 form 15), but in a fixed order: the product, then per
// body its solid and its faces in part order. OCCT visits them in a hash map of shapes, i.e. in an order
// of memory addresses: the 406 entities and the label of the part's group (402: product or body name)
// changed from run to run, so two runs wrote different bytes.
void write_names(IGESControl_Writer& writer, const TopoDS_Shape& compound, const brep::Part& part, const std::string& product) {
  const Handle(Transfer_FinderProcess) fp = writer.TransferProcess();
  auto name_entity = [&](const TopoDS_Shape& shape, const std::string& name) {
    Handle(IGESData_IGESEntity) entity;
    if (!fp->FindTypedTransient(TransferBRep::ShapeMapper(fp, shape), STANDARD_TYPE(IGESData_IGESEntity), entity)) return;
    const TCollection_ExtendedString text(name.c_str(), /*isMultiByte=*/true);
    const Handle(TCollection_HAsciiString) label = new TCollection_HAsciiString("        ");
    for (int k = 1, at = std::max(0, 8 - text.Length()); at < 8; ++k, ++at)
      label->SetValue(at + 1, IsAnAscii(text.Value(k)) ? static_cast<char>(text.Value(k)) : '?');
    entity->SetLabel(label);
    const Handle(IGESBasic_Name) long_name = new IGESBasic_Name;
    long_name->Init(1, new TCollection_HAsciiString(new TCollection_HExtendedString(text), '_'));
    entity->AddProperty(long_name);
    writer.AddEntity(long_name);
  };
  name_entity(compound, product);
  for (const brep::NamedBody& body : part) {
    TopExp_Explorer solid(body.geometry.shape, TopAbs_SOLID);
    name_entity(solid.Current(), body.name);
    for (const brep::NamedFace& f : body.geometry.faces) name_entity(f.face, f.name);
  }
}

}  // namespace

void write_iges(const std::filesystem::path& file, const brep::Part& part, const IgesOptions& options) {
  IGESControl_Controller::Init();
  set_param("write.iges.brep.mode", options.mode == IgesMode::Brep ? 1 : 0);
  set_param("write.iges.unit", "MM");
  set_param("write.iges.header.product", options.product_name.c_str());
  set_param("write.iges.header.author", kToolName);
  set_param("write.iges.header.company", "");
  const brep::Part converted = nurbs_part(part);
  const PartDocument doc(converted, options.product_name);
  // The default constructor: built on a fresh XSControl_WorkSession (the other constructor) OCCT 7.6.3
  // leaves the model's global section unset (unit flag 0, no unit name, unit value 0, resolution 0),
  // and the writer then scales every coordinate by 1 / 0: the file held INF for each non-zero
  // coordinate, which OCCT's reader turned into 927 faces, 496 of them invalid (test_acceptance_*).
  IGESCAFControl_Writer writer;
  writer.SetNameMode(false);  // write_names below
  writer.SetColorMode(true);
  writer.SetLayerMode(true);
  if (!writer.Transfer(doc.document())) throw ExportError("IGES transfer of the part failed");
  write_names(writer, doc.compound(), converted, options.product_name);

  // The global section names OCCT as the sending system by default.
  const Handle(IGESData_IGESModel) model = writer.Model();
  IGESData_GlobalSection gs = model->GlobalSection();
  const std::string tool = std::string(kToolName) + " " + tool_version();
  gs.SetSendName(new TCollection_HAsciiString(options.product_name.c_str()));
  gs.SetFileName(new TCollection_HAsciiString(file.filename().string().c_str()));
  gs.SetSystemId(new TCollection_HAsciiString(tool.c_str()));
  gs.SetInterfaceVersion(new TCollection_HAsciiString("Open CASCADE " OCC_VERSION_STRING_EXT));
  gs.SetReceiveName(new TCollection_HAsciiString(options.product_name.c_str()));
  model->SetGlobalSection(gs);

  // Into memory first: OCCT's IGES writer flushes its stream after every line (one system call per
  // line on a file stream: ~135 000 write calls for the built-in example's 160 000 lines).
  std::ostringstream text;
  if (!writer.Write(text)) throw ExportError("cannot write the IGES data of " + file.string());
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text.str();
    out.close();
    if (!out) throw ExportError("cannot write IGES file " + tmp.string());
  });
}

}  // namespace cg::io
