#pragma once
// Readers that are not ours, for the acceptance tests: each reads a file that `coolinggen build`
// wrote and measures what the next tool in a CFD chain would see.
//  - IGES: OCCT's IGES reader (XCAF, with names and layers), every face checked by BRepCheck_Analyzer,
//    then BRepBuilderAPI_Sewing at 1e-3 mm (what a mesher that starts from trimmed surfaces does): the
//    shells, their free edges and the volume of the sewn solids.
//  - STL: OCCT's STL reader (RWStl) for the triangles, admesh (Debian) for its own verdict.
//  - VTK: VTK's XML reader.
// The checks of orientation and closure are done here on plain arrays, independent of our writers.
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRep_Builder.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Poly_Triangulation.hxx>
#include <RWStl.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <Eigen/Geometry>
#include <array>
#include <functional>
#include <sstream>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "src/brep/solid_integrals.hpp"

namespace cg::test {

inline int count_shapes(const TopoDS_Shape& s, TopAbs_ShapeEnum t) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(s, t, m);
  return m.Extent();
}

/// Edges of `s` used by exactly one face (a closed shell has none).
inline int free_edges(const TopoDS_Shape& s) {
  TopTools_IndexedDataMapOfShapeListOfShape m;
  TopExp::MapShapesAndAncestors(s, TopAbs_EDGE, TopAbs_FACE, m);
  int n = 0;
  for (int i = 1; i <= m.Extent(); ++i)
    if (!BRep_Tool::Degenerated(TopoDS::Edge(m.FindKey(i))) && m(i).Extent() == 1) ++n;
  return n;
}

/// Enclosed volume by our face flux (src/brep/face_flux, verified against a knot-aligned reference):
/// BRepGProp_Vinert's fixed rules scatter by a few 1e-6 between representations of the same faces.
inline double volume(const TopoDS_Shape& s) { return brep::shape_volume(s, 1e-10); }

struct IgesReadBack {
  bool read = false;
  int faces = 0, invalid_faces = 0;
  std::map<std::string, int> invalid_by_status;  ///< BRepCheck status of the invalid faces' first fault
  int shells = 0, closed_shells = 0, free_edges = 0;
  std::vector<double> solid_volumes;             ///< of each sewn closed shell made a solid, mm^3
  std::multiset<std::string> face_names;         ///< names (IGES 406) on face labels
  std::vector<std::pair<std::string, std::string>> face_name_layer;  ///< per named face: (name, IGES level)
};

/// OCCT's IGES reader, then sewing at `sewing_tolerance` mm.
inline IgesReadBack read_iges_back(const std::filesystem::path& file, double sewing_tolerance = 1e-3) {
  IgesReadBack r;
  IGESControl_Controller::Init();
  Handle(TDocStd_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  IGESCAFControl_Reader reader;
  reader.SetNameMode(true);
  reader.SetLayerMode(true);
  if (reader.ReadFile(file.string().c_str()) != IFSelect_RetDone || !reader.Transfer(doc)) {
    app->Close(doc);
    return r;
  }
  r.read = true;
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(doc->Main());
  TDF_LabelSequence labels;
  shapes->GetShapes(labels);
  BRep_Builder bb;
  TopoDS_Compound all;
  bb.MakeCompound(all);
  std::function<void(const TDF_Label&)> visit = [&](const TDF_Label& l) {
    const TopoDS_Shape s = XCAFDoc_ShapeTool::GetShape(l);
    if (!s.IsNull() && s.ShapeType() == TopAbs_FACE) {
      Handle(TDataStd_Name) n;
      if (l.FindAttribute(TDataStd_Name::GetID(), n)) {
        const std::string name = TCollection_AsciiString(n->Get()).ToCString();
        r.face_names.insert(name);
        Handle(TColStd_HSequenceOfExtendedString) names;
        std::string level;
        if (layers->GetLayers(l, names) && names->Length() == 1) level = TCollection_AsciiString(names->Value(1)).ToCString();
        r.face_name_layer.emplace_back(name, level);
      }
    }
    TDF_LabelSequence subs;
    XCAFDoc_ShapeTool::GetComponents(l, subs);
    XCAFDoc_ShapeTool::GetSubShapes(l, subs);
    for (const TDF_Label& c : subs) visit(c);
  };
  TDF_LabelSequence free_labels;
  shapes->GetFreeShapes(free_labels);
  for (const TDF_Label& l : free_labels) {
    bb.Add(all, XCAFDoc_ShapeTool::GetShape(l));
    visit(l);
  }
  for (TopExp_Explorer e(all, TopAbs_FACE); e.More(); e.Next()) {
    ++r.faces;
    BRepCheck_Analyzer a(e.Current());
    if (a.IsValid()) continue;
    ++r.invalid_faces;
    std::ostringstream st;
    const Handle(BRepCheck_Result)& res = a.Result(e.Current());
    if (!res.IsNull() && !res->Status().IsEmpty()) BRepCheck::Print(res->Status().First(), st);
    else st << "sub-shape";
    std::string key = st.str();
    while (!key.empty() && (key.back() == '\n' || key.back() == ' ')) key.pop_back();
    ++r.invalid_by_status[key];
  }
  BRepBuilderAPI_Sewing sew(sewing_tolerance);
  for (TopExp_Explorer e(all, TopAbs_FACE); e.More(); e.Next()) sew.Add(e.Current());
  sew.Perform();
  const TopoDS_Shape sewn = sew.SewedShape();
  r.free_edges = free_edges(sewn);
  for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) {
    ++r.shells;
    const TopoDS_Shell sh = TopoDS::Shell(e.Current());
    if (free_edges(sh) != 0) continue;
    ++r.closed_shells;
    BRepBuilderAPI_MakeSolid ms(sh);
    r.solid_volumes.push_back(std::abs(volume(ms.Solid())));
  }
  std::sort(r.solid_volumes.begin(), r.solid_volumes.end());
  app->Close(doc);
  return r;
}

