#pragma once
// Reading a blade given as CAD (blade.import format "step" or "iges"): the file's shape through
// OCCT's STEP or IGES reader (every root transferred, lengths in mm), and its faces.
#include <TopoDS_Shape.hxx>

#include <string>

namespace cg::cad_import {

enum class CadFormat { Step, Iges };

/// Throws InvalidGeometry "<file>: ..." when the file is not one the reader can read, or holds no
/// face (a blade is a solid, a shell or a set of surfaces).
TopoDS_Shape read_cad_shape(const std::string& path, CadFormat format);

}  // namespace cg::cad_import
