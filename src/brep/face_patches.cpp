#include "src/brep/face_patches.hpp"

#include <BOPAlgo_Builder.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_OBB.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <cmath>

#include "src/brep/boolean/boolean_alerts.hpp"
#include "src/core/error.hpp"

namespace cg::features {
namespace {

struct Interval {
  double lo, hi;
  double centre() const { return 0.5 * (lo + hi); }
};

// Footprint of a tool's oriented box on the tangent plane at surface point p (derivatives su, sv), as
// parameter intervals around (u, v). Returns false when the plane misses the box.
bool footprint(const Bnd_OBB& obb, const gp_Pnt& p, const gp_Vec& su, const gp_Vec& sv, double u, double v,
               Interval& iu, Interval& iv) {
  const gp_Vec n = su.Crossed(sv);
  if (n.Magnitude() < 1e-12) return false;
  const gp_Vec nn = n.Normalized();
  const gp_XYZ ax[3] = {obb.XDirection() * obb.XHSize(), obb.YDirection() * obb.YHSize(), obb.ZDirection() * obb.ZHSize()};
  gp_XYZ corner[8];
  double dist[8];
  for (int k = 0; k < 8; ++k) {
    corner[k] = obb.Center() + ax[0] * ((k & 1) ? 1 : -1) + ax[1] * ((k & 2) ? 1 : -1) + ax[2] * ((k & 4) ? 1 : -1);
    dist[k] = gp_Vec(p.XYZ(), corner[k]).Dot(nn);
  }
  // Least-squares parameter offsets of an in-plane point: [su sv] (du, dv) = x - p.
  const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv), det = a * c - b * b;
  if (std::abs(det) < 1e-24) return false;
  iu = {HUGE_VAL, -HUGE_VAL};
  iv = {HUGE_VAL, -HUGE_VAL};
  bool any = false;
  for (int k = 0; k < 8; ++k)
    for (int bit = 1; bit < 8; bit <<= 1) {
      const int m = k | bit;
      if (m == k || (dist[k] > 0) == (dist[m] > 0)) continue;
      const double t = dist[k] / (dist[k] - dist[m]);
      const gp_Vec x(p.XYZ(), corner[k] + (corner[m] - corner[k]) * t);
      const double ru = x.Dot(su), rv = x.Dot(sv);
      const double du = (c * ru - b * rv) / det, dv = (a * rv - b * ru) / det;
      iu = {std::min(iu.lo, u + du), std::max(iu.hi, u + du)};
      iv = {std::min(iv.lo, v + dv), std::max(iv.hi, v + dv)};
      any = true;
    }
  if (!any) return false;
  const double mu = 0.1 * (iu.hi - iu.lo), mv = 0.1 * (iv.hi - iv.lo);  // curvature margin
  iu = {iu.lo - mu, iu.hi + mu};
  iv = {iv.lo - mv, iv.hi + mv};
  return true;
}

// Up to `count` cut positions in (lo, hi): near the quantiles of the footprint centres, moved to the
// middle of the nearest gap between the (merged) footprints when one exists.
std::vector<double> cut_positions(std::vector<Interval> fp, int count, double lo, double hi) {
  std::vector<double> cuts;
  if (count <= 0 || fp.empty()) return cuts;
  std::sort(fp.begin(), fp.end(), [](const Interval& p, const Interval& q) { return p.lo < q.lo; });
  std::vector<Interval> merged;
  for (const Interval& i : fp)
    if (!merged.empty() && i.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, i.hi);
    else merged.push_back(i);
  std::vector<double> gaps;  // middles of the gaps between merged footprints
  for (std::size_t k = 1; k < merged.size(); ++k) gaps.push_back(0.5 * (merged[k - 1].hi + merged[k].lo));
  std::vector<double> centres;
  for (const Interval& i : fp) centres.push_back(i.centre());
  std::sort(centres.begin(), centres.end());
  const double span = centres.back() - centres.front();
  for (int k = 1; k <= count; ++k) {
    const double target = centres[static_cast<std::size_t>(k * (centres.size() - 1) / (count + 1))];
    double best = target, dist = HUGE_VAL;
    for (double g : gaps)
      if (std::abs(g - target) < dist) dist = std::abs(g - target), best = g;
    // A gap farther than half a cell away would unbalance the cells: cut across tools instead.
    if (dist > 0.5 * span / (count + 1)) best = target;
    if (best > lo && best < hi && (cuts.empty() || std::abs(best - cuts.back()) > 1e-9)) cuts.push_back(best);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double p, double q) { return std::abs(p - q) < 1e-9; }), cuts.end());
  return cuts;
}

TopoDS_Edge iso_edge(const TopoDS_Face& face, bool along_v, double at, double t0, double t1) {
  TopLoc_Location loc;
  const Handle(Geom_Surface)& s = BRep_Tool::Surface(face, loc);
  const Handle(Geom_Curve) c = along_v ? s->UIso(at) : s->VIso(at);
  TopoDS_Edge e = BRepBuilderAPI_MakeEdge(c, t0, t1).Edge();
  e.Move(loc);
  const Handle(Geom2d_Line) line = along_v ? new Geom2d_Line(gp_Pnt2d(at, 0), gp_Dir2d(0, 1))
                                           : new Geom2d_Line(gp_Pnt2d(0, at), gp_Dir2d(1, 0));
  BRep_Builder().UpdateEdge(e, line, s, loc, BRep_Tool::Tolerance(e));
  return e;
}

}  // namespace

