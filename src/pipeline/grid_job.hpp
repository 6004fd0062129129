#pragma once
// The work of `coolinggen grid`: structured, wall-orthogonal grids around the blade sections
// (src/grid/section_grid.hpp) for the config's "grid" section (config/grid_config.hpp; without one,
// the defaults for every defined section), built and checked first, then written into one directory
// through OutputDirectory (the previous grid run's files are removed; grid_report.json, the index, last):
//   section_<k>.vtm + section_<k>_<block>.vts   VTK XML multi-block (ParaView)
//   section_<k>.xyz                               Plot3D, ASCII multi-block
//   section_<k>.cgns                              CGNS: zones, named BCs, 1-to-1 + periodic connections
//   grid_report.json                              per section: cells, checks, wall angles, timings, files
// k is the index into the config's sections; grids are in each section's own frame (a, b), mm.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "src/config/config.hpp"
#include "src/core/progress.hpp"
#include "src/grid/section_grid.hpp"
#include "src/pipeline/build.hpp"

namespace cg::pipeline {

inline constexpr const char* kGridReportFile = "grid_report.json";

struct SectionGridRun {
  int section = 0;    ///< index into the config's sections (= model.profiles[section])
  double span = 0;    ///< span fraction of the section
  std::string name;   ///< file stem "section_<k>"
  grid::SectionGrid grid;
  double seconds = 0;  ///< build + checks
};

struct GridResult {
  blade::BladeModel model;
  std::vector<SectionGridRun> runs;
  std::vector<StageTiming> timings;  ///< "blade_model", then one stage per section
};

/// Builds the blade model and the grids. Throws ConfigError ("grid.<field>: ... (sections[k])") for
/// options the section cannot take, AlgorithmFailure ("sections[k]: ...") when a grid fails its checks,
/// Cancelled when `progress` asks to stop.
GridResult run_grid(const config::Config& config, ProgressSink* progress = nullptr);

struct WrittenGrid {
  std::filesystem::path directory;
  std::vector<std::string> files;  ///< names in `directory`, grid_report.json last
};

/// Writes every run's files and grid_report.json into `dir` (created if missing). Throws io::ExportError,
/// Cancelled (the files of this run are then removed again).
WrittenGrid write_grid_outputs(const config::Config& config, const GridResult& result, const std::filesystem::path& dir,
                               ProgressSink* progress = nullptr);

/// The report entry of one section (grid_report.json "sections"[i]).
nlohmann::ordered_json section_grid_json(const SectionGridRun& run);

}  // namespace cg::pipeline
