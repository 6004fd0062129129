#pragma once
// Shared by the benchmarks: best-of-N timing, and the tally of disagreements with OCCT found on the
// results of the TIMED runs themselves. A benchmark exits with status 1 when any disagreement is found,
// so the CI smoke run (--quick) fails on a fast wrong answer.
#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>

namespace bench {

/// Best wall time in seconds of `run` over `reps` runs (the minimum is the least disturbed by the
/// other jobs on this shared machine). run(rep) is told the repetition index.
template <class Run>
double best_seconds(int reps, Run run) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    run(r);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

/// Counts disagreements; the first few are printed with their details.
class Checker {
 public:
  void fail(const char* fmt, ...) {
    if (++count_ <= 10) {
      std::va_list args;
      va_start(args, fmt);
      std::fputs("DISAGREEMENT: ", stdout);
      std::vprintf(fmt, args);
      std::fputc('\n', stdout);
      va_end(args);
    }
  }
  long count() const { return count_; }
  /// Prints the verdict; the process exit status (0: every result agreed).
  int finish(const char* bench) const {
    if (count_ == 0) {
      std::printf("%s: every timed result agrees with OCCT (or is proven better)\n", bench);
      return 0;
    }
    std::printf("%s: %ld DISAGREEMENTS with OCCT\n", bench, count_);
    return 1;
  }

 private:
  long count_ = 0;
};

}  // namespace bench
