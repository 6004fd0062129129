#pragma once
// The job of `coolinggen mesh` as a library call: a build result -> tetrahedral meshes of its metal
// bodies and of its coolant domain (src/mesh/blade_mesher.hpp) written into one output directory with
// report.json (solid checks + "mesh" statistics) and report.md, with the same directory discipline as
// write_outputs (output_directory.hpp: previous outputs removed, report.json last, nothing left on error).
#include <filesystem>
#include <string>
#include <vector>

#include "src/config/config.hpp"
#include "src/core/progress.hpp"
#include "src/mesh/blade_mesher.hpp"
#include "src/pipeline/build.hpp"

namespace cg::pipeline {

/// The mesher's options of a config's "mesh" section.
mesh::MeshOptions mesh_options(const config::MeshConfig& config);

struct MeshOutputs {
  std::filesystem::path directory;
  std::vector<std::string> files;    ///< names in `directory`, report.json last
  mesh::MeshResult mesh;             ///< empty when the build's checks failed (nothing meshed)
  std::vector<StageTiming> timings;  ///< "mesh", "report"
};

/// Meshes `result` (when every check passed) and writes the files into `dir` (created if missing);
/// report.md when config.output.formats lists "report_md". Throws MeshError, io::ExportError, Cancelled.
MeshOutputs write_mesh(const config::Config& config, const BuildResult& result, const std::filesystem::path& dir,
                       ProgressSink* progress = nullptr);

}  // namespace cg::pipeline
