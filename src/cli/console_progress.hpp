#pragma once
// Stage progress on the terminal, and Ctrl-C as a clean stop request.
//
// With `enabled`, each stage shows one line on stdout that is redrawn in place while the stage runs
// (elapsed seconds, the running step, percent when the algorithm reports it) and ends with the stage's
// time. Disabled (stdout not a terminal, or -q), nothing is printed. Once install_interrupt_handler()
// ran, the first Ctrl-C (SIGINT) asks the running job to stop at its next check point; a second one
// ends the process at once.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "src/core/progress.hpp"

namespace cg::cli {

/// Makes the first SIGINT a stop request of every ConsoleProgress (process-wide; main() calls it).
void install_interrupt_handler();

class ConsoleProgress : public ProgressSink {
 public:
  explicit ConsoleProgress(bool enabled);
  ~ConsoleProgress() override;
  ConsoleProgress(const ConsoleProgress&) = delete;
  ConsoleProgress& operator=(const ConsoleProgress&) = delete;

  /// Whether progress is shown by default: stdout is a terminal.
  static bool stdout_is_terminal();

  void stage_started(const std::string& stage, const std::string& title) override;
  void stage_progress(double fraction, const std::string& step) override;
  void stage_finished(const std::string& stage, double seconds) override;
  bool stop_requested() const override;
  std::string stop_reason() const override;

  /// Ends a stage line that did not finish (error, stop), so later output starts on a new line.
  void interrupt_line();
  /// What runs now: "stage 'verify', at volume and area" ("" between stages). Thread-safe.
  std::string activity();

 private:
  void redraw_locked(bool final_line, double seconds);
  void ticker();

  bool enabled_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
  bool stop_ticker_ = false;
  bool in_stage_ = false;
  std::string stage_, title_, step_;
  double fraction_ = -1;  // < 0: not reported
  std::chrono::steady_clock::time_point stage_start_;
  std::size_t last_width_ = 0;
};

}  // namespace cg::cli
