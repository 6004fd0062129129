#pragma once
// VTK XML files of a structured multi-block grid (VTK 9.1): one .vts (vtkStructuredGrid, zlib-compressed
// appended binary) per block, `<stem>_<block>.vts` next to the .vtm that lists them (a
// vtkMultiBlockDataSet file written here directly, so every file is written atomically and all are plain
// names in one directory). Points in mm, z = `z`; cell data "scaled_jacobian" (smallest corner sine,
// < 0 = inverted) and "block" (block index), so ParaView can colour the quality at once.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "src/grid/block.hpp"

namespace cg::io {

/// Writes one block as .vts. Throws ExportError.
void write_vts(const std::filesystem::path& file, const grid::Block& block, int block_index = 0, double z = 0.0);

/// The .vtm alone: one DataSet per entry (block name, file name relative to the .vtm). Throws ExportError.
void write_vtm_index(const std::filesystem::path& vtm_file,
                     const std::vector<std::pair<std::string, std::string>>& blocks);

/// The .vts file name of a block next to `<stem>.vtm`: `<stem>_<block>.vts`.
std::string vts_file_name(const std::string& stem, const grid::Block& block);

/// Writes every block and the .vtm; returns the files written (the .vtm last). Throws ExportError.
std::vector<std::filesystem::path> write_vtm(const std::filesystem::path& vtm_file, const grid::MultiBlockGrid& grid,
                                             double z = 0.0);

}  // namespace cg::io
