#pragma once
// CGNS file (ADF/HDF5 as libcgns was built, read with any CGNS library) of a structured multi-block grid:
// one base (cell and physical dimension 2, units mm), one structured zone per block with CoordinateX/Y
// (double), the named boundary conditions (BCWall, BCInflow, BCOutflow, BCFarfield; PointRange, 1-based)
// and every connection as GridConnectivity1to1 written from both sides, periodic pairs with their
// translation (GridConnectivityProperty/Periodic, in mm).
#include <filesystem>
#include <string>

#include "src/grid/block.hpp"

namespace cg::io {

/// Writes atomically; base name `base` (<= 32 characters). Throws ExportError with the CGNS message.
void write_cgns(const std::filesystem::path& file, const grid::MultiBlockGrid& grid, const std::string& base);

}  // namespace cg::io
