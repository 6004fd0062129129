#include "src/brep/blade_solid.hpp"

#include <BOPAlgo_Builder.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Message_Alert.hxx>
#include <Message_Report.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Shell.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <TopoDS_Wire.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt2d.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <optional>
#include <sstream>

#include "adaptors/occt_convert.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/blade/surface_iso.hpp"
#include "src/brep/occt_progress.hpp"
#include "src/core/constants.hpp"
#include "src/fit/interpolate.hpp"
#include "src/modify/periodic_conversion.hpp"
#include "src/modify/reparametrize.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::brep {
namespace {

// Bounding box of the surface's poles: it contains the surface (convex hull property).
struct PoleBox {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = Eigen::Vector3d::Constant(-HUGE_VAL);
  Eigen::Vector3d centre() const { return 0.5 * (lo + hi); }
  double diagonal() const { return (hi - lo).norm(); }
};

PoleBox pole_box(const BSplineSurface<3>& s) {
  PoleBox b;
  for (int i = 0; i < s.num_poles_u(); ++i)
    for (int j = 0; j < s.num_poles_v(); ++j) {
      const Eigen::Vector3d p = s.pole(i, j);
      b.lo = b.lo.cwiseMin(p);
      b.hi = b.hi.cwiseMax(p);
    }
  return b;
}

// A square of side 4 * blade diagonal on the plane, centred at the foot of the blade's centre: large
// enough that the blade crosses the plane only inside it.
TopoDS_Face plane_face(const PlaneTrim& t, const PoleBox& box, const char* which) {
  const double n = t.normal.norm();
  require(std::isfinite(n) && n > 1e-12, std::string(which) + " plane normal must be a non-zero vector, got length " +
                                             std::to_string(n));
  require(t.point.allFinite(), std::string(which) + " plane point must be finite");
  const Eigen::Vector3d nn = t.normal / n;
  const Eigen::Vector3d foot = box.centre() - (box.centre() - t.point).dot(nn) * nn;
  const gp_Pln pln(gp_Pnt(foot.x(), foot.y(), foot.z()), gp_Dir(nn.x(), nn.y(), nn.z()));
  const double h = 2.0 * box.diagonal();
  BRepBuilderAPI_MakeFace mk(pln, -h, h, -h, h);
  if (!mk.IsDone()) throw AlgorithmFailure(std::string("cannot make the ") + which + " plane face");
  return mk.Face();
}

// Angular sector [start, start + width] about the x axis that holds the blade: the poles' angles
// about their mean direction. When they span less than pi, the wedge between the extreme angles is
// convex and contains every pole, hence (convex hull property) the whole surface. A margin keeps
// the sector's side edges well away from the blade. Returns width = 2 pi (full revolution, seam
// opposite the blade) when the poles spread too wide.
struct Sector {
  double start, width;
};

Sector blade_sector(const BSplineSurface<3>& s, const PoleBox& box) {
  const double centre = std::atan2(box.centre().z(), box.centre().y());
  double lo = 0, hi = 0;
  for (int i = 0; i < s.num_poles_u(); ++i)
    for (int j = 0; j < s.num_poles_v(); ++j) {
      const Eigen::Vector3d p = s.pole(i, j);
      double a = std::atan2(p.z(), p.y()) - centre;
      a = std::remainder(a, 2 * kPi);  // into [-pi, pi]
      if (std::hypot(p.y(), p.z()) == 0) return {centre + kPi, 2 * kPi};
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  if (hi - lo >= 0.9 * kPi) return {centre + kPi, 2 * kPi};
  const double margin = 0.05 + 0.25 * (hi - lo);
  return {centre + lo - margin, hi - lo + 2 * margin};
}

}  // namespace

Handle(Geom_SurfaceOfRevolution) revolved_surface(const RevolvedTrim& t, double theta0, const char* which) {
  const BSplineCurve<2>& c = t.meridional;
  require(c.num_poles() >= 2, std::string(which) + " meridional curve needs at least 2 poles");
  require(!c.is_periodic(), std::string(which) + " meridional curve must not be periodic");
  std::vector<Eigen::Vector3d> poles;
  for (int i = 0; i < c.num_poles(); ++i) {
    const Eigen::Vector2d q = c.pole(i);
    require(q.allFinite() && q.y() > 0.0, std::string(which) + " meridional curve: pole " + std::to_string(i) +
                                              " has r = " + format_number(q.y()) + ", r must be > 0");
    poles.emplace_back(q.x(), q.y() * std::cos(theta0), q.y() * std::sin(theta0));
  }
  const BSplineCurve<3> c3(c.degree(), c.knots(), poles, c.is_rational() ? c.weights() : std::vector<double>{});
  return new Geom_SurfaceOfRevolution(occt::to_occt(c3), gp_Ax1(gp::Origin(), gp::DX()));
}

namespace {

// Face on the surface of revolution of the meridional curve (x, r) about the x axis, over the
// angular sector only: a smaller face makes the general fuse ~2.5x faster than a full revolution.
// The basis curve lies at angle sector.start (for a full revolution that is the seam, opposite the
// blade, so the end face cut out of it carries no seam).
TopoDS_Face revolved_face(const RevolvedTrim& t, const Sector& sector, const char* which) {
  const BSplineCurve<2>& c = t.meridional;
  const Handle(Geom_SurfaceOfRevolution) rev = revolved_surface(t, sector.start, which);
  BRepBuilderAPI_MakeFace mk = sector.width >= 2 * kPi
                                   ? BRepBuilderAPI_MakeFace(rev, Precision::Confusion())
                                   : BRepBuilderAPI_MakeFace(rev, 0.0, sector.width, c.first_param(), c.last_param(),
                                                             Precision::Confusion());
  if (!mk.IsDone()) throw AlgorithmFailure(std::string("cannot make the ") + which + " surface of revolution face");
  return mk.Face();
}

TopoDS_Face trim_face(const EndTrim& t, const PoleBox& box, const Sector& sector, const char* which) {
  if (const auto* p = std::get_if<PlaneTrim>(&t)) return plane_face(*p, box, which);
  return revolved_face(std::get<RevolvedTrim>(t), sector, which);
}

std::vector<TopoDS_Face> pieces_of(BOPAlgo_Builder& gf, const TopoDS_Face& f) {
  std::vector<TopoDS_Face> out;
  for (const TopoDS_Shape& s : gf.Modified(f)) out.push_back(TopoDS::Face(s));
  if (out.empty() && !gf.IsDeleted(f)) out.push_back(f);  // not split: the face itself
  return out;
}

bool contains(const std::vector<TopoDS_Face>& faces, const TopoDS_Shape& s) {
  for (const auto& f : faces)
    if (f.IsSame(s)) return true;
  return false;
}

// True when some edge of `piece` also bounds a face of `others`.
bool touches(const TopoDS_Face& piece, const std::vector<TopoDS_Face>& others,
             const TopTools_IndexedDataMapOfShapeListOfShape& edge_faces) {
  for (TopExp_Explorer e(piece, TopAbs_EDGE); e.More(); e.Next())
    for (const TopoDS_Shape& f : edge_faces.FindFromKey(e.Current()))
      if (!f.IsSame(piece) && contains(others, f)) return true;
  return false;
}

// End faces: the trim pieces whose every (non-degenerated) edge is an edge of the wall.
std::vector<TopoDS_Face> end_faces(const std::vector<TopoDS_Face>& trim_pieces, const TopoDS_Face& wall) {
  TopTools_IndexedMapOfShape wall_edges;
  TopExp::MapShapes(wall, TopAbs_EDGE, wall_edges);
  std::vector<TopoDS_Face> out;
  for (const auto& q : trim_pieces) {
    bool all = true, any = false;
    for (TopExp_Explorer e(q, TopAbs_EDGE); e.More() && all; e.Next()) {
      if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) continue;
      any = true;
      all = wall_edges.Contains(e.Current());
    }
    if (all && any) out.push_back(q);
  }
  return out;
}

std::vector<std::string> alert_names(const BOPAlgo_Builder& gf, Message_Gravity g) {
  std::vector<std::string> out;
  for (const Handle(Message_Alert)& a : gf.GetReport()->GetAlerts(g)) out.emplace_back(a->GetMessageKey());
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The wall and the end faces (sharing their edges) as one closed, consistently oriented solid with
// outward normals; every face named by the surface it lies on.
BladeSolid close_solid(const TopoDS_Face& wall, const std::vector<TopoDS_Face>& hub_ends,
                       const std::vector<TopoDS_Face>& casing_ends, const Handle(Geom_Surface)& wall_s,
                       const Handle(Geom_Surface)& hub_s, const Handle(Geom_Surface)& casing_s) {
  TopoDS_Shell shell;
  BRep_Builder bb;
  bb.MakeShell(shell);
  bb.Add(shell, wall);
  for (const auto& f : hub_ends) bb.Add(shell, f);
  for (const auto& f : casing_ends) bb.Add(shell, f);

  ShapeAnalysis_FreeBounds free_bounds(shell);
  int free_edges = 0;
  for (const TopoDS_Shape* w : {&free_bounds.GetClosedWires(), &free_bounds.GetOpenWires()})
    for (TopExp_Explorer e(*w, TopAbs_EDGE); e.More(); e.Next()) ++free_edges;
  if (free_edges > 0)
    throw AlgorithmFailure("the trimmed blade shell is open: " + std::to_string(free_edges) + " free edges");

  // Orient the faces consistently (the wall and the end faces come with their surfaces' normals).
  ShapeFix_Shell fix;
  fix.FixFaceOrientation(shell, /*isAccountMultiConex=*/true, /*NonManifold=*/false);
  if (fix.NbShells() != 1) throw AlgorithmFailure("the trimmed blade faces do not form one shell");
  TopoDS_Solid solid;
  bb.MakeSolid(solid);
  bb.Add(solid, fix.Shell());
  BRepLib::OrientClosedSolid(solid);  // outward normals: positive volume

  BladeSolid out;
  out.solid = solid;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face f = TopoDS::Face(e.Current());
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f);
    const char* name = s == wall_s ? kWallFaceName : s == hub_s ? kHubFaceName : s == casing_s ? kCasingFaceName : nullptr;
    if (!name) throw AlgorithmFailure("a face of the blade solid lies on none of the blade, hub and casing surfaces");
    out.faces.push_back({f, name});
  }
  return out;
}

