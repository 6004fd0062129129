#pragma once
// The files a build writes. Each format of config::OutputFormat (src/config/output_format.hpp, the one
// list of formats) has one writer here, chosen by the config's "output.formats"; report.json is always
// written, last, as the index of the directory (output_directory.hpp). A new format is a value of that
// enum plus its writer in output_writers() (outputs.cpp) and its name in
// data/schema/coolinggen.schema.json (output.formats).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "src/config/config.hpp"
#include "src/core/progress.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/output_directory.hpp"

namespace cg::pipeline {

inline constexpr const char* kReportFile = "report.json";

struct OutputWriter {
  config::OutputFormat format;
  std::string description;         ///< one line for people
  std::vector<std::string> files;  ///< the names it writes, removed when a later run does not write them
  /// Writes the format's files through `dir` (each atomically); may poll `progress`.
  std::function<void(OutputDirectory& dir, const config::Config&, const BuildResult&, ProgressSink* progress)> write;
};

/// One writer per output format, in the order of config::kOutputFormats (the order they are written).
const std::vector<OutputWriter>& output_writers();

struct WrittenOutputs {
  std::filesystem::path directory;
  std::vector<std::string> files;    ///< names in `directory`, report.json last
  std::vector<StageTiming> timings;  ///< one stage per format, then "report"
};

/// Writes the outputs of `result` into `dir` (created if missing): when every check passed the files of
/// config.output.formats, then report.json; when a check failed report.json only (valid: false).
/// Earlier runs' outputs in `dir` are removed first, and if writing fails or is cancelled the files of
/// this run are removed again, so after an exception `dir` holds no outputs (output_directory.hpp).
/// Throws io::ExportError, Cancelled (checked before each file).
WrittenOutputs write_outputs(const config::Config& config, const BuildResult& result, const std::filesystem::path& dir,
                             ProgressSink* progress = nullptr);

}  // namespace cg::pipeline
