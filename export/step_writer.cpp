#include "export/step_writer.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Version.hxx>

#include <algorithm>
#include <cctype>

#include "export/atomic_file.hpp"
#include "export/part_document.hpp"
#include "export/version.hpp"

namespace cg::io {
namespace {

// Sets an OCCT static parameter; a missing parameter means the controller was not initialised.
void set_param(const char* name, const char* value) {
  if (!Interface_Static::SetCVal(name, value)) throw ExportError(std::string("cannot set the STEP parameter ") + name);
}
void set_param(const char* name, int value) {
  if (!Interface_Static::SetIVal(name, value)) throw ExportError(std::string("cannot set the STEP parameter ") + name);
}

Handle(TCollection_HAsciiString) ascii(const std::string& s) { return new TCollection_HAsciiString(s.c_str()); }

}  // namespace

StepSchema parse_step_schema(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (n == "AP214") return StepSchema::AP214;
  if (n == "AP242") return StepSchema::AP242;
  throw InvalidGeometry("STEP schema must be \"AP214\" or \"AP242\", got \"" + name + "\"");
}

const char* step_schema_name(StepSchema s) { return s == StepSchema::AP242 ? "AP242" : "AP214"; }

void write_step(const std::filesystem::path& file, const brep::Part& part, const StepOptions& options) {
  // The XCAF controller must be initialised before its parameters exist: set earlier,
  // write.stepcaf.subshapes.name fails silently and the faces lose their names.
  STEPCAFControl_Controller::Init();
  set_param("write.step.schema", options.schema == StepSchema::AP242 ? "AP242DIS" : "AP214IS");
  set_param("write.step.unit", "MM");
  set_param("write.stepcaf.subshapes.name", 1);

  const PartDocument doc(part, options.product_name);
  STEPCAFControl_Writer writer;
  writer.SetNameMode(true);
  writer.SetColorMode(true);
  writer.SetLayerMode(true);
  if (!writer.Transfer(doc.document(), STEPControl_AsIs)) throw ExportError("STEP transfer of the part failed");

  // Header: the defaults name OCCT as the originating system and leave the file name empty.
  APIHeaderSection_MakeHeader header(writer.ChangeWriter().Model());
  const std::string tool = std::string(kToolName) + " " + tool_version();
  header.SetName(ascii(options.product_name));
  header.SetOriginatingSystem(ascii(tool));
  header.SetPreprocessorVersion(ascii(tool + " (Open CASCADE " OCC_VERSION_STRING_EXT ")"));
  header.SetAuthorValue(1, ascii(kToolName));
  header.SetOrganizationValue(1, ascii(""));
  header.SetAuthorisation(ascii(""));
  header.SetDescriptionValue(1, ascii(options.product_name + ": cooled turbine blade, unit mm, faces named by feature"));

  write_atomically(file, [&](const std::filesystem::path& tmp) {
    if (writer.Write(tmp.string().c_str()) != IFSelect_RetDone) throw ExportError("cannot write STEP file " + tmp.string());
  });
}

void write_step(const std::filesystem::path& file, const TopoDS_Shape& shape, const std::vector<brep::NamedFace>& faces,
                const StepOptions& options) {
  if (shape.IsNull()) throw ExportError("cannot write a null shape to " + file.string());
  write_step(file, brep::Part{{"blade", brep::NamedShape{shape, faces}}}, options);
}

}  // namespace cg::io
