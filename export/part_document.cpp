#include "export/part_document.hpp"

#include <BRep_Builder.hxx>
#include <Quantity_Color.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "export/atomic_file.hpp"
#include "export/feature_style.hpp"

namespace cg::io {
namespace {

void set_name(const TDF_Label& label, const std::string& name) {
  TDataStd_Name::Set(label, TCollection_ExtendedString(name.c_str(), /*isMultiByte=*/true));
}

Quantity_Color quantity(const Colour& c) {
  // Quantity_TOC_RGB is linear RGB in OCCT 7.6; our colours are ordinary (sRGB) values.
  return Quantity_Color(c[0], c[1], c[2], Quantity_TOC_sRGB);
}

}  // namespace

TopoDS_Compound part_compound(const brep::Part& part) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  for (const brep::NamedBody& body : part) b.Add(c, body.geometry.shape);
  return c;
}

PartDocument::PartDocument(const brep::Part& part, const std::string& product_name) {
  if (part.empty()) throw ExportError("cannot export an empty part (no bodies)");
  for (const brep::NamedBody& body : part) {
    if (body.geometry.shape.IsNull()) throw ExportError("body \"" + body.name + "\" has no shape");
    int solids = 0;
    for (TopExp_Explorer e(body.geometry.shape, TopAbs_SOLID); e.More(); e.Next()) ++solids;
    if (solids != 1)
      throw ExportError("body \"" + body.name + "\" must be one solid, has " + std::to_string(solids));
  }
  compound_ = part_compound(part);
  app_ = XCAFApp_Application::GetApplication();
  app_->NewDocument("MDTV-XCAF", doc_);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc_->Main());
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc_->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(doc_->Main());
  const TDF_Label root = shapes->AddShape(compound_, /*makeAssembly=*/false);
  set_name(root, product_name);
  for (const brep::NamedBody& body : part) {
    TopExp_Explorer solid(body.geometry.shape, TopAbs_SOLID);
    const TDF_Label body_label = shapes->AddSubShape(root, solid.Current());
    if (body_label.IsNull()) throw ExportError("body \"" + body.name + "\" could not be added to the XCAF document");
    set_name(body_label, body.name);
    for (const brep::NamedFace& f : body.geometry.faces) {
      const TDF_Label face_label = shapes->AddSubShape(root, f.face);
      if (face_label.IsNull())
        throw ExportError("face \"" + f.name + "\" is not a face of body \"" + body.name + "\"");
      set_name(face_label, f.name);
      const std::string kind = brep::feature_kind(f.name);
      colours->SetColor(face_label, quantity(kind_colour(kind)), XCAFDoc_ColorSurf);
      layers->SetLayer(face_label, TCollection_ExtendedString(kind.c_str(), true));
    }
  }
}

PartDocument::~PartDocument() {
  if (!doc_.IsNull() && doc_->IsOpened()) app_->Close(doc_);
}

}  // namespace cg::io
