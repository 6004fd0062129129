#include "features/drilling/drill_hole_topology.hpp"

#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/core/constants.hpp"

namespace cg::features {
namespace {

constexpr double kMinTolerance = 1e-7;  // Precision::Confusion(): OCCT's floor for any tolerance


// The cylinder pcurve (theta(s), t(s)) = (2 pi s, t(s)) as a clamped B-spline on [0, 1]: the periodic
// interpolant of t made non-periodic, and x set to 2 pi times the Greville abscissae (a B-spline with
// Greville poles reproduces the linear function exactly: linear precision).
Handle(Geom2d_BSplineCurve) cylinder_pcurve(const HoleLoop& loop) {
  Handle(Geom2d_BSplineCurve) c = occt::to_occt(loop.cylinder_pcurve);
  c->SetNotPeriodic();
  const int n = c->NbPoles(), p = c->Degree();
  TColStd_Array1OfReal k(1, n + p + 1);
  c->KnotSequence(k);
  for (int i = 1; i <= n; ++i) {
    double g = 0;
    for (int j = i + 1; j <= i + p; ++j) g += k(j);
    c->SetPole(i, gp_Pnt2d(2 * kPi * g / p, c->Pole(i).Y()));
  }
  return c;
}

// Signed area of the loop's (u, v) polygon (> 0: counterclockwise) and the length of its 3D polygon,
// sampled at four points per node.
void loop_measures(const HoleLoop& loop, double& area, double& length) {
  area = 0, length = 0;
  const int n = 4 * loop.nodes;
  Eigen::Vector2d q0 = loop.pcurve.point(0);
  Eigen::Vector3d p0 = loop.curve.point(0);
  for (int k = 1; k <= n; ++k) {
    const double s = static_cast<double>(k % n) / n;
    const Eigen::Vector2d q = loop.pcurve.point(s);
    const Eigen::Vector3d p = loop.curve.point(s);
    area += 0.5 * (q0.x() * q.y() - q.x() * q0.y());
    length += (p - p0).norm();
    q0 = q, p0 = p;
  }
}

LoopEdge loop_edge(const HoleLoop& loop, const WallFaceGeometry& wall, const Handle(Geom_Surface)& cylinder,
                   const TopoDS_Vertex& v) {
  BRep_Builder b;
  LoopEdge e;
  e.tolerance = std::max(kMinTolerance, 1.5 * loop.deviation);
  b.MakeEdge(e.edge, occt::to_occt(loop.curve), e.tolerance);
  b.Add(e.edge, v.Oriented(TopAbs_FORWARD));
  b.Add(e.edge, v.Oriented(TopAbs_REVERSED));
  b.UpdateEdge(e.edge, occt::to_occt(loop.pcurve), wall.surface, wall.location, e.tolerance);
  b.UpdateEdge(e.edge, cylinder_pcurve(loop), cylinder, TopLoc_Location(), e.tolerance);
  b.Range(e.edge, 0, 1);
  double area = 0;
  loop_measures(loop, area, e.length);
  e.counterclockwise = area > 0;
  return e;
}

}  // namespace

HoleShape build_hole_shape(const HoleCylinder& h, const HoleLoop& entry, const WallFaceGeometry& entry_wall,
                           const HoleLoop& exit, const WallFaceGeometry& exit_wall) {
  BRep_Builder b;
  const Handle(Geom_Surface) cylinder =
      new Geom_CylindricalSurface(gp_Ax3(occt::to_pnt(h.o), gp_Dir(h.d.x(), h.d.y(), h.d.z()), gp_Dir(h.e1.x(), h.e1.y(), h.e1.z())),
                                  h.radius);
  HoleShape s;
  TopoDS_Vertex va, vb;
  const double tol_a = std::max(kMinTolerance, 1.5 * entry.deviation), tol_b = std::max(kMinTolerance, 1.5 * exit.deviation);
  b.MakeVertex(va, occt::to_pnt(entry.start), tol_a);
  b.MakeVertex(vb, occt::to_pnt(exit.start), tol_b);
  s.entry = loop_edge(entry, entry_wall, cylinder, va);
  s.exit = loop_edge(exit, exit_wall, cylinder, vb);

  // Seam: the ruling at theta = 0 from the entry loop to the exit loop; pcurves theta = 2 pi (FORWARD,
  // up the right side of the (theta, t) rectangle) and theta = 0 (REVERSED, down its left side).
  const double t0 = entry.cylinder_pcurve.point(0)[1], t1 = exit.cylinder_pcurve.point(0)[1];
  TopoDS_Edge seam;
  b.MakeEdge(seam, new Geom_Line(occt::to_pnt(h.ruling(0, h.radius)), gp_Dir(h.d.x(), h.d.y(), h.d.z())), kMinTolerance);
  b.Add(seam, va.Oriented(TopAbs_FORWARD));
  b.Add(seam, vb.Oriented(TopAbs_REVERSED));
  b.UpdateEdge(seam, new Geom2d_Line(gp_Pnt2d(2 * kPi, 0), gp_Dir2d(0, 1)), new Geom2d_Line(gp_Pnt2d(0, 0), gp_Dir2d(0, 1)),
               cylinder, TopLoc_Location(), kMinTolerance);
  b.Range(seam, t0, t1);

  // Counterclockwise boundary of [0, 2 pi] x [t_entry, t_exit]: entry loop, right seam, exit loop
  // backwards, left seam.
  TopoDS_Wire w;
  b.MakeWire(w);
  b.Add(w, s.entry.edge.Oriented(TopAbs_FORWARD));
  b.Add(w, seam.Oriented(TopAbs_FORWARD));
  b.Add(w, s.exit.edge.Oriented(TopAbs_REVERSED));
  b.Add(w, seam.Oriented(TopAbs_REVERSED));
  w.Closed(true);
  b.MakeFace(s.face, cylinder, TopLoc_Location(), kMinTolerance);
  b.Add(s.face, w);
  return s;
}

TopoDS_Face wall_with_holes(const TopoDS_Face& wall, const std::vector<LoopEdge*>& loops) {
  BRep_Builder b;
  const TopoDS_Face f0 = TopoDS::Face(wall.Oriented(TopAbs_FORWARD));
  TopLoc_Location loc;
  const Handle(Geom_Surface) s = BRep_Tool::Surface(f0, loc);
  TopoDS_Face f;
  b.MakeFace(f, s, loc, BRep_Tool::Tolerance(f0));
  for (TopoDS_Iterator it(f0); it.More(); it.Next()) b.Add(f, it.Value());
  for (LoopEdge* l : loops) {
    TopoDS_Wire w;
    b.MakeWire(w);
    b.Add(w, l->edge.Oriented(l->counterclockwise ? TopAbs_REVERSED : TopAbs_FORWARD));  // clockwise
    w.Closed(true);
    b.Add(f, w);
    l->wire = w;
  }
  f.Orientation(wall.Orientation());
  return f;
}

TopoDS_Face cap_face(const TopoDS_Face& wall, const LoopEdge& loop) {
  BRep_Builder b;
  TopLoc_Location loc;
  const Handle(Geom_Surface) s = BRep_Tool::Surface(wall, loc);
  TopoDS_Face f;
  b.MakeFace(f, s, loc, BRep_Tool::Tolerance(wall));
  TopoDS_Wire w;
  b.MakeWire(w);
  b.Add(w, loop.edge.Oriented(loop.counterclockwise ? TopAbs_FORWARD : TopAbs_REVERSED));  // counterclockwise
  w.Closed(true);
  b.Add(f, w);
  f.Orientation(wall.Orientation());
  return f;
}

}  // namespace cg::features
