#pragma once
// Binary STL of a brep::Part: every body triangulated with BRepMesh (on a copy, so the part keeps no
// mesh) to the given deflection, then StlAPI_Writer. One file for all bodies.
#include <filesystem>

#include "src/brep/named_shape.hpp"

namespace cg::io {

struct StlOptions {
  double linear_deflection = 0.01;  ///< mm, largest distance between triangle and surface, > 0
  double angular_deflection = 0.35; ///< rad, largest angle between normals of adjacent triangles, > 0
};

/// Writes the binary STL atomically; returns the triangle count. Throws ExportError on failure.
std::size_t write_stl(const std::filesystem::path& file, const brep::Part& part, const StlOptions& options = {});

}  // namespace cg::io
