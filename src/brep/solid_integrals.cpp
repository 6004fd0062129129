#include "src/brep/solid_integrals.hpp"

#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Sinert.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <OSD_Parallel.hxx>
#include <TopExp_Explorer.hxx>
#include <Geom2d_Curve.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <TopoDS_Iterator.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "src/brep/face_flux.hpp"
#include "src/core/parallel.hpp"

namespace cg::brep {
namespace {

// BRepGProp's reference point of a shell (the mean of its vertices): the volume of a closed shell does
// not depend on it, but the per-face terms do, so every piece of the shell uses the same one.
gp_Pnt mean_vertex(const TopoDS_Shape& s) {
  gp_XYZ xyz(0, 0, 0);
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_VERTEX); e.More(); e.Next(), ++n) xyz += BRep_Tool::Pnt(TopoDS::Vertex(e.Current())).XYZ();
  return gp_Pnt(n > 0 ? xyz / n : xyz);
}

// A wire that bounds a hole by itself: no seam or degenerated edge, and its pcurves return to their
// start in the parameter plane (a loop around a periodic direction does not).
bool closed_in_uv(const TopoDS_Wire& w, const TopoDS_Face& face) {
  gp_XY sum(0, 0), extent(0, 0);
  int edges = 0;
  for (TopoDS_Iterator it(w); it.More(); it.Next(), ++edges) {
    if (it.Value().ShapeType() != TopAbs_EDGE) return false;
    const TopoDS_Edge& e = TopoDS::Edge(it.Value());
    if (BRep_Tool::Degenerated(e) || BRep_Tool::IsClosed(e, face)) return false;
    double f = 0, l = 0;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(e, face, f, l);
    if (c.IsNull()) return false;
    gp_XY a = c->Value(f).XY(), b = c->Value(l).XY();
    if (e.Orientation() == TopAbs_REVERSED) std::swap(a, b);
    else if (e.Orientation() != TopAbs_FORWARD) return false;
    sum += b - a;
    extent.SetCoord(std::max(extent.X(), std::abs(b.X() - a.X())), std::max(extent.Y(), std::abs(b.Y() - a.Y())));
  }
  // Closure within 1e-9 of the loop's size (the pcurve ends of one vertex agree to ~1e-15 here; a loop
  // around a period is off by the whole period).
  return edges > 0 && sum.Modulus() <= 1e-9 * (1 + extent.Modulus());
}

// The face as pieces whose integrals add up to its own: itself, or (when it has inner wires closed in
// its parameter plane) one face per such wire and one with the rest, all on its surface, in its
// orientation.
void split_face(const TopoDS_Face& face, std::vector<TopoDS_Face>& out) {
  const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const TopoDS_Wire outer = BRepTools::OuterWire(fwd);
  std::vector<TopoDS_Shape> rest, alone;
  for (TopoDS_Iterator it(fwd); it.More(); it.Next()) {
    const TopoDS_Shape& s = it.Value();
    const bool hole = s.ShapeType() == TopAbs_WIRE && !s.IsSame(outer) && closed_in_uv(TopoDS::Wire(s), fwd);
    (hole ? alone : rest).push_back(s);
  }
  if (alone.empty()) {
    out.push_back(face);
    return;
  }
  BRep_Builder b;
  const auto piece = [&](const std::vector<TopoDS_Shape>& wires) {
    TopoDS_Face p = TopoDS::Face(fwd.EmptyCopied());
    for (const TopoDS_Shape& w : wires) b.Add(p, w);
    out.push_back(TopoDS::Face(p.Oriented(face.Orientation())));
  };
  if (!rest.empty()) piece(rest);
  for (const TopoDS_Shape& w : alone) piece({w});
}

struct Item {
  TopoDS_Face face;
  gp_Pnt origin;
  bool volume = false;  ///< volume (Vinert) or area (Sinert)
  int cost = 0;         ///< edges: the integration cost grows with the boundary
  double value = 0, error = 0;
};

}  // namespace

