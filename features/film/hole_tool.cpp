#include "features/film/hole_tool.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepFill.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Geom_Circle.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>

#include <cmath>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg::features {
namespace {


// Points and arcs of the hole frame: P(s, x, y) = E + s d + x e_l + y e_f.
struct Local {
  HoleFrame f;
  Eigen::Vector3d l;
  explicit Local(const HoleFrame& frame) : f(frame), l(frame.lateral()) {}
  gp_Pnt at(double s, double x, double y) const { return occt::to_pnt(f.exit + s * f.axis + x * l + y * f.forward); }
  // Circle in the section plane at s, centre (x, y); parameter theta from e_l towards e_f.
  Handle(Geom_Circle) circle(double s, double x, double y, double radius) const {
    return new Geom_Circle(gp_Ax2(at(s, x, y), occt::to_dir(-f.axis), occt::to_dir(l)), radius);
  }
};

TopoDS_Edge arc(const Handle(Geom_Circle)& c, int quadrant) {
  return BRepBuilderAPI_MakeEdge(c, 0.5 * kPi * quadrant, 0.5 * kPi * (quadrant + 1)).Edge();
}

TopoDS_Shape sew(const std::vector<TopoDS_Face>& faces) {
  BRepBuilderAPI_Sewing sewing(1e-7);
  for (const TopoDS_Face& f : faces) sewing.Add(f);
  sewing.Perform();
  const TopoDS_Shape sewn = sewing.SewedShape();
  TopExp_Explorer shells(sewn, TopAbs_SHELL);
  if (!shells.More()) throw AlgorithmFailure("fan-shaped hole: the tool faces did not sew into a shell");
  const TopoDS_Shell shell = TopoDS::Shell(shells.Current());
  shells.Next();
  if (shells.More() || sewing.NbFreeEdges() > 0)
    throw AlgorithmFailure("fan-shaped hole: the tool faces did not sew into one closed shell");
  BRepBuilderAPI_MakeSolid mk(shell);
  TopoDS_Solid solid = mk.Solid();
  BRepLib::OrientClosedSolid(solid);
  return solid;
}

TopoDS_Shape fan_solid(const HoleFrame& frame, const HoleShape& shape, const HoleToolExtent& e) {
  const FanProfile prof(shape, e.diffuser_length);
  const Local L(frame);
  const double r = prof.radius(), sd = e.s_diffuser, st = e.s_top, se = e.s_end;
  const FanSection top = prof.at(sd - st);
  const double w = top.w, y0 = top.y0, y1 = top.y1, rho = top.rho;
  // Corner centres of the top section by quadrant (theta from e_l towards e_f).
  const double cx[4] = {w, -w, -w, w}, cy[4] = {y1, y1, y0, y0};
  std::vector<TopoDS_Face> faces;
  BRepBuilderAPI_MakeWire top_wire;
  const Handle(Geom_Circle) start = L.circle(sd, 0, 0, r), end = L.circle(se, 0, 0, r);
  const Handle(Geom_CylindricalSurface) cyl =
      new Geom_CylindricalSurface(gp_Ax3(L.at(se, 0, 0), occt::to_dir(-frame.axis), occt::to_dir(L.l)), r);
  // Junction points of the quadrants: metering circle at angle 90 q, top section's straight sides.
  const double jx[4] = {r, 0, -r, 0}, jy[4] = {0, r, 0, -r};
  for (int q = 0; q < 4; ++q) {
    const TopoDS_Edge bottom = arc(start, q);
    const TopoDS_Edge top_arc = arc(L.circle(st, cx[q], cy[q], rho), q);
    if (std::abs(rho - r) <= 1e-12 * r) {
      // Equal radii (edge radius = metering radius, the 7-7-7 construction): the corner is the metering
      // quarter arc swept along a straight line, an exact surface of linear extrusion, which OCCT
      // intersects faster and more robustly than a general ruled B-spline.
      const Eigen::Vector3d v = (st - sd) * frame.axis + cx[q] * L.l + cy[q] * frame.forward;
      const Handle(Geom_SurfaceOfLinearExtrusion) ext = new Geom_SurfaceOfLinearExtrusion(start, occt::to_dir(v));
      faces.push_back(BRepBuilderAPI_MakeFace(ext, 0.5 * kPi * q, 0.5 * kPi * (q + 1), 0, v.norm(), 1e-7).Face());
    } else {
      faces.push_back(BRepFill::Face(bottom, top_arc));
    }
    top_wire.Add(top_arc);
    // The straight side after quadrant q (from its end to the next corner's start) and its triangle.
    const int n = (q + 1) % 4;
    const double c = std::cos(0.5 * kPi * (q + 1)), s = std::sin(0.5 * kPi * (q + 1));
    const gp_Pnt a = L.at(st, cx[q] + rho * c, cy[q] + rho * s), b = L.at(st, cx[n] + rho * c, cy[n] + rho * s);
    if (a.Distance(b) > 1e-9) {
      top_wire.Add(BRepBuilderAPI_MakeEdge(a, b).Edge());
      const gp_Pnt j = L.at(sd, jx[n], jy[n]);
      faces.push_back(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakePolygon(j, a, b, true).Wire(), true).Face());
    }
  }
  if (!top_wire.IsDone()) throw AlgorithmFailure("fan-shaped hole: cannot close the end wires");
  // The metering cylinder as one face with its seam (four quarter faces sewn along their generators
  // made OCCT's face builder drop section edges: BOPAlgo_AlertFaceBuilderUnusedEdges); sewing splits its
  // circle at the diffuser's quadrant points.
  faces.push_back(BRepBuilderAPI_MakeFace(cyl, 0, 2 * kPi, 0, se - sd, 1e-7).Face());
  faces.push_back(BRepBuilderAPI_MakeFace(top_wire.Wire(), true).Face());
  faces.push_back(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(end).Edge()).Wire(), true).Face());
  return sew(faces);
}

}  // namespace

