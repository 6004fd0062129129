#pragma once
// An XCAF document of a brep::Part, shared by the STEP and IGES writers: one product (the part,
// named `product_name`) whose shape is a compound of the bodies' solids; every solid is a named
// sub-shape (its body name, "blade", "insert_1"), every face a named and coloured sub-shape (its
// feature name, colour of its feature kind: export/feature_style.hpp) on the layer of its kind
// (IGES level). CAD tools show this as one multi-body part with named bodies and faces.
#include <TDocStd_Application.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Compound.hxx>

#include <string>

#include "src/brep/named_shape.hpp"

namespace cg::io {

/// Owns an open XCAF document and closes it on destruction (the application keeps a list of open
/// documents, which would otherwise grow with every export).
class PartDocument {
 public:
  /// Builds the document; throws ExportError when the part is empty, a body is not one solid, or a
  /// named face is not a face of its body.
  PartDocument(const brep::Part& part, const std::string& product_name);
  ~PartDocument();
  PartDocument(const PartDocument&) = delete;
  PartDocument& operator=(const PartDocument&) = delete;

  const Handle(TDocStd_Document)& document() const { return doc_; }
  /// The compound of the bodies' shapes, in body order (what the document's product holds).
  const TopoDS_Compound& compound() const { return compound_; }

 private:
  Handle(TDocStd_Application) app_;
  Handle(TDocStd_Document) doc_;
  TopoDS_Compound compound_;
};

/// The compound of the bodies' shapes of a part, in body order.
TopoDS_Compound part_compound(const brep::Part& part);

}  // namespace cg::io
