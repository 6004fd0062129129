#include "export/step_writer.hpp"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <cctype>

#include "export/atomic_file.hpp"

namespace cg::io {
namespace {

// Sets an OCCT static parameter; a missing parameter means the controller was not initialised.
void set_param(const char* name, const char* value) {
  if (!Interface_Static::SetCVal(name, value)) throw ExportError(std::string("cannot set the STEP parameter ") + name);
}
void set_param(const char* name, int value) {
  if (!Interface_Static::SetIVal(name, value)) throw ExportError(std::string("cannot set the STEP parameter ") + name);
}

// Closes the document when leaving scope (the application keeps a list of open documents).
struct DocumentGuard {
  Handle(TDocStd_Application) app;
  Handle(TDocStd_Document) doc;
  ~DocumentGuard() {
    if (!doc.IsNull() && doc->IsOpened()) app->Close(doc);
  }
};

}  // namespace

StepSchema parse_step_schema(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (n == "AP214") return StepSchema::AP214;
  if (n == "AP242") return StepSchema::AP242;
  throw InvalidGeometry("STEP schema must be \"AP214\" or \"AP242\", got \"" + name + "\"");
}

const char* step_schema_name(StepSchema s) { return s == StepSchema::AP242 ? "AP242" : "AP214"; }

void write_step(const std::filesystem::path& file, const TopoDS_Shape& shape, const std::vector<brep::NamedFace>& faces,
                const StepOptions& options) {
  if (shape.IsNull()) throw ExportError("cannot write a null shape to " + file.string());
  // The XCAF controller must be initialised before its parameters exist: set earlier,
  // write.stepcaf.subshapes.name fails silently and the faces lose their names.
  STEPCAFControl_Controller::Init();
  set_param("write.step.schema", options.schema == StepSchema::AP242 ? "AP242DIS" : "AP214IS");
  set_param("write.step.unit", "MM");
  set_param("write.stepcaf.subshapes.name", 1);

  DocumentGuard g{XCAFApp_Application::GetApplication(), {}};
  g.app->NewDocument("MDTV-XCAF", g.doc);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(g.doc->Main());
  const TDF_Label label = tool->AddShape(shape, /*makeAssembly=*/false);
  TDataStd_Name::Set(label, TCollection_ExtendedString(options.product_name.c_str(), /*isMultiByte=*/true));
  for (const auto& f : faces) {
    const TDF_Label sub = tool->AddSubShape(label, f.face);
    if (sub.IsNull()) throw ExportError("face \"" + f.name + "\" is not a face of the shape written to " + file.string());
    TDataStd_Name::Set(sub, TCollection_ExtendedString(f.name.c_str(), true));
  }

  STEPCAFControl_Writer writer;
  writer.SetNameMode(true);
  if (!writer.Transfer(g.doc, STEPControl_AsIs)) throw ExportError("STEP transfer of the shape failed");
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    if (writer.Write(tmp.string().c_str()) != IFSelect_RetDone) throw ExportError("cannot write STEP file " + tmp.string());
  });
}

}  // namespace cg::io