/// An MSBO (186) IGES file through OCCT's plain reader, no sewing: the solids and their validity.
struct IgesSolids {
  int solids = 0, invalid = 0, free_edges = 0;
  std::vector<double> volumes;
};

inline IgesSolids read_iges_solids(const std::filesystem::path& file) {
  IgesSolids r;
  IGESControl_Controller::Init();
  IGESControl_Reader reader;
  if (reader.ReadFile(file.string().c_str()) != IFSelect_RetDone) return r;
  reader.TransferRoots();
  const TopoDS_Shape s = reader.OneShape();
  for (TopExp_Explorer e(s, TopAbs_SOLID); e.More(); e.Next()) {
    ++r.solids;
    r.invalid += !BRepCheck_Analyzer(e.Current()).IsValid();
    r.free_edges += free_edges(e.Current());
    r.volumes.push_back(std::abs(volume(e.Current())));
  }
  std::sort(r.volumes.begin(), r.volumes.end());
  return r;
}

/// A triangle soup's closure and orientation, measured on its node positions: vertices closer than
/// `merge` mm are one node (STL stores no connectivity); every directed edge must be used exactly once
/// and its opposite exactly once (closed, consistently oriented), and the signed volume
/// 1/6 sum a.(b x c) is positive when the triangles face outward.
struct SoupCheck {
  std::size_t triangles = 0;
  std::size_t directed_edges = 0, unmatched = 0, repeated = 0;
  double signed_volume = 0;  ///< mm^3
};

inline SoupCheck check_soup(const std::vector<std::array<Eigen::Vector3d, 3>>& tris, double merge = 1e-6) {
  SoupCheck c;
  c.triangles = tris.size();
  std::map<std::array<long long, 3>, std::size_t> ids;
  auto id = [&](const Eigen::Vector3d& p) {
    const std::array<long long, 3> k{std::llround(p.x() / merge), std::llround(p.y() / merge), std::llround(p.z() / merge)};
    return ids.emplace(k, ids.size()).first->second;
  };
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for (const auto& t : tris) {
    c.signed_volume += t[0].dot(t[1].cross(t[2])) / 6.0;
    const std::size_t n[3] = {id(t[0]), id(t[1]), id(t[2])};
    for (int k = 0; k < 3; ++k)
      if (n[k] != n[(k + 1) % 3]) ++directed[{n[k], n[(k + 1) % 3]}];
  }
  c.directed_edges = directed.size();
  for (const auto& [e, count] : directed) {
    if (count != 1) ++c.repeated;
    const auto o = directed.find({e.second, e.first});
    if (o == directed.end() || o->second != 1) ++c.unmatched;
  }
  return c;
}

/// The triangles of an STL file as OCCT's reader (RWStl) returns them.
inline std::vector<std::array<Eigen::Vector3d, 3>> read_stl_triangles(const std::filesystem::path& file) {
  std::vector<std::array<Eigen::Vector3d, 3>> out;
  const Handle(Poly_Triangulation) t = RWStl::ReadFile(file.string().c_str());
  if (t.IsNull()) return out;
  for (int i = 1; i <= t->NbTriangles(); ++i) {
    int a, b, c;
    t->Triangle(i).Get(a, b, c);
    auto p = [&](int k) { const gp_Pnt q = t->Node(k); return Eigen::Vector3d(q.X(), q.Y(), q.Z()); };
    out.push_back({p(a), p(b), p(c)});
  }
  return out;
}

/// What admesh (the Debian package) says of an STL file, read from its report.
struct AdmeshReport {
  bool ran = false;
  long facets = -1, reversed = -1, backwards_edges = -1, parts = -1;
  double volume = 0;
  std::string text;
};

inline AdmeshReport run_admesh(const std::filesystem::path& file) {
  AdmeshReport r;
  const std::string cmd = "admesh '" + file.string() + "' 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) r.text += buf;
  r.ran = ::pclose(p) == 0;
  auto number = [&](const char* label) -> double {
    const std::regex re(std::string(label) + R"(\s*:\s*([-+0-9.eE]+))");
    std::smatch m;
    return std::regex_search(r.text, m, re) ? std::stod(m[1]) : -1.0;
  };
  r.facets = static_cast<long>(number("Number of facets"));
  r.reversed = static_cast<long>(number("Facets reversed"));
  r.backwards_edges = static_cast<long>(number("Backwards edges"));
  r.parts = static_cast<long>(number("Number of parts"));
  r.volume = number("Volume");
  return r;
}

}  // namespace cg::test
