#pragma once
// The guarantee behind --timeout: a time limit stops the job at its next check point (cooperative,
// nothing half-written). A step without check points (e.g. OCCT's volume integration) could still run
// long past the limit, so when the job has not stopped `grace_s` after the limit, the watchdog prints
// the error naming the stage and ends the process with exit code 6. It never does so while outputs are
// written (set_writing): output files are written one by one with check points between them, and
// before that nothing in the output directory has been touched.
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "src/cli/console_progress.hpp"
#include "src/pipeline/time_limit.hpp"

namespace cg::cli {

class Watchdog {
 public:
  /// `limit` without a limit (seconds <= 0): the watchdog does nothing. `output` names the directory
  /// in the message.
  Watchdog(const pipeline::TimeLimit& limit, ConsoleProgress& console, double grace_s, std::string output);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  /// From here on the job writes outputs and is not ended by the watchdog.
  void set_writing();

 private:
  void watch();

  const pipeline::TimeLimit& limit_;
  ConsoleProgress& console_;
  double grace_s_;
  std::string output_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false, writing_ = false;
  std::thread thread_;
};

/// Grace after the time limit: 10 % of the limit, at least 2 s and at most 30 s.
double watchdog_grace(double timeout_s);

}  // namespace cg::cli