// ---- Trimming along the wall's own iso-curves -------------------------------------------------------
// A blade model's wall has its sections at v = 0 and v = 1 on the hub and casing (within the surface
// tolerance): the wall face is then the surface restricted to v in [0, 1] (its edges are exact iso-
// curves with straight pcurves), and each end face is the trim surface bounded by that same edge. No
// intersection curves are computed, so the edges stay as light as the wall (a general fuse makes
// boundary curves of ~600 poles, which every later check and boolean pays for).

// Distance of the iso-curve v = const from the trim surface, 16 samples per knot span.
double iso_deviation(const BSplineCurve<3>& iso, const EndTrim& trim) {
  double worst = 0;
  const int m = 16 * (iso.num_period_poles() + 1);
  std::optional<CurveProjector<2>> proj;
  if (const auto* r = std::get_if<RevolvedTrim>(&trim)) proj.emplace(r->meridional);
  for (int i = 0; i < m; ++i) {
    const Eigen::Vector3d p = iso.point(iso.first_param() + iso.period() * i / m);
    if (const auto* pl = std::get_if<PlaneTrim>(&trim))
      worst = std::max(worst, std::abs((p - pl->point).dot(pl->normal.normalized())));
    else
      worst = std::max(worst, proj->project(Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z()))).distance);
  }
  return worst;
}

