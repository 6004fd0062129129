#include "export/stl_writer.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <StlAPI_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "export/atomic_file.hpp"
#include "export/part_document.hpp"

namespace cg::io {

std::size_t write_stl(const std::filesystem::path& file, const brep::Part& part, const StlOptions& options) {
  if (part.empty()) throw ExportError("cannot export an empty part (no bodies)");
  if (!(options.linear_deflection > 0) || !(options.angular_deflection > 0))
    throw ExportError("STL deflections must be > 0");
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(part_compound(part), /*copyGeom=*/false, /*copyMesh=*/false).Shape();
  BRepMesh_IncrementalMesh mesh(copy, options.linear_deflection, /*isRelative=*/false, options.angular_deflection,
                                /*isInParallel=*/true);
  std::size_t triangles = 0;
  for (TopExp_Explorer e(copy, TopAbs_FACE); e.More(); e.Next()) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(TopoDS::Face(e.Current()), loc);
    if (t.IsNull()) throw ExportError("STL: a face could not be triangulated");
    triangles += static_cast<std::size_t>(t->NbTriangles());
  }
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    StlAPI_Writer w;
    w.ASCIIMode() = false;
    if (!w.Write(copy, tmp.string().c_str())) throw ExportError("cannot write STL file " + tmp.string());
  });
  return triangles;
}

}  // namespace cg::io
