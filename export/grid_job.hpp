#pragma once
// The work of `coolinggen grid`: structured grids around blade sections (src/grid/section_grid.hpp),
// built and checked first, then written:
//   DIR/section_<k>.vtm (+ DIR/section_<k>_blocks/<block>.vts)   VTK XML multi-block
//   DIR/section_<k>.xyz                                            Plot3D, ASCII multi-block
//   DIR/section_<k>.cgns                                           CGNS, zones, BCs, 1-to-1 + periodic
//   DIR/grid_report.json                                           checks, counts, timings (below)
// k is the index into the config's sections; grids are in the section's own frame (a, b), mm.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/grid/section_grid.hpp"

namespace cg::io {

struct SectionGridRun {
  int section = 0;      ///< index into the config's sections (= model.profiles[section])
  double span = 0;      ///< span fraction of the section
  std::string name;     ///< file stem "section_<k>"
  grid::SectionGrid grid;
  double seconds = 0;   ///< build + checks
  std::vector<std::filesystem::path> files;
};

/// Builds the grids (no files). Throws InvalidGeometry "grid.<option>: ... (sections[k])" for impossible
/// options and AlgorithmFailure (naming the section) when a grid fails its checks.
std::vector<SectionGridRun> build_section_grids(const blade::BladeModel& model, const std::vector<int>& sections,
                                                const grid::SectionGridOptions& options);

/// Writes every run's files into `dir` (created) and `dir`/grid_report.json; `meta` (name, source ...) is
/// copied into the report. Every file is written atomically. Throws ExportError.
void write_section_grids(const std::filesystem::path& dir, std::vector<SectionGridRun>& runs, const nlohmann::json& meta);

/// The report of one run (also used for the CLI summary and tests).
nlohmann::ordered_json section_grid_json(const SectionGridRun& run);

}  // namespace cg::io
