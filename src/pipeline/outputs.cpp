#include "src/pipeline/outputs.hpp"

#include <algorithm>
#include <set>

#include "export/atomic_file.hpp"
#include "export/report.hpp"
#include "export/step_writer.hpp"
#include "src/config/json_fields.hpp"
#include "src/pipeline/handoff_formats.hpp"
#include "src/pipeline/network_format.hpp"
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

const std::vector<OutputFormat>& output_formats() {
  static const std::vector<OutputFormat> formats = [] {
    std::vector<OutputFormat> f{
        {"step", "STEP (AP242 or AP214, unit mm) with named bodies and faces", {"blade.step"}, write_step_file}};
    for (OutputFormat& h : handoff_formats()) f.push_back(std::move(h));
    // The network before report_md, so that report.md shows its headline numbers.
    const auto md = std::find_if(f.begin(), f.end(), [](const OutputFormat& x) { return x.name == "report_md"; });
    f.insert(md, network_format());
    return f;
  }();
  return formats;
}

void check_output_options(const config::Config& c) {
  std::string names;
  for (const OutputFormat& f : output_formats()) names += (names.empty() ? "\"" : ", \"") + f.name + "\"";
  std::set<std::string> seen;
  for (std::size_t i = 0; i < c.output.formats.size(); ++i) {
    const std::string& n = c.output.formats[i];
    const std::string path = "output.formats[" + std::to_string(i) + "]";
    bool known = false;
    for (const OutputFormat& f : output_formats()) known = known || f.name == n;
    if (!known) config::fail(path, "unknown output format \"" + n + "\" (allowed: " + names + ")");
    if (!seen.insert(n).second) config::fail(path, "\"" + n + "\" is listed twice");
  }
  check_network_options(c);
}

WrittenOutputs write_outputs(const config::Config& c, const BuildResult& r, const fs::path& dir, ProgressSink* progress) {
  check_output_options(c);
  std::vector<std::string> owned{kReportFile};
  for (const OutputFormat& f : output_formats()) owned.insert(owned.end(), f.files.begin(), f.files.end());
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
    for (const OutputFormat& f : output_formats()) {
      bool selected = false;
      for (const std::string& n : c.output.formats) selected = selected || n == f.name;
      if (!shared_started && f.name != "step") {
        prepare_shared_outputs(c, r);
        shared_started = true;
      }
      std::string files;
      for (const std::string& n : f.files) files += (files.empty() ? "" : ", ") + n;
      if (selected) stages.run(f.name, "write " + files, [&] { f.write(od, c, r, progress); });
    }
  }
  stages.run("report", "write report.json", [&] {
    std::vector<StageTiming> timings = r.timings;
    timings.insert(timings.end(), out.timings.begin(), out.timings.end());
    od.commit([&](const fs::path& target, const std::vector<std::string>& files) {
      io::ReportContent rc = report_content(c, r, files, timings);
      add_handoff_report(c, r, rc);
      add_network_report(r, rc);
      io::write_report(target, rc);
    });
  });
  out.files = od.files();
  return out;
}

}  // namespace cg::pipeline
