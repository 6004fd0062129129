#include "export/iges_writer.hpp"

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <TopoDS.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Standard_Version.hxx>
#include <XSControl_WorkSession.hxx>

#include "export/atomic_file.hpp"
#include "export/part_document.hpp"
#include "export/version.hpp"

namespace cg::io {
namespace {

void set_param(const char* name, const char* value) {
  if (!Interface_Static::SetCVal(name, value)) throw ExportError(std::string("cannot set the IGES parameter ") + name);
}
void set_param(const char* name, int value) {
  if (!Interface_Static::SetIVal(name, value)) throw ExportError(std::string("cannot set the IGES parameter ") + name);
}

// OCCT writes analytic surfaces as IGES analytic entities (planes 108, cylinders as surfaces of
// revolution 120): convert every surface and curve to its exact rational B-spline form first, so the
// file holds only 144/142/128/126. The face names follow the conversion history.
brep::Part nurbs_part(const brep::Part& part) {
  brep::Part out;
  for (const brep::NamedBody& body : part) {
    BRepBuilderAPI_NurbsConvert convert(body.geometry.shape, /*Copy=*/true);
    if (!convert.IsDone()) throw ExportError("IGES: conversion of body \"" + body.name + "\" to B-splines failed");
    brep::NamedBody b{body.name, {convert.Shape(), {}}};
    for (const brep::NamedFace& f : body.geometry.faces)
      b.geometry.faces.push_back({TopoDS::Face(convert.ModifiedShape(f.face)), f.name});
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace

void write_iges(const std::filesystem::path& file, const brep::Part& part, const IgesOptions& options) {
  IGESControl_Controller::Init();
  set_param("write.iges.brep.mode", 0);  // faces: 144 over 128 with 126 trims, not an MSBO B-rep (186)
  set_param("write.iges.unit", "MM");
  set_param("write.iges.header.product", options.product_name.c_str());
  set_param("write.iges.header.author", kToolName);
  set_param("write.iges.header.company", "");
  const PartDocument doc(nurbs_part(part), options.product_name);
  IGESCAFControl_Writer writer(new XSControl_WorkSession, /*scratch=*/true);
  writer.SetNameMode(true);
  writer.SetColorMode(true);
  writer.SetLayerMode(true);
  if (!writer.Transfer(doc.document())) throw ExportError("IGES transfer of the part failed");

  // The global section names OCCT as the sending system by default.
  const Handle(IGESData_IGESModel) model = writer.Model();
  IGESData_GlobalSection gs = model->GlobalSection();
  const std::string tool = std::string(kToolName) + " " + tool_version();
  gs.SetSendName(new TCollection_HAsciiString(options.product_name.c_str()));
  gs.SetFileName(new TCollection_HAsciiString(file.filename().string().c_str()));
  gs.SetSystemId(new TCollection_HAsciiString(tool.c_str()));
  gs.SetInterfaceVersion(new TCollection_HAsciiString("Open CASCADE " OCC_VERSION_STRING_EXT));
  gs.SetReceiveName(new TCollection_HAsciiString(options.product_name.c_str()));
  model->SetGlobalSection(gs);

  write_atomically(file, [&](const std::filesystem::path& tmp) {
    if (!writer.Write(tmp.string().c_str())) throw ExportError("cannot write IGES file " + tmp.string());
  });
}

}  // namespace cg::io
