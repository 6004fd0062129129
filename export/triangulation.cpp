#include "export/triangulation.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <Bnd_Box.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <NCollection_DataMap.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

#include "export/atomic_file.hpp"

namespace cg::io {

PartTriangles triangulate_part(const brep::Part& part, const TriangulationOptions& options) {
  if (!(options.linear_deflection > 0) || !(options.angular_deflection > 0))
    throw ExportError("triangulation deflections must be > 0");
  PartTriangles out;
  out.table = feature_table(part);
  // Floor of the linear deflection relative to the part's size: an absolute 0.01 mm on a 100 m vane
  // would ask BRepMesh for billions of triangles (a file nobody can use); 2e-5 of the diagonal keeps
  // the configured value for blades up to 500 mm.
  Bnd_Box box;
  for (const brep::NamedBody& b : part) BRepBndLib::Add(b.geometry.shape, box);
  const double deflection = std::max(options.linear_deflection, box.IsVoid() ? 0.0 : 2e-5 * std::sqrt(box.SquareExtent()));
  for (std::size_t b = 0; b < part.size(); ++b) {
    const brep::NamedShape& g = part[b].geometry;
    // Mesh a copy: the part is shared with other exporters and must not keep this mesh.
    BRepBuilderAPI_Copy copier(g.shape, /*copyGeom=*/false, /*copyMesh=*/false);
    BRepMesh_IncrementalMesh(copier.Shape(), deflection, false, options.angular_deflection, true);
    // Each face as it sits in the solid's shells: after the feature booleans the orientation of a face in
    // the part's name list need not be the one it has in the shell (a tool face enters the result
    // reversed), and only the shell's orientation points outward. Names are matched by IsSame.
    NCollection_DataMap<TopoDS_Shape, TopoDS_Face, TopTools_ShapeMapHasher> in_shell;
    for (TopExp_Explorer e(copier.Shape(), TopAbs_FACE); e.More(); e.Next())
      if (!in_shell.IsBound(e.Current())) in_shell.Bind(e.Current(), TopoDS::Face(e.Current()));
    if (in_shell.Extent() != static_cast<int>(g.faces.size()))
      throw ExportError("body \"" + part[b].name + "\" has " + std::to_string(in_shell.Extent()) + " faces but " +
                        std::to_string(g.faces.size()) + " face names");
    for (std::size_t fi = 0; fi < g.faces.size(); ++fi) {
      const TopoDS_Shape copied = copier.ModifiedShape(g.faces[fi].face);
      if (!in_shell.IsBound(copied))
        throw ExportError("face \"" + g.faces[fi].name + "\" of body \"" + part[b].name + "\" is not in the body's shells");
      const TopoDS_Face face = in_shell.Find(copied);
      TopLoc_Location loc;
      Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, loc);
      if (t.IsNull())
        throw ExportError("face \"" + g.faces[fi].name + "\" of body \"" + part[b].name + "\" could not be triangulated");
      if (!t->HasNormals()) t->ComputeNormals();  // from the triangles, in the surface's orientation
      const gp_Trsf trsf = loc.Transformation();
      const bool reversed = face.Orientation() == TopAbs_REVERSED;
      const int base = static_cast<int>(out.points.size());
      for (int i = 1; i <= t->NbNodes(); ++i) {
        const gp_Pnt p = t->Node(i).Transformed(trsf);
        gp_Dir n = t->Normal(i);
        n.Transform(trsf);
        if (reversed) n.Reverse();
        out.points.emplace_back(p.X(), p.Y(), p.Z());
        out.normals.emplace_back(n.X(), n.Y(), n.Z());
      }
      const int kind = out.table.kind_id(g.faces[fi].name), name = out.table.name_id(g.faces[fi].name);
      for (int i = 1; i <= t->NbTriangles(); ++i) {
        int n1, n2, n3;
        t->Triangle(i).Get(n1, n2, n3);
        if (reversed) std::swap(n2, n3);
        out.triangles.push_back({base + n1 - 1, base + n2 - 1, base + n3 - 1});
        out.body.push_back(static_cast<int>(b));
        out.face.push_back(static_cast<int>(fi));
        out.kind_id.push_back(kind);
        out.name_id.push_back(name);
      }
    }
  }
  return out;
}

}  // namespace cg::io
