// coolinggen build [CONFIG] -o DIR [-q] [--timeout S] [--stage-cache CACHE_DIR]: the pipeline's run_build +
// write_outputs, printed.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "export/atomic_file.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/cli/output_jobs.hpp"
#include "src/cli/watchdog.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/time_limit.hpp"

namespace cg::cli {
namespace {

void print_summary(const config::Config& c, const pipeline::BuildResult& r, const pipeline::WrittenOutputs& w) {
  const brep::SolidCheck& k = r.checks.front();
  std::printf("%s: %s flow path, %zu sections\n", c.name.c_str(), r.model.trim.straight ? "straight" : "meridional",
              config::section_count(c));
  std::printf("  volume %.4f mm^3, surface %.4f mm^2, %d faces, bbox [%.3f %.3f %.3f] - [%.3f %.3f %.3f] mm\n", k.volume,
              k.area(), k.face_count, k.bbox_min[0], k.bbox_min[1], k.bbox_min[2], k.bbox_max[0], k.bbox_max[1],
              k.bbox_max[2]);
  std::printf("  checks:");
  for (const brep::Check* x : k.checks()) std::printf(" %s %s", x->name.c_str(), x->passed ? "ok" : "FAILED");
  std::printf("\n  time:");
  double total = 0;
  for (const auto* list : {&r.timings, &w.timings})
    for (const pipeline::StageTiming& t : *list) {
      std::printf(" %s %.3f s,", t.stage.c_str(), t.seconds);
      total += t.seconds;
    }
  std::printf(" total %.3f s\n", total);
  for (const pipeline::StageCacheUse& u : r.stage_cache)
    std::printf("  stage cache: %s %s (key %s)\n", u.stage.c_str(), pipeline::StageCacheUse::name(u.outcome), u.key.c_str());
  for (const std::string& warning : r.warnings) std::printf("  warning: %s\n", warning.c_str());
  std::printf("  wrote");
  for (std::size_t i = 0; i < w.files.size(); ++i)
    std::printf("%s %s", i ? "," : "", (w.directory / w.files[i]).string().c_str());
  std::printf("\n");
}

}  // namespace

int run_build_job(const JobOptions& o, const std::string& stage_cache_dir, const std::function<void(config::Config&)>& adjust) {
  ConsoleProgress console(o.show_progress());
  pipeline::TimeLimit limit(&console, o.timeout_s);
  Watchdog watchdog(limit, console, watchdog_grace(o.timeout_s), o.output.string());
  bool writing = false;
  try {
    std::error_code ec;  // fail now, not after a build of minutes
    if (std::filesystem::exists(o.output, ec) && !std::filesystem::is_directory(o.output, ec))
      throw io::ExportError("output directory " + o.output.string() + " exists and is not a directory");
    find_output_jobs();  // a missing module fails now, not after the build
    config::Config c = load_config_argument(o.config);
    if (adjust) adjust(c);
    std::optional<pipeline::StageCache> cache;
    if (!stage_cache_dir.empty()) cache.emplace(pipeline::StageCacheOptions{pipeline::StageCacheMode::kDisk, stage_cache_dir});
    pipeline::BuildOptions options;
    options.stage_cache = cache ? &*cache : nullptr;
    const pipeline::BuildResult r = pipeline::run_build(c, options, &limit);
    // The directory is touched only from here on (write_outputs polls before each file).
    if (limit.stop_requested()) throw Cancelled("writing outputs", "before");
    const OutputJobs& jobs = output_jobs();  // loads the writers' libraries (output_jobs.hpp)
    watchdog.set_writing();
    writing = true;
    const pipeline::WrittenOutputs w = jobs.write_outputs(c, r, o.output, &limit);
    console.interrupt_line();
    if (!r.valid())
      throw ChecksFailed("solid checks failed (" + r.failed_checks() + "); wrote " +
                         (o.output / pipeline::kReportFile).string() + " only (valid: false), no model files");
    if (!o.quiet) print_summary(c, r, w);
    return kOk;
  } catch (const Cancelled& e) {
    console.interrupt_line();
    throw Stopped(limit.stop_reason() + ": " + e.what() + "; " +
                  (writing ? "the outputs of this run were removed, " + o.output.string() + " holds none"
                           : "nothing written, " + o.output.string() + " left as it was"));
  } catch (...) {
    console.interrupt_line();
    throw;
  }
}

Command add_build_command(CLI::App& app) {
  auto o = std::make_shared<JobOptions>();
  CLI::App* cmd = app.add_subcommand("build", "Build and check the blade solid; write DIR/blade.step and DIR/report.json");
  add_job_options(cmd, *o);
  auto cache_dir = std::make_shared<std::string>();
  cmd->add_option("--stage-cache", *cache_dir,
                  "Take the cooling stage from DIR when a build of the same inputs stored it there, else store it "
                  "(docs/studies.md; coolinggen sweep passes its study's cache)")
      ->type_name("DIR");
  return {cmd, [o, cache_dir] { return run_build_job(*o, *cache_dir, {}); }};
}

}  // namespace cg::cli
