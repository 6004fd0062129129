#pragma once
// Work that runs beside the caller on cores the caller leaves idle.
#include <future>
#include <type_traits>
#include <utility>

#include "src/core/parallel.hpp"

namespace cg {

/// Lowers the calling thread's scheduling priority to the lowest (Linux: nice 19 for this thread
/// only; elsewhere nothing). Threads it starts afterwards inherit it.
void lower_thread_priority();

/// Starts f() on a new thread at the lowest priority and returns its future (get() returns f's value
/// or rethrows its exception; the future's destructor waits for f). The foreground keeps its cores
/// while it uses them, and f takes what it leaves idle (the single-threaded stretches of OCCT
/// algorithms): measured on the cooled example, tools built beside the core at equal priority slowed
/// the core's parallel split by half (1.2 -> 1.8 s); at nice 19 the split kept its time and the tools
/// filled the fillet stage's idle core. With one worker (parallel_workers(), `--threads 1`) f runs in
/// the caller, at its priority, when the future is first waited for.
template <class F>
std::future<std::invoke_result_t<std::decay_t<F>&>> start_in_background(F&& f) {
  const std::launch launch = beside_or_deferred();
  const bool beside = launch == std::launch::async;
  return std::async(launch, [beside, fn = std::forward<F>(f)]() mutable {
    if (beside) lower_thread_priority();
    return fn();
  });
}

}  // namespace cg
