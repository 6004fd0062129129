#include "src/brep/boolean/false_seams.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <cmath>
#include <limits>
#include <vector>

#include "src/brep/naming/face_names.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

struct FalseSeam {
  TopoDS_Edge edge;
  TopoDS_Face f1, f2;  // f1 gets its own surface
};

// Faces of `part` adjacent to each edge (distinct faces only).
std::vector<FalseSeam> find_false_seams(const TopoDS_Shape& part) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(part, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<FalseSeam> out;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    std::vector<TopoDS_Face> faces;
    for (const TopoDS_Shape& f : edge_faces(i)) {
      bool seen = false;
      for (const TopoDS_Face& g : faces) seen |= g.IsSame(f);
      if (!seen) faces.push_back(TopoDS::Face(f));
    }
    if (faces.size() != 2) continue;
    const TopoDS_Edge e = TopoDS::Edge(edge_faces.FindKey(i));
    if (!BRep_Tool::IsClosed(e, faces[0]) || !BRep_Tool::IsClosed(e, faces[1])) continue;
    TopLoc_Location l0, l1;
    if (BRep_Tool::Surface(faces[0], l0) != BRep_Tool::Surface(faces[1], l1) || !(l0 == l1)) continue;
    out.push_back({e, faces[0], faces[1]});
  }
  return out;
}

// Distance in the face's (u, v) from the point of pcurve `c` (of edge `e` on `f`) at vertex `v` to where
// the face's other edges through `v` have it: the pcurve that closes the face's wire there is 0 away.
double mismatch_at(const TopoDS_Face& f, const TopoDS_Edge& e, const Handle(Geom2d_Curve)& c, const TopoDS_Vertex& v) {
  const gp_Pnt2d p = c->Value(BRep_Tool::Parameter(v, e));
  double best = std::numeric_limits<double>::infinity();
  for (TopExp_Explorer x(f, TopAbs_EDGE); x.More(); x.Next()) {
    const TopoDS_Edge g = TopoDS::Edge(x.Current());
    if (g.IsSame(e)) continue;
    TopoDS_Vertex a, b;
    TopExp::Vertices(g, a, b);
    for (const TopoDS_Vertex& w : {a, b}) {
      if (!w.IsSame(v)) continue;
      double first, last;
      const Handle(Geom2d_Curve) gc = BRep_Tool::CurveOnSurface(g, f, first, last);
      if (gc.IsNull()) continue;
      best = std::min(best, gc->Value(BRep_Tool::Parameter(w, g, f)).Distance(p));
    }
  }
  return best;
}

// Of the edge's two pcurves on the shared surface, the one that belongs to face `f`.
Handle(Geom2d_Curve) own_pcurve(const TopoDS_Face& f, const TopoDS_Edge& e) {
  double first, last;
  const Handle(Geom2d_Curve) c1 = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), f, first, last);
  const Handle(Geom2d_Curve) c2 = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Oriented(TopAbs_REVERSED)), f, first, last);
  TopoDS_Vertex a, b;
  TopExp::Vertices(e, a, b);
  const double m1 = std::max(mismatch_at(f, e, c1, a), mismatch_at(f, e, c1, b));
  const double m2 = std::max(mismatch_at(f, e, c2, a), mismatch_at(f, e, c2, b));
  // The two candidates lie a period apart; the right one meets the neighbours within the tolerances.
  if (!(std::min(m1, m2) < 1e-3 && std::max(m1, m2) > 100 * std::min(m1, m2)))
    throw FeatureFailure("false seam repair: cannot tell which pcurve of a seam edge belongs to which face (mismatch " +
                         std::to_string(m1) + " / " + std::to_string(m2) + ")");
  return m1 < m2 ? c1 : c2;
}

// Uses of edge `e` in face `f` (a true seam is used twice).
int uses(const TopoDS_Face& f, const TopoDS_Edge& e) {
  int n = 0;
  for (TopExp_Explorer x(f, TopAbs_EDGE); x.More(); x.Next()) n += x.Current().IsSame(e);
  return n;
}

