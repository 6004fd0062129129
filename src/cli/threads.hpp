#pragma once
// How many threads a coolinggen process computes on: `--threads N` on every command that computes, else
// the environment's COOLINGGEN_THREADS (src/core/parallel.hpp), else the CPUs the process may run on
// (its affinity mask: taskset, Slurm's --cpus-per-task). A study (`sweep --jobs K`) gives each variant
// its share, so K builds side by side do not run K times as many threads as there are cores.
#include <CLI/CLI.hpp>

#include <stdexcept>

namespace cg::cli {

/// Adds --threads to `command` (stored in `threads`, 0 when not given).
void add_threads_option(CLI::App* command, int& threads);

/// Sets the budget before any thread runs: CoolingGen's own loops, TBB's (OCCT's booleans and meshing
/// run on it), OCCT's thread pool and the rasteriser threads of the previews' software renderer
/// (LP_NUM_THREADS, unless set). Throws ThreadBudgetError for a COOLINGGEN_THREADS that is not a
/// whole number in [1, 1024] (a command-line error, exit 1).
void apply_thread_budget(int threads);

struct ThreadBudgetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cg::cli
