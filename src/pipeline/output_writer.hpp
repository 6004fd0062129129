#pragma once
// The writer of one output format of a build (config::OutputFormat, src/config/output_format.hpp): the
// files it writes and how. The writers are listed in outputs.cpp (STEP) and handoff_formats.cpp (the
// hand-off formats).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "src/config/config.hpp"
#include "src/core/progress.hpp"
#include "src/pipeline/build_result.hpp"
#include "src/pipeline/output_directory.hpp"

namespace cg::pipeline {

/// The index of an output directory: written last by every job, so its presence means complete.
inline constexpr const char* kReportFile = "report.json";

struct OutputWriter {
  config::OutputFormat format;
  std::string description;         ///< one line for people
  std::vector<std::string> files;  ///< the names it writes, removed when a later run does not write them
  /// Writes the format's files through `dir` (each atomically); may poll `progress`.
  std::function<void(OutputDirectory& dir, const config::Config&, const BuildResult&, ProgressSink* progress)> write;
};

}  // namespace cg::pipeline