// The pcurve (U = angle from theta0, V = meridional parameter) of the closed iso-curve on the surface of
// revolution of `meridional`: the iso-curve's foot points on that surface in (U, V), interpolated at the
// same parameter as the iso-curve (so the edge stays same-parameter) at its knots and 1, 2, 4 ... points
// per knot span until, halfway between the points, the pcurve's image is within `target` of the foot
// point there (or 32 per span); `deviation` is that distance. (The iso-curve's own distance from the surface
// is the edge tolerance's other part, measured by iso_deviation.)
Handle(Geom2d_BSplineCurve) revolved_pcurve(const BSplineCurve<3>& iso, const BSplineCurve<2>& meridional,
                                            double theta0, double target, double& deviation) {
  CurveProjector<2> proj(meridional);
  const double a = iso.first_param(), T = iso.period();
  auto uv = [&](double u) {
    const Eigen::Vector3d p = iso.point(u);
    const CurveProjection<2> f = proj.project(Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z())));
    return Eigen::Vector2d(std::remainder(std::atan2(p.z(), p.y()) - theta0 - kPi, 2 * kPi) + kPi, f.param);
  };
  auto on_surface = [&](const Eigen::Vector2d& q) {
    const Eigen::Vector2d xr = meridional.point(meridional.check_param(q.y()));
    const double th = theta0 + q.x();
    return Eigen::Vector3d(xr.x(), xr.y() * std::cos(th), xr.y() * std::sin(th));
  };
  // The iso-curve's distinct knots in one period: (U, V) of its points is smooth between them, so the
  // pcurve's knots are these, each span cut into equal parts (odd degree: knots at the data).
  std::vector<double> breaks;
  for (double k : iso.knots())
    if (k >= a && k < a + T && (breaks.empty() || k > breaks.back())) breaks.push_back(k);
  BSplineCurve<2> pc;
  for (int per_span = 1;; per_span *= 2) {
    std::vector<double> params;
    std::vector<Eigen::Vector2d> pts;
    for (std::size_t i = 0; i < breaks.size(); ++i) {
      const double lo = breaks[i], hi = i + 1 < breaks.size() ? breaks[i + 1] : a + T;
      for (int j = 0; j < per_span; ++j) {
        params.push_back((lo + (hi - lo) * j / per_span - a) / T);
        pts.push_back(uv(a + T * params.back()));
      }
    }
    pc = reparametrized(interpolate_closed<2>(pts, 3, params, params), a, a + T);
    deviation = 0;
    for (std::size_t i = 0; i < params.size(); ++i) {
      const double u = a + T * 0.5 * (params[i] + (i + 1 < params.size() ? params[i + 1] : 1.0));
      deviation = std::max(deviation, (on_surface(pc.point(u)) - on_surface(uv(u))).norm());
    }
    if (deviation <= target || per_span >= 32) break;
  }
  // Non-periodic form, as OCCT's own intersection pcurves.
  return occt::to_occt(to_non_periodic(pc));
}

