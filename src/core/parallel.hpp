#pragma once
// Independent work items on all cores: a shared counter hands out the next index to the next free
// thread (no fixed partition, so a few large items do not leave a core idle).
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cg {

/// Threads for parallel work: one per core, or 1.
inline int worker_count(bool parallel) {
  return parallel ? std::max(1, static_cast<int>(std::thread::hardware_concurrency())) : 1;
}

/// Runs f(i, worker) for i in [0, n) on up to worker_count(parallel) threads (worker < that count).
/// The first exception stops the hand-out of further items and is rethrown after all threads ended.
inline void for_each_index(int n, bool parallel, const std::function<void(int, int)>& f) {
  const int threads = std::min(n, worker_count(parallel));
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) f(i, 0);
    return;
  }
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex m;
  for (int k = 0; k < threads; ++k)
    pool.emplace_back([&, k] {
      try {
        for (int i = next++; i < n; i = next++) f(i, k);
      } catch (...) {
        std::lock_guard<std::mutex> g(m);
        if (!error) error = std::current_exception();
        next = n;
      }
    });
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace cg
