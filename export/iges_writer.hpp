#pragma once
// IGES export of a brep::Part for NURBS-based meshers (CENTAUR and the like), unit mm.
//
// By default faces are written in IGES "faces" mode (write.iges.brep.mode 0): every face is a trimmed
// surface (type 144) over a rational B-spline surface (128) whose boundaries are B-spline curves (126),
// in parameter space and in 3D — the entities such meshers read safely; IgesMode::Brep writes MSBO
// solids (186) instead. Exact geometry: analytic surfaces (cylindrical hole walls, planes) are
// converted to their exact rational B-spline form, and every closed surface is written open where its
// face's loops start, so each trim curve lies in its surface's domain (OCCT's reader sews the faces of
// the built-in example back into one closed shell of the part's volume: tests/acceptance).
// Faces are grouped per feature through IGESCAFControl_Writer: each face carries its feature name
// (name property, 406 form 15) and lies on the level of its feature kind, so boundary groups map to
// CFD boundaries; the levels are listed in FeatureTable order (level = kind id + 1).
#include <filesystem>
#include <string>

#include "src/brep/named_shape.hpp"

namespace cg::io {

/// Faces: every face a trimmed surface (144) with its own trim curves (142/126): what NURBS meshers
/// such as CENTAUR read; a reader rebuilds the topology by sewing. Brep: manifold solid B-rep objects
/// (186) with shells, faces, loops, shared edges and vertices (502/504/508/510/514): exact topology
/// for readers that take MSBO (CAD systems); the geometry is the same rational B-splines.
enum class IgesMode { Faces, Brep };

struct IgesOptions {
  std::string product_name = "blade";  ///< product name in the global section
  IgesMode mode = IgesMode::Faces;
};

/// Writes `part` atomically. Throws ExportError on failure.
void write_iges(const std::filesystem::path& file, const brep::Part& part, const IgesOptions& options = {});

}  // namespace cg::io
