#include "src/pipeline/outputs.hpp"

#include <algorithm>

#include "export/atomic_file.hpp"
#include "export/report.hpp"
#include "export/step_writer.hpp"
#include "src/pipeline/handoff_formats.hpp"
#include "src/pipeline/report.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;
namespace {

// All bodies in one STEP file, each a named solid, faces named and coloured per feature (XCAF).
void write_step_file(OutputDirectory& dir, const config::Config& c, const BuildResult& r, ProgressSink*) {
  if (r.part.empty()) throw io::ExportError("STEP: the build produced no body");
  const io::StepOptions options{io::parse_step_schema(c.output.step_schema),
                                c.output.product_name.empty() ? c.name : c.output.product_name};
  dir.write("blade.step", [&](const fs::path& target) { io::write_step(target, r.part, options); });
}

}  // namespace

const std::vector<OutputWriter>& output_writers() {
  static const std::vector<OutputWriter> writers = [] {
    std::vector<OutputWriter> all{{config::OutputFormat::Step, "STEP (AP242 or AP214, unit mm) with named bodies and faces",
                                   {"blade.step"}, write_step_file}};
    for (OutputWriter& h : handoff_writers()) all.push_back(std::move(h));
    // In the order of kOutputFormats, one each (a format without a writer is a programming error).
    std::vector<OutputWriter> ordered;
    for (const config::OutputFormatInfo& f : config::kOutputFormats) {
      const auto it = std::find_if(all.begin(), all.end(), [&](const OutputWriter& w) { return w.format == f.format; });
      if (it == all.end()) throw Error(std::string("output format \"") + f.name + "\" has no writer");
      ordered.push_back(*it);
    }
    return ordered;
  }();
  return writers;
}

WrittenOutputs write_outputs(const config::Config& c, const BuildResult& r, const fs::path& dir, ProgressSink* progress) {
  std::vector<std::string> owned{kReportFile};
  for (const OutputWriter& f : output_writers()) owned.insert(owned.end(), f.files.begin(), f.files.end());
  WrittenOutputs out;
  out.directory = dir;
  StageRunner stages(progress, out.timings);
  OutputDirectory od(dir, kReportFile, owned);
  // The triangulation and the sections start once the STEP file is written (the file most users wait
  // for: its writer then has the cores to itself) and overlap the single-threaded IGES writer; the guard
  // waits for them however this function ends (they read `r`).
  struct Finish {
    const BuildResult& r;
    ~Finish() { finish_shared_outputs(r); }
  } finish{r};
  if (r.valid()) {
    bool shared_started = false;
    for (const OutputWriter& f : output_writers()) {
      const bool selected = config::has_format(c.output.formats, f.format);
      if (!shared_started && f.format != config::OutputFormat::Step) {
        prepare_shared_outputs(c, r);
        shared_started = true;
      }
      std::string files;
      for (const std::string& n : f.files) files += (files.empty() ? "" : ", ") + n;
      if (selected) stages.run(config::output_format_name(f.format), "write " + files, [&] { f.write(od, c, r, progress); });
    }
  }
  stages.run("report", "write report.json", [&] {
    std::vector<StageTiming> timings = r.timings;
    timings.insert(timings.end(), out.timings.begin(), out.timings.end());
    od.commit([&](const fs::path& target, const std::vector<std::string>& files) {
      io::ReportContent rc = report_content(c, r, files, timings);
      add_handoff_report(c, r, rc);
      io::write_report(target, rc);
    });
  });
  out.files = od.files();
  return out;
}

}  // namespace cg::pipeline