// The end face on `trim` bounded by the closed wall edge `edge` (the iso-curve `iso`); sets the edge's
// and its vertex's tolerance to `tol` (the iso-curve's distance from the trim, with a margin) plus the
// pcurve's own error.
TopoDS_Face end_face(const EndTrim& trim, const TopoDS_Edge& edge, const BSplineCurve<3>& iso, double theta0,
                     double tol, const char* which) {
  BRep_Builder bb;
  TopoDS_Wire wire;
  bb.MakeWire(wire);
  bb.Add(wire, edge);
  if (const auto* pl = std::get_if<PlaneTrim>(&trim)) {
    const Eigen::Vector3d n = pl->normal.normalized();
    bb.UpdateEdge(edge, tol);
    for (TopExp_Explorer v(edge, TopAbs_VERTEX); v.More(); v.Next()) bb.UpdateVertex(TopoDS::Vertex(v.Current()), tol);
    BRepBuilderAPI_MakeFace mk(gp_Pln(gp_Pnt(pl->point.x(), pl->point.y(), pl->point.z()), gp_Dir(n.x(), n.y(), n.z())),
                               wire, /*Inside=*/true);
    if (!mk.IsDone()) throw AlgorithmFailure(std::string("cannot make the ") + which + " end face");
    return mk.Face();
  }
  const RevolvedTrim& r = std::get<RevolvedTrim>(trim);
  const Handle(Geom_SurfaceOfRevolution) rev = revolved_surface(r, theta0, which);
  double dev = 0;
  // The pcurve adds at most a tenth of the edge's own tolerance.
  const Handle(Geom2d_BSplineCurve) pc = revolved_pcurve(iso, r.meridional, theta0, 0.1 * tol, dev);
  tol += 1.5 * dev;
  bb.UpdateEdge(edge, pc, rev, TopLoc_Location(), tol);
  for (TopExp_Explorer v(edge, TopAbs_VERTEX); v.More(); v.Next()) bb.UpdateVertex(TopoDS::Vertex(v.Current()), tol);
  BRepBuilderAPI_MakeFace mk(rev, wire, /*Inside=*/true);
  if (!mk.IsDone()) throw AlgorithmFailure(std::string("cannot make the ") + which + " end face");
  return mk.Face();
}