SolidIntegrals integrate_solid(const TopoDS_Shape& shape, double eps, bool parallel, Integrals which) {
  SolidIntegrals r;
  std::vector<Item> items;
  const auto add = [&](const TopoDS_Face& f, const gp_Pnt& origin, bool volume) {
    TopLoc_Location loc;
    if (BRep_Tool::Surface(f, loc).IsNull()) return;  // BRepGProp skips such faces too
    std::vector<TopoDS_Face> pieces;
    if (volume) pieces.push_back(f);  // face_volume_flux starts each closed loop's strips at the loop
    else split_face(f, pieces);
    for (const TopoDS_Face& p : pieces) {
      int cost = 1;
      for (TopExp_Explorer e(p, TopAbs_EDGE); e.More(); e.Next()) ++cost;
      items.push_back({p, origin, volume, cost});
    }
  };
  // As BRepGProp::VolumeProperties(OnlyClosed = true): the forward and reversed faces of closed shells.
  for (TopExp_Explorer sh(shape, TopAbs_SHELL); which != Integrals::Area && sh.More(); sh.Next()) {
    if (!BRep_Tool::IsClosed(sh.Current())) continue;
    const gp_Pnt origin = mean_vertex(sh.Current());
    for (TopExp_Explorer f(sh.Current(), TopAbs_FACE); f.More(); f.Next()) {
      const TopAbs_Orientation o = f.Current().Orientation();
      if (o == TopAbs_FORWARD || o == TopAbs_REVERSED) add(TopoDS::Face(f.Current()), origin, true);
    }
  }
  // As BRepGProp::SurfaceProperties: every face.
  if (which != Integrals::Volume) {
    const gp_Pnt origin = mean_vertex(shape);
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) add(TopoDS::Face(f.Current()), origin, false);
  }
  r.pieces = static_cast<int>(items.size());

  // Largest first, each taken by the next free thread: the walls with many holes do not end up last.
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return items[a].cost > items[b].cost; });
  parallel_for(static_cast<int>(order.size()), parallel ? parallel_workers() : 1, [&](int k, int) {
    Item& it = items[order[static_cast<std::size_t>(k)]];
    if (it.volume) {
      const FaceFlux f = face_volume_flux(it.face, it.origin, eps);
      it.value = f.value;
      it.error = f.error;
    } else {
      BRepGProp_Face bf;
      BRepGProp_Domain bd;
      bf.Load(it.face);
      bd.Init(it.face);
      BRepGProp_Sinert g;
      g.SetLocation(it.origin);
      g.Perform(bf, bd, eps);
      it.value = g.Mass();
      it.error = g.GetEpsilon();
    }
  });
  // Summed in the fixed order of the faces: the same result however the threads ran.
  for (const Item& it : items) {
    if (it.volume) {
      r.volume += it.value;
      r.volume_error += it.error;
    } else {
      r.area += it.value;
    }
  }
  return r;
}

double shape_volume(const TopoDS_Shape& shape, double eps) {
  constexpr int kParallelFaces = 64;  // below this the threads cost more than they save
  const gp_Pnt origin = mean_vertex(shape);
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    TopLoc_Location loc;
    if (!BRep_Tool::Surface(TopoDS::Face(f.Current()), loc).IsNull()) faces.push_back(TopoDS::Face(f.Current()));
  }
  const int n = static_cast<int>(faces.size());
  std::vector<double> flux(faces.size(), 0.0);
  parallel_for(n, n >= kParallelFaces ? parallel_workers() : 1, [&](int i, int) {
    flux[static_cast<std::size_t>(i)] = face_volume_flux(faces[static_cast<std::size_t>(i)], origin, eps).value;
  });
  double v = 0;
  for (const double f : flux) v += f;  // in face order: the same sum however the threads ran
  return v;
}

double volume_of(const TopoDS_Shape& shape) { return shape_volume(shape, 1e-7); }

std::vector<double> volumes_of(const std::vector<TopoDS_Shape>& shapes) {
  std::vector<double> v(shapes.size(), 0.0);
  // Read-only on the shapes (each integration has its own surface adaptors), so they run in parallel.
  OSD_Parallel::For(0, static_cast<int>(shapes.size()),
                    [&](int i) { v[static_cast<std::size_t>(i)] = volume_of(shapes[static_cast<std::size_t>(i)]); });
  return v;
}

}  // namespace cg::brep
