#include "export/iges_writer.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools_NurbsConvertModification.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
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
// BRepTools_NurbsConvertModification recomputes every pcurve on a face it converts -- B-spline faces
// included, whose surface it only copies -- by projecting the edge's 3D curve onto the surface
// (ProjLib_ComputeApproxOnPolarSurface) and then measures the new tolerance; on the cooled blade, with
// its film-hole loops of up to 512 spans, that was ~70 % of the IGES time. On a B-spline face whose
// edge keeps its parametrisation (3D curve absent, a B-spline, Bezier or line: converted without
// reparametrisation) the existing pcurve is still exact: it is kept, in B-spline form. Everything
// else (analytic surfaces, conic edges whose parameter changes) goes through OCCT's conversion.
class KeepBSplineFaces : public BRepTools_NurbsConvertModification {
 public:
  Standard_Boolean NewCurve2d(const TopoDS_Edge& e, const TopoDS_Face& f, const TopoDS_Edge& new_e, const TopoDS_Face& new_f,
                              Handle(Geom2d_Curve)& c, Standard_Real& tol) override {
    TopLoc_Location sl, cl;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f, sl);
    double f3 = 0, l3 = 0, f2 = 0, l2 = 0;
    const Handle(Geom_Curve) c3 = BRep_Tool::Curve(e, cl, f3, l3);
    const Handle(Geom2d_Curve) c2 = BRep_Tool::CurveOnSurface(e, f, f2, l2);
    const bool keeps = !BRep_Tool::Degenerated(e) && !c2.IsNull() && s->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) &&
                       (c3.IsNull() || keeps_parameter(c3));
    if (!keeps) return BRepTools_NurbsConvertModification::NewCurve2d(e, f, new_e, new_f, c, tol);
    c = c2->IsKind(STANDARD_TYPE(Geom2d_BSplineCurve)) ? Handle(Geom2d_Curve)::DownCast(c2->Copy())
                                                         : Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(c2, f2, l2));
    tol = BRep_Tool::Tolerance(e);
    return Standard_True;
  }

 private:
  static bool keeps_parameter(Handle(Geom_Curve) c) {
    while (c->IsKind(STANDARD_TYPE(Geom_TrimmedCurve))) c = Handle(Geom_TrimmedCurve)::DownCast(c)->BasisCurve();
    return c->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) || c->IsKind(STANDARD_TYPE(Geom_BezierCurve)) ||
           c->IsKind(STANDARD_TYPE(Geom_Line));
  }
};

// BRepBuilderAPI_NurbsConvert (the modifier and its vertex tolerance correction) with the modification above.
class NurbsConvertKeepingBSplines : public BRepBuilderAPI_NurbsConvert {
 public:
  explicit NurbsConvertKeepingBSplines(const TopoDS_Shape& shape) {
    myModification = new KeepBSplineFaces();
    Perform(shape);
  }
};

// The conversion runs on a copy of the topology (geometry shared): OCCT's modifier updates the vertices
// and edges it keeps (their parameters on the new curves), and other exporters read the part meanwhile.
brep::Part nurbs_part(const brep::Part& part) {
  brep::Part out;
  for (const brep::NamedBody& body : part) {
    BRepBuilderAPI_Copy copy(body.geometry.shape, /*copyGeom=*/false, /*copyMesh=*/false);
    NurbsConvertKeepingBSplines convert(copy.Shape());
    if (!convert.IsDone()) throw ExportError("IGES: conversion of body \"" + body.name + "\" to B-splines failed");
    brep::NamedBody b{body.name, {convert.Shape(), {}}};
    for (const brep::NamedFace& f : body.geometry.faces)
      b.geometry.faces.push_back({TopoDS::Face(convert.ModifiedShape(copy.ModifiedShape(f.face))), f.name});
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