// Gives `s.f1` its own copy of the surface; every false seam of f1 (here or with another face on the
// shared surface) keeps on the shared surface only the other face's pcurve.
void repair(const FalseSeam& s, const std::vector<FalseSeam>& all) {
  TopLoc_Location loc;
  const Handle(Geom_Surface) shared = BRep_Tool::Surface(s.f1, loc);
  const Handle(Geom_Surface) own = Handle(Geom_Surface)::DownCast(shared->Copy());
  // Pcurves of f1's edges, read while f1 still lies on the shared surface.
  struct PCurves {
    TopoDS_Edge edge;
    Handle(Geom2d_Curve) a, b;  // b: the second pcurve of a true seam of f1
    Handle(Geom2d_Curve) other;  // false seam: the other face's pcurve (stays on the shared surface)
  };
  std::vector<PCurves> pcs;
  TopTools_IndexedMapOfShape done;
  for (TopExp_Explorer x(s.f1, TopAbs_EDGE); x.More(); x.Next()) {
    const TopoDS_Edge e = TopoDS::Edge(x.Current());
    if (done.Contains(e)) continue;
    done.Add(e);
    double first, last;
    if (!BRep_Tool::IsClosed(e, s.f1)) {
      pcs.push_back({e, BRep_Tool::CurveOnSurface(e, s.f1, first, last), {}, {}});
    } else if (uses(s.f1, e) == 2) {
      pcs.push_back({e, BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), s.f1, first, last),
                     BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Oriented(TopAbs_REVERSED)), s.f1, first, last), {}});
    } else {
      const FalseSeam* seam = nullptr;
      for (const FalseSeam& t : all)
        if (t.edge.IsSame(e)) seam = &t;
      if (!seam) throw FeatureFailure("false seam repair: a seam edge used once by a face has no second face");
      const TopoDS_Face& other = seam->f1.IsSame(s.f1) ? seam->f2 : seam->f1;
      pcs.push_back({e, own_pcurve(s.f1, e), {}, own_pcurve(other, e)});
    }
  }
  BRep_Builder bb;
  bb.UpdateFace(s.f1, own, loc, BRep_Tool::Tolerance(s.f1));
  for (const PCurves& p : pcs) {
    const double tol = BRep_Tool::Tolerance(p.edge);
    if (p.b.IsNull()) bb.UpdateEdge(p.edge, p.a, own, loc, tol);
    else bb.UpdateEdge(p.edge, p.a, p.b, own, loc, tol);
    if (!p.other.IsNull()) bb.UpdateEdge(p.edge, p.other, shared, loc, tol);  // replaces the seam pair
  }
}

}  // namespace

FalseSeamRepair repair_false_seams(const brep::NamedShape& part) {
  FalseSeamRepair out;
  if (find_false_seams(part.shape).empty()) {
    out.shape = part;
    return out;
  }
  // Repair a copy (shared geometry, new topology): the input stays as it was.
  BRepBuilderAPI_Copy copy(part.shape, false, false);
  const TopoDS_Shape shape = copy.Shape();
  const std::vector<FalseSeam> seams = find_false_seams(shape);
  // The checks look at the repaired faces only (the rest of the part is untouched): each face valid
  // (BRepCheck: its wires close in (u, v) on the new pcurves, pcurves same-parameter with the edges) and
  // the faces' share of the volume integral (divergence theorem) unchanged.
  BRep_Builder bb;
  TopoDS_Compound touched;
  bb.MakeCompound(touched);
  TopTools_IndexedMapOfShape faces;
  for (const FalseSeam& s : seams) faces.Add(s.f1), faces.Add(s.f2);
  for (int i = 1; i <= faces.Extent(); ++i) bb.Add(touched, faces(i));
  const double v0 = volume_of(touched);
  for (const FalseSeam& s : seams)
    if (BRep_Tool::IsClosed(s.edge, s.f1)) repair(s, seams);  // else repaired with an earlier edge's face
  out.repaired_edges = static_cast<int>(seams.size());
  if (!find_false_seams(shape).empty()) throw FeatureFailure("false seam repair: false seams remain");
  for (int i = 1; i <= faces.Extent(); ++i)
    if (!BRepCheck_Analyzer(faces(i)).IsValid()) throw FeatureFailure("false seam repair: a repaired face is not valid");
  const double v1 = volume_of(touched);
  if (!(std::abs(v1 - v0) <= 1e-9 * (std::abs(v0) + 1.0))) {
    const ValueLimitText t = format_value_limit(v1, v0, Allowed::near);
    throw FeatureFailure("false seam repair changed the faces' volume integral (" + t.limit + " -> " + t.value + " mm^3)");
  }
  out.shape.shape = shape;
  out.shape.faces = FaceNames(part.faces).carried(copy, shape).list(shape, "false seam repair");
  return out;
}

}  // namespace cg::features
