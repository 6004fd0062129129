#include "src/study/sweep.hpp"

#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "export/atomic_file.hpp"
#include "src/config/config_error.hpp"
#include "src/core/format.hpp"
#include "src/pipeline/cooling_stage_cache.hpp"
#include "src/pipeline/stage_cache.hpp"
#include "src/study/design.hpp"
#include "src/core/process_pool.hpp"
#include "src/study/study_file.hpp"
#include "src/study/study_html.hpp"
#include "src/study/text_file.hpp"
#include "src/study/variant_config.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The last line of the variant's stderr, without "coolinggen: error: ".
std::string error_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  const std::string prefix = "coolinggen: error: ";
  return last.rfind(prefix, 0) == 0 ? last.substr(prefix.size()) : last;
}

std::vector<Variant> select(const std::vector<Variant>& all, const std::string& only) {
  if (only.empty()) return all;
  for (const Variant& v : all)
    if (v.id == only || (only.find_first_not_of("0123456789") == std::string::npos && only.size() < 10 && std::stoul(only) == v.index))
      return {v};
  throw config::ConfigError("--only: '" + only + "' is not a variant of the study (index 0 to " + std::to_string(all.size() - 1) +
                            " or id " + all.front().id + " to " + all.back().id + ")");
}

// The row of a finished process.
void record(ResultRow& row, const ProcessResult& r, const PreparedVariant& p, const SweepOptions& o) {
  row.exit_code = r.exit_code >= 0 ? std::optional<int>(r.exit_code) : std::nullopt;
  row.error = error_line(p.dir / "build.err");
  row.input_hash = p.input_hash;
  row.process_s = r.seconds;
  const nlohmann::json report = read_report(p.dir);
  const bool report_matches = report.is_object() && report.value("input_hash", "") == p.input_hash;
  if (r.killed_for_time) {
    row.status = Status::kTimeout;
    row.error = "killed after " + format_number(o.kill_after_s) + " s (no clean stop after --timeout " + format_number(o.timeout_s) + " s)";
  } else if (r.signal != 0) {
    row.status = Status::kFailed;
    row.error = std::string("ended by signal ") + std::to_string(r.signal) + " (" + strsignal(r.signal) + ")" + (row.error.empty() ? "" : ": " + row.error);
  } else if (r.exit_code == 0) {
    row.status = report_matches ? Status::kBuilt : Status::kFailed;
    // A built variant has no error (its stderr may still hold warnings; report.json lists them).
    row.error = report_matches ? std::string() : "exit 0 but no report.json with the variant's input_hash";
  } else {
    row.status = r.exit_code == 2 ? Status::kRefused : r.exit_code == 6 ? Status::kTimeout : Status::kFailed;
  }
  row.metrics = report_matches ? report_metrics(report) : Metrics{};
}

// An earlier run's outcome that a rerun would repeat: a report.json with the variant's input hash
// (built, or failed checks), or a status.json with it saying refused by the build (exit 2: a config
// error only the build finds) or failed with exit 3 (the model or solid cannot be made). Timeouts,
// crashes and output errors are run again.
bool up_to_date(const PreparedVariant& p, ResultRow& row) {
  ResultRow saved = row;
  const bool has_status = read_status(p.dir, saved) && saved.input_hash == p.input_hash;
  if (!has_status) saved = row;
  const nlohmann::json report = read_report(p.dir);
  if (report.is_object() && report.value("input_hash", "") == p.input_hash) {
    if (!has_status) {  // built before status.json was written (killed right after)
      const bool valid = report.value("valid", false);
      saved.status = valid ? Status::kBuilt : Status::kFailed;
      saved.exit_code = valid ? 0 : 3;
      saved.input_hash = p.input_hash;
    }
    saved.metrics = report_metrics(report);
    row = saved;
    return true;
  }
  const bool repeats = has_status && saved.exit_code && ((saved.status == Status::kRefused && *saved.exit_code == 2) ||
                                                          (saved.status == Status::kFailed && *saved.exit_code == 3));
  if (repeats) row = saved;
  return repeats;
}

