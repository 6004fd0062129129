#pragma once
// Plot3D grid file (.xyz) of a structured multi-block grid: formatted (ASCII), multi-block, 3D with one
// plane (nk = 1, z = `z`), no IBLANK, coordinates in mm with 17 significant digits (lossless). This is
// the layout most readers accept without options (ParaView's PLOT3D reader with "multi grid" on, Pointwise,
// Tecplot):
//   nblocks
//   ni nj nk            (one line per block, node counts)
//   x... y... z...      (per block, i fastest, then j)
#include <filesystem>

#include "src/grid/block.hpp"

namespace cg::io {

/// Writes atomically (export/atomic_file.hpp); throws ExportError.
void write_plot3d(const std::filesystem::path& file, const grid::MultiBlockGrid& grid, double z = 0.0);

}  // namespace cg::io
