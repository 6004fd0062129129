#include "src/cli/threads.hpp"

#include <OSD_ThreadPool.hxx>
#include <oneapi/tbb/global_control.h>

#include <cstdlib>
#include <string>

#include "src/core/parallel.hpp"

namespace cg::cli {

void add_threads_option(CLI::App* command, int& threads) {
  command->add_option("--threads", threads,
                      "Compute on at most N threads (default: COOLINGGEN_THREADS, else the CPUs this process may run on)")
      ->check(CLI::Range(1, kMaxThreadBudget))
      ->type_name("N");
}

void apply_thread_budget(int threads) {
  if (threads > 0) set_thread_budget(threads);
  if (thread_budget() < 0)
    throw ThreadBudgetError(std::string("COOLINGGEN_THREADS must be a whole number in [1, ") + std::to_string(kMaxThreadBudget) +
                            "], got '" + std::getenv("COOLINGGEN_THREADS") + "'");
  const int n = parallel_workers();
  // Kept to the process's end (never destroyed: TBB starts a thread to destroy one at exit).
  static tbb::global_control* const tbb_limit =
      new tbb::global_control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(n));
  (void)tbb_limit;
  OSD_ThreadPool::DefaultPool(n);  // created here with n threads: OCCT's algorithms that use its own pool
  // The previews' software renderer (Mesa's llvmpipe) rasterises on as many threads, unless set.
  setenv("LP_NUM_THREADS", std::to_string(n).c_str(), 0);
}

}  // namespace cg::cli