std::string eta_text(double s) {
  if (s < 90) return std::to_string(static_cast<int>(s + 0.5)) + " s";
  return std::to_string(static_cast<int>(s / 60 + 0.5)) + " min";
}

}  // namespace

std::string slurm_script(const SweepOptions& o, const std::string& name, std::size_t variants) {
  const fs::path dir = fs::absolute(o.output).lexically_normal();
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by coolinggen sweep --emit slurm: one array task per variant of " << name << ".\n"
    << "# Submit with sbatch, then merge the variants' reports: coolinggen sweep --collect " << shell_quote(dir.string()) << "\n"
    << "#SBATCH --job-name=" << name << "\n"
    << "#SBATCH --array=0-" << variants - 1 << "%" << std::max(1, o.jobs) << "\n"
    << "#SBATCH --output=" << (dir / "slurm" / "%A_%a.out").string() << "\n"
    << "#SBATCH --ntasks=1\n"
    << "exec " << shell_quote(fs::absolute(o.executable).string()) << " sweep " << shell_quote(fs::absolute(o.study_file).lexically_normal().string())
    << " -o " << shell_quote(dir.string()) << " --only \"$SLURM_ARRAY_TASK_ID\" --jobs 1";
  if (o.timeout_s > 0) s << " --timeout " << format_round_trip(o.timeout_s);
  if (o.stage_cache == pipeline::StageCacheMode::kOff) s << " --stage-cache off";
  s << "\n";
  return s.str();
}

StudyListing collect_study(const fs::path& dir) {
  StudyListing l = read_listing(dir);
  collect_rows(dir, l);
  write_results_csv(dir, l);
  write_study_report(dir, l);
  write_study_html(dir, l);
  return l;
}

fs::path stage_cache_directory(const fs::path& study_dir) { return study_dir / "cache"; }

int variant_threads(int threads, int jobs) { return std::max(1, threads / std::max(1, jobs)); }

