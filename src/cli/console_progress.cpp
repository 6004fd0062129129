#include "src/cli/console_progress.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>

namespace cg::cli {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_sigint(int) { g_interrupted = true; }

std::string fixed(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

}  // namespace

// First SIGINT: flag only (SA_RESETHAND restores the default, so a second one terminates).
void install_interrupt_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, nullptr);
}

ConsoleProgress::ConsoleProgress(bool enabled) : enabled_(enabled) {
  if (enabled_) ticker_ = std::thread([this] { ticker(); });
}

ConsoleProgress::~ConsoleProgress() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ticker_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  interrupt_line();
}

bool ConsoleProgress::stdout_is_terminal() { return ::isatty(STDOUT_FILENO) == 1; }

void ConsoleProgress::stage_started(const std::string& stage, const std::string& title) {
  std::lock_guard<std::mutex> lock(mutex_);
  in_stage_ = true;
  stage_ = stage;
  title_ = title;
  step_.clear();
  fraction_ = -1;
  stage_start_ = std::chrono::steady_clock::now();
  last_width_ = 0;
  if (enabled_) redraw_locked(false, 0);
}

void ConsoleProgress::stage_progress(double fraction, const std::string& step) {
  std::lock_guard<std::mutex> lock(mutex_);
  step_ = step;
  fraction_ = fraction;
}

void ConsoleProgress::stage_finished(const std::string&, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (enabled_ && in_stage_) redraw_locked(true, seconds);
  in_stage_ = false;
}

bool ConsoleProgress::stop_requested() const { return g_interrupted; }

std::string ConsoleProgress::stop_reason() const { return g_interrupted ? "interrupted (Ctrl-C)" : "stop requested"; }

void ConsoleProgress::interrupt_line() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (enabled_ && in_stage_) {
    std::fputs("\n", stdout);
    std::fflush(stdout);
  }
  in_stage_ = false;
}

std::string ConsoleProgress::activity() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!in_stage_) return "";
  return "stage '" + stage_ + "'" + (step_.empty() ? "" : ", at " + step_);
}

// One line per stage: "  solid (blade surface trimmed ...)  3 s  general fuse 45%", redrawn with '\r'
// (padded to overwrite a longer previous text), finished as "  solid (...)  0.744 s".
void ConsoleProgress::redraw_locked(bool final_line, double seconds) {
  std::string line = "  " + title_ + "  ";
  if (final_line) {
    line += fixed(seconds, 3) + " s";
  } else {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_start_).count();
    line += fixed(elapsed, 0) + " s";
    if (!step_.empty()) line += "  " + step_;
    if (fraction_ >= 0) line += " " + fixed(100 * fraction_, 0) + "%";
  }
  const std::size_t width = line.size();
  if (width < last_width_) line.append(last_width_ - width, ' ');
  last_width_ = width;
  std::fputs(("\r" + line + (final_line ? "\n" : "")).c_str(), stdout);
  std::fflush(stdout);
}

void ConsoleProgress::ticker() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_ticker_) {
    wake_.wait_for(lock, std::chrono::milliseconds(500));
    if (!stop_ticker_ && in_stage_) redraw_locked(false, 0);
  }
}

}  // namespace cg::cli
