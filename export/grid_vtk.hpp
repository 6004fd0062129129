#pragma once
// VTK XML files of a structured multi-block grid (VTK 9.1): one .vts (vtkStructuredGrid, zlib-compressed
// appended binary) per block in the directory `<stem>_blocks/` next to the .vtm that lists them (a
// vtkMultiBlockDataSet file written here directly, so every file is written atomically). Points in mm,
// z = `z`; cell data "scaled_jacobian" (smallest corner sine, < 0 = inverted) and "block" (block index),
// so ParaView can colour the quality at once.
#include <filesystem>
#include <vector>

#include "src/grid/block.hpp"

namespace cg::io {

/// Writes one block as .vts. Throws ExportError.
void write_vts(const std::filesystem::path& file, const grid::Block& block, int block_index = 0, double z = 0.0);

/// Writes every block and the .vtm; returns the files written (the .vtm last). Throws ExportError.
std::vector<std::filesystem::path> write_vtm(const std::filesystem::path& vtm_file, const grid::MultiBlockGrid& grid,
                                             double z = 0.0);

}  // namespace cg::io