BladeSolid iso_trimmed_solid(const BSplineSurface<3>& surface, const EndTrim& hub, const EndTrim& casing,
                             double hub_dev, double casing_dev, const BSplineCurve<3>& hub_iso,
                             const BSplineCurve<3>& casing_iso) {
  const PoleBox box = pole_box(surface);
  const Sector sector = blade_sector(surface, box);
  const Handle(Geom_BSplineSurface) gs = occt::to_occt(surface);
  BRepBuilderAPI_MakeFace mk(gs, surface.first_u(), surface.last_u(), 0.0, 1.0, Precision::Confusion());
  if (!mk.IsDone()) throw AlgorithmFailure("cannot make the blade wall face");
  const TopoDS_Face wall = mk.Face();
  TopoDS_Edge bottom, top;
  for (TopExp_Explorer e(wall, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    if (BRep_Tool::IsClosed(edge, wall)) continue;  // the seam
    double a = 0, b = 0;
    const gp_Pnt2d mid = BRep_Tool::CurveOnSurface(edge, wall, a, b)->Value(0.5 * (a + b));
    (std::abs(mid.Y()) < 0.5 ? bottom : top) = edge;
  }
  if (bottom.IsNull() || top.IsNull()) throw AlgorithmFailure("the blade wall face has no end edges at v = 0 and 1");
  const double floor_tol = Precision::Confusion();
  const TopoDS_Face hub_face =
      end_face(hub, bottom, hub_iso, sector.start, std::max(floor_tol, 1.5 * hub_dev), "hub");
  const TopoDS_Face casing_face =
      end_face(casing, top, casing_iso, sector.start, std::max(floor_tol, 1.5 * casing_dev), "casing");
  BladeSolid out = close_solid(wall, {hub_face}, {casing_face}, BRep_Tool::Surface(wall),
                               BRep_Tool::Surface(hub_face), BRep_Tool::Surface(casing_face));
  out.trimmed_along_iso_curves = true;
  return out;
}

}  // namespace

