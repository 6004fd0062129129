#pragma once
// The job of `coolinggen sweep` as a library call: load the study, expand its design, write and check
// every variant's config (refused ones never get a process), skip the variants whose report.json
// already carries their config's input_hash (resume), run the others as `coolinggen build` processes
// (process_pool.hpp) and keep results.csv, status.json and study_report.md up to date (results.hpp).
// Variants that differ only in the stages after the cooling stage share it through the stage cache in
// DIR/cache (pipeline/stage_cache.hpp). Or, with Emit::kSlurm, write DIR/study.sbatch (a job array of `sweep --only`) instead of running.
#include <filesystem>
#include <functional>
#include <string>

#include "src/pipeline/stage_cache.hpp"
#include "src/study/results.hpp"

namespace cg::study {

enum class Emit { kNone, kSlurm };

struct SweepOptions {
  std::filesystem::path study_file, output;
  std::filesystem::path executable;  ///< the coolinggen binary the variants run (current_executable())
  int jobs = 1;                      ///< processes at a time; with kSlurm the array's %K
  /// `--threads` of each variant's build: its share of the study's threads (variant_threads); 0: the
  /// build's own default.
  int threads = 0;
  double timeout_s = 0;              ///< --timeout of each variant's build (0: none)
  double kill_after_s = 0;           ///< a variant's process is killed after this (0: never)
  std::string only;                  ///< one variant: its index or id (Slurm array task); empty: all
  Emit emit = Emit::kNone;
  /// kDisk: the variants' builds share the stage cache DIR/cache (`build --stage-cache`), and a variant
  /// whose cooling stage another variant of this run builds waits for it; kOff: every variant builds
  /// every stage. (kMemory is a cache within one process: a sweep's variants are processes, so it is
  /// refused here.)
  pipeline::StageCacheMode stage_cache = pipeline::StageCacheMode::kDisk;
  std::function<bool()> stop_requested;                 ///< Ctrl-C
  std::function<void(const std::string&)> progress;     ///< a progress line, after each change and each second
};

struct SweepOutcome {
  StudyListing listing;
  int skipped = 0;           ///< up to date from an earlier run
  int ran = 0;               ///< processes started
  bool interrupted = false;  ///< stopped by stop_requested; unfinished variants stay pending
  double wall_s = 0;
  std::filesystem::path sbatch;  ///< Emit::kSlurm: the script written
};

/// Throws config::ConfigError for an invalid study (exit 2), io::ExportError when DIR cannot be written.
SweepOutcome run_sweep(const SweepOptions& options);

/// `sweep --collect DIR`: results.csv and study_report.md from the variants' status.json and report.json.
StudyListing collect_study(const std::filesystem::path& study_dir);

/// Each variant's share of `threads` when `jobs` variants run at a time: threads / jobs, at least 1.
int variant_threads(int threads, int jobs);

/// DIR/cache: the stage cache of the study in DIR.
std::filesystem::path stage_cache_directory(const std::filesystem::path& study_dir);

/// The text of study.sbatch: a job array over `variants` tasks, at most `max_parallel` at a time.
std::string slurm_script(const SweepOptions& options, const std::string& study_name, std::size_t variants);

}  // namespace cg::study
