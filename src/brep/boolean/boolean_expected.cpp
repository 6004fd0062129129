#include "src/brep/boolean/boolean_expected.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>

#include "src/brep/boolean/boolean_alerts.hpp"
#include "src/brep/boolean/verified_boolean.hpp"

namespace cg::features {

double occt_volume(const TopoDS_Shape& s) {
  GProp_GProps p;
  BRepGProp::VolumeProperties(s, p, 1e-10, /*OnlyClosed=*/Standard_True);
  return p.Mass();
}

double occt_expected_volume(const TopoDS_Shape& tool, const TopoDS_Shape& part, BooleanOperation op,
                            const std::string& feature) {
  std::string why;
  try {
    TopTools_ListOfShape a, b;
    a.Append(tool);
    b.Append(part);
    BRepAlgoAPI_Common common;
    BRepAlgoAPI_Cut cut;
    BRepAlgoAPI_BooleanOperation& bop = op == BooleanOperation::Cut ? static_cast<BRepAlgoAPI_BooleanOperation&>(common)
                                                                     : static_cast<BRepAlgoAPI_BooleanOperation&>(cut);
    bop.SetArguments(a);
    bop.SetTools(b);
    bop.SetRunParallel(false);  // the step runs several of these side by side
    bop.SetNonDestructive(true);
    bop.SetToFillHistory(false);
    bop.Build();
    if (bop.HasErrors() || bop.HasWarnings()) why = alert_summary(bop.GetReport());
    else return occt_volume(bop.Shape());
  } catch (const Standard_Failure& e) {
    why = std::string("exception ") + e.GetMessageString();
  }
  throw FeatureFailure(feature + ": no independent expectation of its volume (OCCT " +
                       (op == BooleanOperation::Cut ? "Common" : "Cut") + " of the tool with the part: " + why +
                       "); give the tool's expected_volume");
}

}  // namespace cg::features