BladeSolid build_blade_solid(const BSplineSurface<3>& surface, const EndTrim& hub, const EndTrim& casing,
                             ProgressSink* progress) {
  require(surface.num_poles_u() > 0, "blade surface is empty");
  require(surface.is_periodic_u(), "blade surface must be periodic in u (closed chordwise section)");
  require(!surface.is_periodic_v(), "blade surface must not be periodic in v (spanwise)");

  const PoleBox box = pole_box(surface);
  const Sector sector = blade_sector(surface, box);

  const TopoDS_Face blade = [&] {
    BRepBuilderAPI_MakeFace mk(occt::to_occt(surface), Precision::Confusion());
    if (!mk.IsDone()) throw AlgorithmFailure("cannot make a face of the blade surface");
    return mk.Face();
  }();
  const TopoDS_Face hub_face = trim_face(hub, box, sector, "hub");
  const TopoDS_Face casing_face = trim_face(casing, box, sector, "casing");

  BOPAlgo_Builder gf;
  gf.AddArgument(blade);
  gf.AddArgument(hub_face);
  gf.AddArgument(casing_face);
  gf.SetRunParallel(true);
  const Handle(OcctProgress) fuse_progress = new OcctProgress(progress, "general fuse");
  gf.Perform(fuse_progress->Start());
  fuse_progress->throw_if_stopped();
  if (gf.HasErrors())
    throw AlgorithmFailure("cutting the blade surface by hub and casing failed: " + joined(alert_names(gf, Message_Fail)));

  const auto blade_pieces = pieces_of(gf, blade);
  const auto hub_pieces = pieces_of(gf, hub_face);
  const auto casing_pieces = pieces_of(gf, casing_face);
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(gf.Shape(), TopAbs_EDGE, TopAbs_FACE, edge_faces);

  std::vector<TopoDS_Face> walls;
  for (const auto& p : blade_pieces)
    if (touches(p, hub_pieces, edge_faces) && touches(p, casing_pieces, edge_faces)) walls.push_back(p);
  if (walls.size() != 1)
    throw AlgorithmFailure("the hub and casing trims must cut the blade surface into one wall between them, found " +
                           std::to_string(walls.size()) +
                           " (is the blade over-built past both trims, and do the trims stay apart inside the blade?)");
  const TopoDS_Face wall = walls.front();
  const auto hub_ends = end_faces(hub_pieces, wall);
  const auto casing_ends = end_faces(casing_pieces, wall);
  if (hub_ends.empty() || casing_ends.empty())
    throw AlgorithmFailure(std::string("the ") + (hub_ends.empty() ? "hub" : "casing") +
                           " trim does not close the blade section (does its meridional curve cover the blade's axial extent?)");

  BladeSolid out = close_solid(wall, hub_ends, casing_ends, BRep_Tool::Surface(blade), BRep_Tool::Surface(hub_face),
                               BRep_Tool::Surface(casing_face));
  out.warnings = alert_names(gf, Message_Warning);
  return out;
}

EndTrim hub_trim(const blade::FlowPathTrim& t) {
  if (t.straight) return PlaneTrim{Eigen::Vector3d(0, 0, t.hub_z), Eigen::Vector3d::UnitZ()};
  return RevolvedTrim{t.hub};
}

EndTrim casing_trim(const blade::FlowPathTrim& t) {
  if (t.straight) return PlaneTrim{Eigen::Vector3d(0, 0, t.casing_z), Eigen::Vector3d::UnitZ()};
  return RevolvedTrim{t.casing};
}

BladeSolid build_blade_solid(const blade::BladeModel& model, ProgressSink* progress) {
  const EndTrim hub = hub_trim(model.trim), casing = casing_trim(model.trim);
  const BSplineCurve<3> hub_iso = blade::detail::iso_curve_v(model.surface, 0.0),
                        casing_iso = blade::detail::iso_curve_v(model.surface, 1.0);
  const double hub_dev = iso_deviation(hub_iso, hub), casing_dev = iso_deviation(casing_iso, casing);
  // The model's end sections lie on the trims within its surface tolerance; anything else (a surface
  // edited by hand) takes the general fuse.
  const double allowed = std::max(model.surface_tolerance, 1e-7);
  if (model.surface.first_v() < 0 && model.surface.last_v() > 1 && hub_dev <= allowed && casing_dev <= allowed) {
    // Milliseconds of work: one progress report and one check point.
    report_progress(progress, 0.0, "trimming along the wall's iso-curves");
    check_cancel(progress, "trimming along the wall's iso-curves");
    return iso_trimmed_solid(model.surface, hub, casing, hub_dev, casing_dev, hub_iso, casing_iso);
  }
  return build_blade_solid(model.surface, hub, casing, progress);
}

}  // namespace cg::brep
