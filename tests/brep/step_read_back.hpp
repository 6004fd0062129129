#pragma once
// A STEP file read back through XCAF with names: its free shapes and the names on their sub-shape
// labels (the face names write_step stores). For tests that check a round trip.
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace cg::test {

struct StepReadBack {
  bool ok = false;                         ///< read and transferred
  std::vector<TopoDS_Shape> free_shapes;   ///< top-level shapes
  std::multiset<std::string> names;        ///< names of the free shapes' sub-shape labels
  std::multiset<std::string> face_names;   ///< the names on face labels
  std::map<std::string, TopoDS_Shape> named_solids;  ///< solid labels by name (bodies)
  std::multimap<std::string, TopoDS_Shape> named_faces;  ///< face labels by name
};

inline StepReadBack read_step_back(const std::filesystem::path& file) {
  StepReadBack r;
  STEPCAFControl_Controller::Init();
  Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
  Handle(TDocStd_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  if (reader.ReadFile(file.string().c_str()) == IFSelect_RetDone && reader.Transfer(doc)) {
    r.ok = true;
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence free_shapes;
    tool->GetFreeShapes(free_shapes);
    for (const TDF_Label& l : free_shapes) {
      r.free_shapes.push_back(tool->GetShape(l));
      TDF_LabelSequence subs;
      XCAFDoc_ShapeTool::GetSubShapes(l, subs);
      for (const TDF_Label& s : subs) {
        Handle(TDataStd_Name) n;
        if (!s.FindAttribute(TDataStd_Name::GetID(), n)) continue;
        const std::string name = TCollection_AsciiString(n->Get()).ToCString();
        r.names.insert(name);
        const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(s);
        if (shape.ShapeType() == TopAbs_FACE) {
          r.face_names.insert(name);
          r.named_faces.emplace(name, shape);
        }
        if (shape.ShapeType() == TopAbs_SOLID) r.named_solids[name] = shape;
      }
    }
  }
  app->Close(doc);
  return r;
}

}  // namespace cg::test
