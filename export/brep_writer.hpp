#pragma once
// OCCT native B-rep file (BRepTools::Write) of a brep::Part: the compound of the bodies' solids in body
// order, exact geometry, no names (the format has none; STEP carries them).
#include <filesystem>

#include "src/brep/named_shape.hpp"

namespace cg::io {

/// Writes the part's compound atomically. Throws ExportError on failure.
void write_brep(const std::filesystem::path& file, const brep::Part& part);

}  // namespace cg::io
