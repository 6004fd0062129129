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
#include <ShapeFix_Shell.hxx>
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
#include <sstream>

#include "adaptors/occt_convert.hpp"
#include "src/brep/occt_progress.hpp"
#include "src/core/error.hpp"

namespace cg::brep {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

// Face on the surface of revolution of the meridional curve (x, r) about the x axis, over the
// angular sector only: a smaller face makes the general fuse ~2.5x faster than a full revolution.
// The basis curve lies at angle sector.start (for a full revolution that is the seam, opposite the
// blade, so the end face cut out of it carries no seam).
TopoDS_Face revolved_face(const RevolvedTrim& t, const Sector& sector, const char* which) {
  const BSplineCurve<2>& c = t.meridional;
  require(c.num_poles() >= 2, std::string(which) + " meridional curve needs at least 2 poles");
  require(!c.is_periodic(), std::string(which) + " meridional curve must not be periodic");
  std::vector<Eigen::Vector3d> poles;
  const double theta0 = sector.start;
  for (int i = 0; i < c.num_poles(); ++i) {
    const Eigen::Vector2d q = c.pole(i);
    require(q.allFinite() && q.y() > 0.0, std::string(which) + " meridional curve: pole " + std::to_string(i) +
                                              " has r = " + std::to_string(q.y()) + ", r must be > 0");
    poles.emplace_back(q.x(), q.y() * std::cos(theta0), q.y() * std::sin(theta0));
  }
  const BSplineCurve<3> c3(c.degree(), c.knots(), poles, c.is_rational() ? c.weights() : std::vector<double>{});
  Handle(Geom_SurfaceOfRevolution) rev = new Geom_SurfaceOfRevolution(occt::to_occt(c3), gp_Ax1(gp::Origin(), gp::DX()));
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
  out.warnings = alert_names(gf, Message_Warning);
  const Handle(Geom_Surface) wall_s = BRep_Tool::Surface(blade), hub_s = BRep_Tool::Surface(hub_face),
                             casing_s = BRep_Tool::Surface(casing_face);
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face f = TopoDS::Face(e.Current());
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f);
    const char* name = s == wall_s ? kWallFaceName : s == hub_s ? kHubFaceName : s == casing_s ? kCasingFaceName : nullptr;
    if (!name) throw AlgorithmFailure("a face of the blade solid lies on none of the blade, hub and casing surfaces");
    out.faces.push_back({f, name});
  }
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
  return build_blade_solid(model.surface, hub_trim(model.trim), casing_trim(model.trim), progress);
}

}  // namespace cg::brep
