#include "src/brep/boolean/boolean_volume.hpp"

#include <BOPTools_AlgoTools3D.hxx>
#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_OBB.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <IntTools_Context.hxx>
#include <OSD_Parallel.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/brep/face_flux.hpp"

namespace cg::features {
namespace {

// Relative accuracy of the face integrals: the volume itself (each face flux is of the order of the
// tool volume, so this is far below the 1e-6 tolerance), and the
// closure check, which only has to see gaps the size of a face.
constexpr double kFluxAccuracy = 1e-7, kClosureAccuracy = 1e-5;

struct OrientedPiece {
  TopoDS_Face face;  ///< oriented so its normal points out of the solid it bounds
  double sign;       ///< its contribution to the tool's volume is sign * flux
};

gp_Vec oriented_normal(const TopoDS_Face& f, double u, double v) {
  BRepAdaptor_Surface s(f, false);
  BRepLProp_SLProps props(s, u, v, 1, 1e-9);
  gp_Vec n = props.IsNormalDefined() ? gp_Vec(props.Normal()) : gp_Vec();
  return f.Orientation() == TopAbs_REVERSED ? -n : n;
}

// `piece` (a split of `original`) turned to the orientation `original` has in the part.
TopoDS_Face orient_like(const TopoDS_Face& piece, const TopoDS_Face& original) {
  TopLoc_Location lp, lo;
  const Handle(Geom_Surface)& sp = BRep_Tool::Surface(piece, lp);
  const Handle(Geom_Surface)& so = BRep_Tool::Surface(original, lo);
  TopoDS_Face r = piece;
  if (sp == so && lp.IsEqual(lo)) {
    r.Orientation(original.Orientation());
    return r;
  }
  // Different surface objects: compare normals at a point of the piece.
  gp_Pnt p;
  gp_Pnt2d uv;
  Handle(IntTools_Context) ctx = new IntTools_Context;
  if (BOPTools_AlgoTools3D::PointInFace(piece, p, uv, ctx) != 0) return r;
  GeomAPI_ProjectPointOnSurf proj(p, BRep_Tool::Surface(original));
  if (proj.NbPoints() == 0) return r;
  double u, v;
  proj.LowerDistanceParameters(u, v);
  if (oriented_normal(piece, uv.X(), uv.Y()).Dot(oriented_normal(original, u, v)) < 0) r.Reverse();
  return r;
}

Bnd_Box box_of(const TopoDS_Shape& s) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, /*useTriangulation=*/false);
  return b;
}

// Tool pieces kept in the result, as oriented there (appended to `pieces`, per tool), and each
// tool's box and oriented box. A piece shared with the part (`part_pieces`) is the part's.
void kept_tool_pieces(const BooleanRun& run, const std::vector<TopoDS_Shape>& tools, const TopTools_IndexedMapOfShape& result_faces,
                      const std::vector<TopoDS_Face>& as_in_result, const TopTools_IndexedMapOfShape& part_pieces,
                      double tool_sign, std::vector<std::vector<OrientedPiece>>& pieces, std::vector<Bnd_Box>& boxes,
                      std::vector<Bnd_OBB>& obbs) {
  const std::size_t n = tools.size();
  boxes.assign(n, Bnd_Box());
  obbs.assign(n, Bnd_OBB());
  for (std::size_t t = 0; t < n; ++t) {
    boxes[t] = box_of(tools[t]);
    BRepBndLib::AddOBB(tools[t], obbs[t], /*useTriangulation=*/false, /*optimal=*/false, /*useShapeTolerance=*/true);
    obbs[t].Enlarge(1e-6);
    TopTools_IndexedMapOfShape seen;
    for (TopExp_Explorer e(tools[t], TopAbs_FACE); e.More(); e.Next())
      for (const TopoDS_Shape& piece : pieces_of(run, e.Current())) {
        const int i = result_faces.FindIndex(piece);
        if (i > 0 && !part_pieces.Contains(piece) && seen.Add(piece))
          pieces[t].push_back({as_in_result[static_cast<std::size_t>(i - 1)], tool_sign});
      }
  }
}