TopoDS_Shape make_hole_solid(const HoleFrame& frame, const HoleShape& shape, const HoleToolExtent& extent) {
  require(shape.diameter > 0, "hole tool: diameter must be > 0");
  HoleToolExtent e = extent;
  const bool oblique = e.end_normal.squaredNorm() > 0;
  const double r = 0.5 * shape.diameter;
  if (oblique) {
    const double c = e.end_normal.normalized().dot(frame.axis);
    require(c >= 0.2 - 1e-12, "hole tool: the end plane must make at most 78 deg with the axis' normal plane");
    e.s_end += r * std::sqrt(1 - c * c) / c + 0.05 * r;  // past the plane everywhere
  }
  TopoDS_Shape tool;
  if (shape.kind == HoleKind::Cylindrical) {
    require(e.s_end > e.s_top, "hole tool: s_end must be > s_top");
    const gp_Ax2 ax(occt::to_pnt(frame.exit + e.s_top * frame.axis), occt::to_dir(frame.axis), occt::to_dir(frame.lateral()));
    tool = BRepPrimAPI_MakeCylinder(ax, r, e.s_end - e.s_top).Shape();
  } else {
    require(e.s_top < e.s_diffuser && e.s_diffuser < e.s_end, "hole tool: need s_top < s_diffuser < s_end");
    tool = fan_solid(frame, shape, e);
  }
  if (!oblique) return tool;
  // Keep the side of the end plane towards the exit: a box with one face on the plane.
  const Eigen::Vector3d n = extent.end_normal.normalized(), p = frame.exit + extent.s_end * frame.axis;
  // The box's own axes: Z = -n (into the kept side), X = x, Y = Z x X (gp_Ax2), so the corner lies half
  // a box back along X and Y for the box to be centred on the axis.
  const Eigen::Vector3d x = n.unitOrthogonal(), y = (-n).cross(x);
  const double big = 4 * (e.s_end - e.s_top) + 20 * shape.diameter;
  const gp_Ax2 ax(occt::to_pnt(p - 0.5 * big * (x + y)), occt::to_dir(-n), occt::to_dir(x));
  BRepAlgoAPI_Common common(tool, BRepPrimAPI_MakeBox(ax, big, big, big).Shape());
  if (!common.IsDone() || common.HasErrors()) throw AlgorithmFailure("hole tool: cannot cut the tool's oblique end");
  TopExp_Explorer solids(common.Shape(), TopAbs_SOLID);
  if (!solids.More()) throw AlgorithmFailure("hole tool: the oblique end left no solid");
  const TopoDS_Shape solid = solids.Current();
  solids.Next();
  if (solids.More()) throw AlgorithmFailure("hole tool: the oblique end left several solids");
  return solid;
}

double hole_solid_volume(const HoleShape& shape, const HoleToolExtent& e) {
  const double r = 0.5 * shape.diameter;
  if (shape.kind == HoleKind::Cylindrical) return kPi * r * r * (e.s_end - e.s_top);
  const std::array<double, 3> a = FanProfile(shape, e.diffuser_length).area_polynomial();
  const double t = e.s_diffuser - e.s_top;
  return kPi * r * r * (e.s_end - e.s_diffuser) + a[0] * t + a[1] * t * t / 2 + a[2] * t * t * t / 3;
}

brep::NamedShape named_all_faces(const TopoDS_Shape& solid, const std::string& name) {
  brep::NamedShape n{solid, {}};
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) n.faces.push_back({TopoDS::Face(e.Current()), name});
  return n;
}

}  // namespace cg::features
