#include "src/core/parallel.hpp"

#include <sched.h>

#include <cstdlib>
#include <string>

namespace cg {

namespace {
constexpr const char* kBudgetVariable = "COOLINGGEN_THREADS";
}  // namespace

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int thread_budget() {
  const char* text = std::getenv(kBudgetVariable);
  if (!text || !*text) return 0;
  long n = 0;
  for (const char* c = text; *c; ++c) {
    if (*c < '0' || *c > '9' || n > kMaxThreadBudget) return -1;
    n = 10 * n + (*c - '0');
  }
  return n >= 1 && n <= kMaxThreadBudget ? static_cast<int>(n) : -1;
}

int parallel_workers() {
  const int cpus = available_cpus(), budget = thread_budget();
  return budget > 0 ? std::min(budget, cpus) : cpus;
}

void set_thread_budget(int threads) { setenv(kBudgetVariable, std::to_string(threads).c_str(), 1); }

}  // namespace cg