// Dropped part pieces, oriented as in the part.
std::vector<OrientedPiece> dropped_part_pieces(const BooleanRun& run, const TopoDS_Shape& part,
                                               const TopTools_IndexedMapOfShape& result_faces, double part_sign) {
  std::vector<OrientedPiece> dropped;
  TopTools_IndexedMapOfShape dropped_seen;
  for (TopExp_Explorer e(part, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& original = TopoDS::Face(e.Current());
    for (const TopoDS_Shape& piece : pieces_of(run, original))
      if (!result_faces.Contains(piece) && dropped_seen.Add(piece))
        dropped.push_back({orient_like(TopoDS::Face(piece), original), part_sign});
  }
  return dropped;
}

// Candidate tools of each dropped piece by box: tools sorted by their lowest x, so a query only
// scans the tools whose x range can reach the piece (no scan of every tool per piece).
std::vector<std::vector<int>> candidate_tools(const std::vector<OrientedPiece>& dropped, const std::vector<Bnd_Box>& boxes,
                                              const std::vector<Bnd_OBB>& obbs) {
  const std::size_t n = boxes.size();
  std::vector<std::vector<int>> candidates(dropped.size());
  std::vector<std::pair<double, int>> by_x;
  double widest = 0;
  for (std::size_t t = 0; t < n; ++t) {
    double c[6];
    boxes[t].Get(c[0], c[1], c[2], c[3], c[4], c[5]);
    by_x.emplace_back(c[0], static_cast<int>(t));
    widest = std::max(widest, c[3] - c[0]);
  }
  std::sort(by_x.begin(), by_x.end());
  for (std::size_t k = 0; k < dropped.size(); ++k) {
    const Bnd_Box fb = box_of(dropped[k].face);
    double c[6];
    fb.Get(c[0], c[1], c[2], c[3], c[4], c[5]);
    auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(c[0] - widest, -1));
    for (; it != by_x.end() && it->first <= c[3]; ++it)
      if (!boxes[static_cast<std::size_t>(it->second)].IsOut(fb)) candidates[k].push_back(it->second);
    if (candidates[k].size() > 1) {  // neighbours' axis-aligned boxes overlap: oriented boxes decide
      Bnd_OBB fo;
      BRepBndLib::AddOBB(dropped[k].face, fo, false, false, true);
      std::vector<int> kept;
      for (const int t : candidates[k])
        if (!obbs[static_cast<std::size_t>(t)].IsOut(fo)) kept.push_back(t);
      candidates[k] = kept;
    }
  }
  return candidates;
}

// A point inside each dropped piece, then per tool one classifier for all the pieces it may hold
// (building a classifier explores the solid: once per tool, not once per piece). Each piece goes to
// the first tool holding it (appended to `pieces`); lost and ambiguous pieces are counted in m.
void assign_dropped_pieces(const std::vector<OrientedPiece>& dropped, const std::vector<std::vector<int>>& candidates,
                           const std::vector<TopoDS_Shape>& tools, bool parallel,
                           std::vector<std::vector<OrientedPiece>>& pieces, VolumeMeasure& m) {
  const std::size_t n = tools.size();
  std::vector<gp_Pnt> point(dropped.size());
  std::vector<char> has_point(dropped.size(), 0);
  OSD_Parallel::For(0, static_cast<int>(dropped.size()), [&](int k) {
    if (candidates[static_cast<std::size_t>(k)].empty()) return;
    gp_Pnt2d uv;
    Handle(IntTools_Context) ctx = new IntTools_Context;
    has_point[static_cast<std::size_t>(k)] =
        BOPTools_AlgoTools3D::PointInFace(dropped[static_cast<std::size_t>(k)].face, point[static_cast<std::size_t>(k)], uv, ctx) == 0;
  }, !parallel);
  std::vector<std::vector<int>> to_classify(n);
  for (std::size_t k = 0; k < dropped.size(); ++k)
    if (has_point[k])
      for (const int t : candidates[k]) to_classify[static_cast<std::size_t>(t)].push_back(static_cast<int>(k));
  std::vector<std::vector<int>> inside(n);
  OSD_Parallel::For(0, static_cast<int>(n), [&](int t) {
    const std::vector<int>& ks = to_classify[static_cast<std::size_t>(t)];
    if (ks.empty()) return;
    BRepClass3d_SolidClassifier cls(tools[static_cast<std::size_t>(t)]);
    for (const int k : ks) {
      cls.Perform(point[static_cast<std::size_t>(k)], 1e-7);
      if (cls.State() == TopAbs_IN || cls.State() == TopAbs_ON) inside[static_cast<std::size_t>(t)].push_back(k);
    }
  }, !parallel);
  std::vector<int> owner(dropped.size(), -1), owners(dropped.size(), 0);
  for (std::size_t t = 0; t < n; ++t)
    for (const int k : inside[t]) {
      if (owner[static_cast<std::size_t>(k)] < 0) owner[static_cast<std::size_t>(k)] = static_cast<int>(t);
      ++owners[static_cast<std::size_t>(k)];
    }
  for (std::size_t k = 0; k < dropped.size(); ++k) {
    if (owner[k] < 0) {
      ++m.lost_pieces;
      GProp_GProps a;
      BRepGProp::SurfaceProperties(dropped[k].face, a, 1e-6);
      m.lost_area += a.Mass();
      continue;
    }
    if (owners[k] > 1) ++m.ambiguous_pieces;
    pieces[static_cast<std::size_t>(owner[k])].push_back(dropped[k]);
    ++m.tools[static_cast<std::size_t>(owner[k])].part_pieces;
  }
}

