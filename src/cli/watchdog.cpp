#include "src/cli/watchdog.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "src/cli/exit_codes.hpp"
#include "src/core/format.hpp"

namespace cg::cli {

double watchdog_grace(double timeout_s) { return std::clamp(0.1 * timeout_s, 2.0, 30.0); }

Watchdog::Watchdog(const pipeline::TimeLimit& limit, ConsoleProgress& console, double grace_s, std::string output)
    : limit_(limit), console_(console), grace_s_(grace_s), output_(std::move(output)) {
  if (limit_.seconds() > 0) thread_ = std::thread([this] { watch(); });
}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Watchdog::set_writing() {
  std::lock_guard<std::mutex> lock(mutex_);
  writing_ = true;
}

void Watchdog::watch() {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_.seconds() + grace_s_);
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_until(lock, end, [this] { return done_; }) || writing_) return;
  // Still running grace_s after the limit, in a step without check points.
  const std::string where = console_.activity();
  console_.interrupt_line();
  error_exit(kStopped, limit_.stop_reason() + ": stopped in " + (where.empty() ? std::string("the job") : where) +
                           " (no check point came within " + format_number(grace_s_) +
                           " s of the limit); nothing written, " + output_ + " left as it was");
  std::_Exit(kStopped);
}

}  // namespace cg::cli
