#pragma once
// IGES export of a brep::Part for NURBS-based meshers (CENTAUR and the like), unit mm.
//
// Faces are written in IGES "faces" mode (write.iges.brep.mode 0): every face is a trimmed surface
// (type 144) over a rational B-spline surface (128) whose boundaries are B-spline curves (126), in
// parameter space and in 3D — the entities such meshers read safely. Exact geometry: analytic
// surfaces (cylindrical hole walls, planes) are converted to their exact rational B-spline form.
// Faces are grouped per feature through IGESCAFControl_Writer: each face carries its feature name
// (name property, 406 form 15) and lies on the level of its feature kind, so boundary groups map to
// CFD boundaries; the levels are listed in FeatureTable order (level = kind id + 1).
#include <filesystem>
#include <string>

#include "src/brep/named_shape.hpp"

namespace cg::io {

struct IgesOptions {
  std::string product_name = "blade";  ///< product name in the global section
};

/// Writes `part` atomically. Throws ExportError on failure.
void write_iges(const std::filesystem::path& file, const brep::Part& part, const IgesOptions& options = {});

}  // namespace cg::io