PatchedPart patch_faces(const brep::NamedShape& part, const std::vector<TopoDS_Shape>& tools, const PatchOptions& o) {
  require(o.min_tools >= 2 && o.tools_per_patch >= 1, "patches: min_tools >= 2 and tools_per_patch >= 1 required");
  PatchedPart r;
  r.part = part;
  r.faces_before = r.faces_after = static_cast<int>(part.faces.size());
  if (static_cast<int>(tools.size()) < o.min_tools) return r;

  std::vector<Bnd_Box> boxes(tools.size());
  std::vector<Bnd_OBB> obbs(tools.size());
  for (std::size_t i = 0; i < tools.size(); ++i) {
    BRepBndLib::Add(tools[i], boxes[i], /*useTriangulation=*/false);
    BRepBndLib::AddOBB(tools[i], obbs[i], /*theIsTriangulationUsed=*/false, /*theIsOptimal=*/false);
  }
  std::vector<TopoDS_Edge> cuts;
  for (TopExp_Explorer e(part.shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    Bnd_Box fbox;
    BRepBndLib::Add(face, fbox, false);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face);  // located
    GeomAPI_ProjectPointOnSurf proj;
    bool proj_ready = false;
    std::vector<Interval> fu, fv;
    for (std::size_t i = 0; i < tools.size(); ++i) {
      if (boxes[i].IsOut(fbox)) continue;
      if (!proj_ready) proj.Init(s, u0, u1, v0, v1), proj_ready = true;
      const gp_Pnt c(obbs[i].Center());
      proj.Perform(c);
      if (proj.NbPoints() == 0) continue;
      const double half_diag = std::sqrt(obbs[i].SquareExtent());
      if (proj.LowerDistance() > half_diag) continue;
      double u, v;
      proj.LowerDistanceParameters(u, v);
      gp_Pnt p;
      gp_Vec su, sv;
      s->D1(u, v, p, su, sv);
      Interval iu, iv;
      if (!footprint(obbs[i], p, su, sv, u, v, iu, iv)) continue;
      fu.push_back(iu);
      fv.push_back(iv);
    }
    const int n = static_cast<int>(fu.size());
    if (n < o.min_tools) continue;
    // Cells about square in space: split the count between the directions by the footprints' extents
    // (parameter extents times the mean speed |S_u|, |S_v| at the footprints).
    double ua = HUGE_VAL, ub = -HUGE_VAL, va = HUGE_VAL, vb = -HUGE_VAL, speed_u = 0, speed_v = 0;
    for (int k = 0; k < n; ++k) {
      const double cu = fu[static_cast<std::size_t>(k)].centre(), cv = fv[static_cast<std::size_t>(k)].centre();
      ua = std::min(ua, cu), ub = std::max(ub, cu), va = std::min(va, cv), vb = std::max(vb, cv);
      gp_Pnt p;
      gp_Vec su, sv;
      s->D1(cu, cv, p, su, sv);
      speed_u += su.Magnitude() / n, speed_v += sv.Magnitude() / n;
    }
    const double lu = (ub - ua) * speed_u + 1e-9, lv = (vb - va) * speed_v + 1e-9;
    const double cells = static_cast<double>(n) / o.tools_per_patch;
    const int nu = std::max(1, static_cast<int>(std::lround(std::sqrt(cells * lu / lv))));
    const int nv = std::max(1, static_cast<int>(std::lround(cells / nu)));
    for (double at : cut_positions(fu, nu - 1, u0, u1)) cuts.push_back(iso_edge(face, true, at, v0, v1));
    for (double at : cut_positions(fv, nv - 1, v0, v1)) cuts.push_back(iso_edge(face, false, at, u0, u1));
  }
  r.cut_lines = static_cast<int>(cuts.size());
  if (cuts.empty()) return r;

  BOPAlgo_Builder gf;
  for (TopExp_Explorer e(part.shape, TopAbs_SHELL); e.More(); e.Next()) gf.AddArgument(e.Current());
  for (const TopoDS_Edge& c : cuts) gf.AddArgument(c);
  gf.SetRunParallel(o.parallel);
  gf.SetNonDestructive(true);
  gf.SetUseOBB(true);
  gf.Perform();
  r.warnings = alert_names(gf.GetReport(), Message_Warning);
  if (gf.HasErrors()) throw AlgorithmFailure("splitting the part into patches failed: " + alert_summary(gf.GetReport()));

  BRep_Builder bb;
  TopoDS_Compound all;
  bb.MakeCompound(all);
  int solids = 0;
  for (TopExp_Explorer s(part.shape, TopAbs_SOLID); s.More(); s.Next(), ++solids) {
    TopoDS_Solid solid;
    bb.MakeSolid(solid);
    for (TopoDS_Iterator it(s.Current()); it.More(); it.Next()) {
      const TopTools_ListOfShape* im = gf.Images().Seek(it.Value());
      bb.Add(solid, im && !im->IsEmpty() ? im->First() : it.Value());
    }
    solid.Orientation(s.Current().Orientation());
    bb.Add(all, solid);
  }
  r.part.shape = solids == 1 ? TopoDS_Iterator(all).Value() : TopoDS_Shape(all);
  r.part.faces.clear();
  for (const brep::NamedFace& f : part.faces) {
    const TopTools_ListOfShape* im = gf.Images().Seek(f.face);
    if (!im || im->IsEmpty()) {
      r.part.faces.push_back(f);
      continue;
    }
    for (const TopoDS_Shape& piece : *im) r.part.faces.push_back({TopoDS::Face(piece), f.name});
  }
  r.faces_after = static_cast<int>(r.part.faces.size());
  return r;
}

}  // namespace cg::features
