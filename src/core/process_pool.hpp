#pragma once
// (Shared by design studies and the network solver run; namespace kept from src/study.)
// Runs commands as child processes, at most `jobs` at a time, in order (a spec may wait for an earlier one
// to end or to create a path: ProcessSpec::after, ready_path). Each child runs in its own process group
// with stdout and stderr in files; one that outlives its `kill_after_s` is killed (SIGKILL to its
// group). When `stop_requested` turns true no child is started any more, the running ones get SIGINT
// (a coolinggen build stops cleanly at its next check point) and, after `stop_grace_s`, SIGKILL.
// A child that crashes, hangs or is killed is one result among the others.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cg::study {

struct ProcessSpec {
  std::vector<std::string> argv;  ///< argv[0] is the program (a path)
  std::filesystem::path stdout_file, stderr_file;
  double kill_after_s = 0;  ///< 0: never
  /// Index of an earlier spec that must have ended before this one starts (e.g. the variant that
  /// stores the stage this one takes from the stage cache); kNone: no such wait. Specs start in
  /// order, a waiting one skipped for the next that can start.
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t after = kNone;
  /// A path this spec's process creates when what the specs waiting for it need is there (the stage
  /// cache's entry): once it exists they start without waiting for the end. Empty: only the end counts.
  std::filesystem::path ready_path;
};

struct ProcessResult {
  int exit_code = -1;      ///< exit status, -1 when ended by a signal
  int signal = 0;          ///< the signal that ended it
  bool killed_for_time = false;
  bool interrupted = false;  ///< it was asked to stop (stop_requested)
  bool started = false;      ///< false: never started (stop requested before its turn)
  double seconds = 0;        ///< wall clock
};

struct PoolOptions {
  int jobs = 1;
  double stop_grace_s = 10;
  std::function<bool()> stop_requested;                           ///< polled; may be empty
  std::function<void(std::size_t, const ProcessResult&)> on_finished;  ///< index into specs; not for unstarted ones
  std::function<void()> on_tick;                                  ///< about every 0.2 s (a progress line)
};

/// Runs `specs`; returns one result per spec. Throws cg::Error when fork fails.
std::vector<ProcessResult> run_processes(const std::vector<ProcessSpec>& specs, const PoolOptions& options);

/// The running program's executable (/proc/self/exe).
std::filesystem::path current_executable();

}  // namespace cg::study
