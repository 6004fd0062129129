#pragma once
// Binary STL of a brep::Part: the triangulation of export/triangulation.hpp (BRepMesh on a copy of
// every body to the given deflection, outward-oriented triangles) written as little-endian binary STL
// (80-byte header naming the tool, unit and product; triangle count; per triangle the unit normal and
// three vertices as float32, attribute 0). One file for all bodies.
#include <filesystem>
#include <string>

#include "export/triangulation.hpp"

namespace cg::io {

/// Writes the triangles atomically; returns the triangle count. Throws ExportError on failure.
std::size_t write_stl(const std::filesystem::path& file, const PartTriangles& triangles, const std::string& product_name = "blade");

/// Triangulates `part` (deflections from `options`) and writes it.
std::size_t write_stl(const std::filesystem::path& file, const brep::Part& part, const TriangulationOptions& options = {},
                      const std::string& product_name = "blade");

}  // namespace cg::io