gp_Pnt centre_of(const Bnd_Box& b) {
  double c[6];
  b.Get(c[0], c[1], c[2], c[3], c[4], c[5]);
  return gp_Pnt(0.5 * (c[0] + c[3]), 0.5 * (c[1] + c[4]), 0.5 * (c[2] + c[5]));
}

double face_flux(const TopoDS_Shape& face, const gp_Pnt& c, double accuracy) {
  return brep::face_volume_flux(TopoDS::Face(face), c, accuracy).value;
}

}  // namespace

VolumeMeasure measure_tool_volumes(const BooleanRun& run, const TopoDS_Shape& part, const std::vector<TopoDS_Shape>& tools,
                                   BooleanOperation op, bool parallel) {
  VolumeMeasure m;
  const std::size_t n = tools.size();
  m.tools.assign(n, {});
  std::vector<std::vector<OrientedPiece>> pieces(n);
  const double tool_sign = op == BooleanOperation::Cut ? -1 : 1, part_sign = -tool_sign;

  TopTools_IndexedMapOfShape result_faces;
  TopExp::MapShapes(run.result, TopAbs_FACE, result_faces);
  std::vector<TopoDS_Face> as_in_result(static_cast<std::size_t>(result_faces.Extent()));
  for (TopExp_Explorer e(run.result, TopAbs_FACE); e.More(); e.Next())
    as_in_result[static_cast<std::size_t>(result_faces.FindIndex(e.Current()) - 1)] = TopoDS::Face(e.Current());

  // Pieces of the part's faces. A piece shared with a tool face (coincident faces) is the part's: if
  // it is dropped it bounds the tool's region as a part piece; if it is kept the tool only touched
  // the part there from outside and it bounds nothing of the tool's region.
  TopTools_IndexedMapOfShape part_pieces;
  for (TopExp_Explorer e(part, TopAbs_FACE); e.More(); e.Next())
    for (const TopoDS_Shape& piece : pieces_of(run, e.Current())) part_pieces.Add(piece);

  // Tool pieces kept in the result, as oriented there.
  std::vector<Bnd_Box> boxes;
  std::vector<Bnd_OBB> obbs;
  kept_tool_pieces(run, tools, result_faces, as_in_result, part_pieces, tool_sign, pieces, boxes, obbs);

  // Dropped part pieces, oriented as in the part, then located in a tool.
  const std::vector<OrientedPiece> dropped = dropped_part_pieces(run, part, result_faces, part_sign);
  assign_dropped_pieces(dropped, candidate_tools(dropped, boxes, obbs), tools, parallel, pieces, m);

  OSD_Parallel::For(0, static_cast<int>(n), [&](int t) {
    const Bnd_Box& b = boxes[static_cast<std::size_t>(t)];
    const gp_Pnt c1 = centre_of(b);
    const double size = std::sqrt(b.SquareExtent());
    const gp_Pnt c2 = c1.Translated(gp_Vec(0.61, 0.70, 0.37).Normalized() * size);
    ToolVolume& tv = m.tools[static_cast<std::size_t>(t)];
    double v1 = 0, v2 = 0;
    TopTools_IndexedMapOfShape edges;
    for (const OrientedPiece& p : pieces[static_cast<std::size_t>(t)]) {
      v1 += p.sign * face_flux(p.face, c1, kFluxAccuracy);
      v2 += p.sign * face_flux(p.face, c2, kClosureAccuracy);
      if (p.sign == tool_sign) ++tv.tool_pieces;
      TopExp::MapShapes(p.face, TopAbs_EDGE, edges);
    }
    tv.volume = v1;
    tv.closure = std::abs(v1 - v2);
    double gap_area = 0;
    for (int k = 1; k <= edges.Extent(); ++k) {
      const TopoDS_Edge& e = TopoDS::Edge(edges(k));
      if (BRep_Tool::Degenerated(e)) continue;
      GProp_GProps lp;
      BRepGProp::LinearProperties(e, lp);
      gap_area += 2 * BRep_Tool::Tolerance(e) * lp.Mass();
    }
    double lever = 0, x[6];
    b.Get(x[0], x[1], x[2], x[3], x[4], x[5]);
    for (int k = 0; k < 8; ++k)
      lever = std::max(lever, c1.Distance(gp_Pnt(x[(k & 1) ? 3 : 0], x[(k & 2) ? 4 : 1], x[(k & 4) ? 5 : 2])));
    tv.uncertainty = lever * gap_area / 3;
  }, !parallel);
  return m;
}

}  // namespace cg::features