SweepOutcome run_sweep(const SweepOptions& o) {
  const auto t0 = Clock::now();
  if (o.stage_cache == pipeline::StageCacheMode::kMemory)
    throw config::ConfigError("--stage-cache: \"memory\" keeps stages within one process, and each variant of a sweep is its own "
                              "process (allowed: \"off\", \"disk\")");
  const Study study = load_study(o.study_file);
  const std::vector<Variant> all = expand_design(study);
  const std::vector<Variant> chosen = select(all, o.only);
  std::error_code ec;
  fs::create_directories(o.output / "variants", ec);
  if (ec) throw io::ExportError("cannot create " + (o.output / "variants").string() + ": " + ec.message());

  SweepOutcome out;
  StudyListing& l = out.listing;
  l.name = study.name;
  for (const Parameter& p : study.parameters) l.parameters.push_back(p.name);
  std::vector<PreparedVariant> prepared;
  std::vector<std::size_t> row_of;  // prepared[i] -> its row in l.rows
  for (const Variant& v : chosen) {
    prepared.push_back(prepare_variant(study, v, o.output));
    ResultRow row;
    row.id = v.id, row.values = v.values;
    const PreparedVariant& p = prepared.back();
    if (p.refused()) row.status = Status::kRefused, row.error = p.refusal, write_status(p.dir, row);
    l.rows.push_back(row);
    row_of.push_back(l.rows.size() - 1);
  }
  if (o.only.empty()) write_listing(o.output, l);
  else if (!fs::exists(o.output / "study_variants.json")) {  // a lone --only run: the listing without the others' checks
    StudyListing whole{l.name, l.parameters, {}};
    for (const Variant& v : all) {
      whole.rows.emplace_back();
      whole.rows.back().id = v.id, whole.rows.back().values = v.values;
    }
    write_listing(o.output, whole);
  }
  if (o.emit == Emit::kSlurm) {
    fs::create_directories(o.output / "slurm", ec);
    out.sbatch = o.output / "study.sbatch";
    const std::string text = slurm_script(o, study.name, all.size());
    write_text(out.sbatch, text);
    fs::permissions(out.sbatch, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add, ec);
    return out;
  }

  // Resume: what an earlier run of the same config found is kept.
  std::vector<ProcessSpec> specs;
  std::vector<std::size_t> spec_of;  // specs[k] -> prepared index
  std::map<std::string, std::size_t> builds_stage;  // cooling key -> the spec that builds it first
  const pipeline::StageCache cache({pipeline::StageCacheMode::kDisk, stage_cache_directory(o.output)});  // its entries' paths
  for (std::size_t i = 0; i < prepared.size(); ++i) {
    const PreparedVariant& p = prepared[i];
    if (p.refused()) continue;
    ResultRow& row = l.rows[row_of[i]];
    if (up_to_date(p, row)) {
      ++out.skipped;
      continue;
    }
    fs::remove(p.dir / "status.json", ec);  // of another config: the variant is pending until it ran
    ProcessSpec s;
    s.argv = {o.executable.string(), "build", p.config_file.string(), "-o", p.dir.string()};
    if (o.timeout_s > 0) s.argv.insert(s.argv.end(), {"--timeout", format_round_trip(o.timeout_s)});
    if (o.threads > 0) s.argv.insert(s.argv.end(), {"--threads", std::to_string(o.threads)});
    if (o.stage_cache == pipeline::StageCacheMode::kDisk) {
      s.argv.insert(s.argv.end(), {"--stage-cache", stage_cache_directory(o.output).string()});
      // The first variant of a cooling stage builds and stores it; the others of this run wait until
      // its entry is there (or the variant ended without storing it).
      if (!p.cooling_key.empty()) {
        const auto [it, first] = builds_stage.emplace(p.cooling_key, specs.size());
        if (first) s.ready_path = cache.entry_directory(pipeline::kCoolingStage, p.cooling_key);
        else s.after = it->second;
      }
    }
    s.stdout_file = p.dir / "build.log";
    s.stderr_file = p.dir / "build.err";
    s.kill_after_s = o.kill_after_s;
    specs.push_back(s);
    spec_of.push_back(i);
  }

  const bool tabulate = o.only.empty();
  if (tabulate) write_results_csv(o.output, l);
  int finished = 0;
  const auto progress = [&] {
    if (!o.progress) return;
    const auto n = status_counts(l);
    const auto count = [&](Status s) { return n.count(s) ? n.at(s) : 0; };
    const int remaining = static_cast<int>(specs.size()) - finished;
    const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    std::string line = "sweep: " + std::to_string(static_cast<int>(l.rows.size()) - count(Status::kPending)) + "/" +
                       std::to_string(l.rows.size()) + " done (" + std::to_string(count(Status::kBuilt)) + " built, " +
                       std::to_string(count(Status::kFailed) + count(Status::kTimeout)) + " failed, " +
                       std::to_string(count(Status::kRefused)) + " refused), " + std::to_string(remaining) + " remaining";
    if (finished > 0 && remaining > 0) line += ", ETA " + eta_text(elapsed / finished * remaining);
    o.progress(line);
  };
  PoolOptions pool;
  pool.jobs = o.jobs;
  pool.stop_requested = o.stop_requested;
  pool.on_tick = progress;
  pool.on_finished = [&](std::size_t k, const ProcessResult& r) {
    const PreparedVariant& p = prepared[spec_of[k]];
    ResultRow& row = l.rows[row_of[spec_of[k]]];
    ResultRow done = row;
    record(done, r, p, o);
    ++finished;
    if (r.interrupted && done.status != Status::kBuilt) return;  // stopped by Ctrl-C: still pending
    row = done;
    write_status(p.dir, row);
    if (tabulate) write_results_csv(o.output, l);
    progress();
  };
  progress();
  const std::vector<ProcessResult> results = run_processes(specs, pool);
  for (const ProcessResult& r : results) out.ran += r.started;
  bool unfinished = false;
  for (const ResultRow& row : l.rows) unfinished = unfinished || row.status == Status::kPending;
  out.interrupted = unfinished && o.stop_requested && o.stop_requested();
  if (tabulate) {
    write_results_csv(o.output, l);
    write_study_report(o.output, l);
    write_study_html(o.output, l);
  }
  progress();
  out.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace cg::study
