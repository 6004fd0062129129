#pragma once
// Independent work items on the machine's cores (std::thread; no OCCT or TBB in the kernel).
#include <algorithm>
#include <atomic>
#include <exception>
#include <future>
#include <thread>
#include <vector>

namespace cg {

/// The CPUs this process may run on: its affinity mask (as `taskset` or Slurm's --cpus-per-task set it),
/// else the machine's; at least 1.
int available_cpus();

/// The thread budget: the environment variable COOLINGGEN_THREADS, a whole number in [1,
/// kMaxThreadBudget] (as OMP_NUM_THREADS is to OpenMP; `coolinggen --threads` sets it, a study passes
/// its share to each variant); 0 when unset, -1 when set to anything else.
constexpr int kMaxThreadBudget = 1024;
int thread_budget();

/// Worker threads for parallel loops: available_cpus(), at most the thread budget.
int parallel_workers();

/// How work that could run beside the caller starts: on a thread of its own (std::launch::async) when
/// there is more than one worker, else deferred to the caller's first wait (`--threads 1`).
inline std::launch beside_or_deferred() { return parallel_workers() > 1 ? std::launch::async : std::launch::deferred; }

/// Sets the thread budget (COOLINGGEN_THREADS) of this process and of the processes it starts; call it
/// before any other thread runs. OCCT's and TBB's threads are the caller's (src/cli/threads.hpp).
void set_thread_budget(int threads);

/// Runs f(i, worker) for every i in [0, n) on up to `workers` threads (worker in [0, workers): give
/// each worker its own non-thread-safe state). Items are taken in order as workers become free. When
/// items throw, the remaining ones are skipped and the exception of the lowest item index is rethrown,
/// so the error does not depend on the scheduling.
template <class F>
void parallel_for(int n, int workers, F&& f) {
  workers = std::clamp(workers, 1, std::max(n, 1));
  if (workers == 1) {
    for (int i = 0; i < n; ++i) f(i, 0);
    return;
  }
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(n));
  std::atomic<bool> failed{false};
  auto run = [&](int worker) {
    for (int i = next++; i < n && !failed; i = next++) {
      try {
        f(i, worker);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
  run(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace cg
