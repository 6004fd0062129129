#include "src/brep/naming/face_names.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::features {

void FaceNames::add(const std::vector<brep::NamedFace>& faces) {
  for (const auto& f : faces) set(f.face, f.name);
}

void FaceNames::set(const TopoDS_Shape& face, const std::string& name) {
  if (map_.IsBound(face))
    map_.ChangeFind(face) = name;
  else
    map_.Bind(face, name);
}

void FaceNames::merge(const FaceNames& other) {
  for (NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher>::Iterator it(other.map_); it.More(); it.Next())
    set(it.Key(), it.Value());
}

std::string FaceNames::get(const TopoDS_Shape& face) const {
  const std::string* s = map_.Seek(face);
  return s ? *s : std::string();
}

FaceNames FaceNames::carried(BRepBuilderAPI_MakeShape& op, const TopoDS_Shape& result) const {
  TopTools_IndexedMapOfShape in_result;
  TopExp::MapShapes(result, TopAbs_FACE, in_result);
  FaceNames out;
  for (NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher>::Iterator it(map_); it.More(); it.Next()) {
    const TopoDS_Shape& f = it.Key();
    const TopTools_ListOfShape& mod = op.Modified(f);
    if (mod.IsEmpty()) {
      if (!op.IsDeleted(f) && in_result.Contains(f)) out.set(f, it.Value());
      continue;
    }
    for (const TopoDS_Shape& p : mod)
      if (p.ShapeType() == TopAbs_FACE && in_result.Contains(p)) out.set(p, it.Value());
  }
  return out;
}

std::vector<brep::NamedFace> FaceNames::list(const TopoDS_Shape& shape, const std::string& what) const {
  std::vector<brep::NamedFace> out;
  for (const TopoDS_Shape& f : faces_of(shape)) {
    const std::string n = get(f);
    if (n.empty()) {
      BRepAdaptor_Surface ad(TopoDS::Face(f));
      GProp_GProps p;
      BRepGProp::SurfaceProperties(f, p);
      throw AlgorithmFailure(what + ": a face has no name (lost in the boolean history): surface type " +
                             std::to_string(static_cast<int>(ad.GetType())) + ", area " + format_number(p.Mass()) +
                             " mm^2 at (" + format_number(p.CentreOfMass().X()) + ", " +
                             format_number(p.CentreOfMass().Y()) + ", " + format_number(p.CentreOfMass().Z()) + ")");
    }
    out.push_back({TopoDS::Face(f), n});
  }
  return out;
}

std::vector<TopoDS_Shape> faces_of(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(shape, TopAbs_FACE, m);
  std::vector<TopoDS_Shape> out;
  for (int i = 1; i <= m.Extent(); ++i) out.push_back(m(i));
  return out;
}

std::vector<TopoDS_Shape> solids_of(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(shape, TopAbs_SOLID, m);
  std::vector<TopoDS_Shape> out;
  for (int i = 1; i <= m.Extent(); ++i) out.push_back(m(i));
  return out;
}

TopoDS_Shape merge_cells(const std::vector<TopoDS_Shape>& cells) {
  if (cells.size() == 1) return cells.front();
  // Count each face over the cells (IsSame); keep the faces of one cell only.
  NCollection_DataMap<TopoDS_Shape, int, TopTools_ShapeMapHasher> count;
  for (const TopoDS_Shape& c : cells)
    for (TopExp_Explorer e(c, TopAbs_FACE); e.More(); e.Next()) {
      if (count.IsBound(e.Current()))
        ++count.ChangeFind(e.Current());
      else
        count.Bind(e.Current(), 1);
    }
  BRep_Builder bb;
  TopoDS_Shell shell;
  bb.MakeShell(shell);
  for (const TopoDS_Shape& c : cells)
    for (TopExp_Explorer e(c, TopAbs_FACE); e.More(); e.Next())
      if (count.Find(e.Current()) == 1) bb.Add(shell, e.Current());
  shell.Closed(true);
  ShapeAnalysis_FreeBounds fb(shell);
  int free_edges = 0;
  for (const TopoDS_Shape* w : {&fb.GetClosedWires(), &fb.GetOpenWires()})
    for (TopExp_Explorer e(*w, TopAbs_EDGE); e.More(); e.Next()) ++free_edges;
  if (free_edges > 0)
    throw AlgorithmFailure("merging cells: the outer faces leave " + std::to_string(free_edges) + " free edges");
  TopoDS_Solid solid;
  bb.MakeSolid(solid);
  bb.Add(solid, shell);
  BRepLib::OrientClosedSolid(solid);
  return solid;
}

}  // namespace cg::features
