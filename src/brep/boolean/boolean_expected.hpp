#pragma once
// The fallback expectation of a tool's effect when the feature gives none: OCCT's Common of the tool
// with the part (Cut) or Cut of the tool by the part (Fuse), a boolean of its own, independent of the
// step's multi-tool boolean; its volume by BRepGProp at relative accuracy 1e-10.
#include <TopoDS_Shape.hxx>

#include <string>

namespace cg::features {

enum class BooleanOperation;

/// Throws FeatureFailure naming `feature` when OCCT reports an error or warning.
double occt_expected_volume(const TopoDS_Shape& tool, const TopoDS_Shape& part, BooleanOperation op,
                            const std::string& feature);

/// Volume of a solid (BRepGProp, relative accuracy 1e-10), mm^3.
double occt_volume(const TopoDS_Shape& s);

}  // namespace cg::features
