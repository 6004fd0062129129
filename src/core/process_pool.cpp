#include "src/core/process_pool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "src/core/error.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Running {
  std::size_t index;
  pid_t pid;
  Clock::time_point start;
  bool interrupted = false, killed = false;
  Clock::time_point interrupt_time;
};

// In the child: own process group, output files, exec. Only async-signal-safe calls after fork.
[[noreturn]] void exec_child(const std::vector<char*>& argv, const char* out, const char* err) {
  setpgid(0, 0);
  const int o = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644), e = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int null = open("/dev/null", O_RDONLY);
  if (o < 0 || e < 0 || null < 0) _exit(127);
  dup2(null, 0);
  dup2(o, 1);
  dup2(e, 2);
  signal(SIGINT, SIG_DFL);
  execv(argv[0], argv.data());
  static const char msg[] = "coolinggen: error: cannot run the variant's program\n";
  (void)!write(2, msg, sizeof msg - 1);
  _exit(127);
}

pid_t start(const ProcessSpec& s) {
  std::vector<char*> argv;
  for (const std::string& a : s.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string out = s.stdout_file.string(), err = s.stderr_file.string();
  const pid_t pid = fork();
  if (pid < 0) throw Error("cannot start a variant's process (fork failed)");
  if (pid == 0) exec_child(argv, out.c_str(), err.c_str());
  setpgid(pid, pid);  // also here, so the group exists before the parent signals it
  return pid;
}

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

fs::path current_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the running program (/proc/self/exe): " + ec.message());
  return p;
}

std::vector<ProcessResult> run_processes(const std::vector<ProcessSpec>& specs, const PoolOptions& o) {
  std::vector<ProcessResult> results(specs.size());
  std::vector<Running> running;
  // ready[i]: spec i ended or created its ready_path (checked for running specs only, once a tick).
  std::vector<bool> started(specs.size(), false), ready(specs.size(), false);
  std::size_t first_unstarted = 0;  // specs before it have all started
  bool stopping = false;
  auto last_tick = Clock::now();
  // The first spec that has not started and whose `after` spec (an earlier one) is ready.
  const auto next_ready = [&]() -> std::size_t {
    while (first_unstarted < specs.size() && started[first_unstarted]) ++first_unstarted;
    for (std::size_t i = first_unstarted; i < specs.size(); ++i) {
      const std::size_t a = specs[i].after;
      if (!started[i] && (a >= i || ready[a])) return i;
    }
    return specs.size();
  };
  while (first_unstarted < specs.size() || !running.empty()) {
    if (!stopping && o.stop_requested && o.stop_requested()) {
      stopping = true;
      for (Running& r : running) {
        kill(-r.pid, SIGINT);
        r.interrupted = true;
        r.interrupt_time = Clock::now();
      }
    }
    for (const Running& r : running) {
      std::error_code ec;
      if (!ready[r.index] && !specs[r.index].ready_path.empty() && fs::exists(specs[r.index].ready_path, ec)) ready[r.index] = true;
    }
    while (!stopping && static_cast<int>(running.size()) < std::max(1, o.jobs)) {
      const std::size_t next = next_ready();
      if (next == specs.size()) break;
      pid_t pid = -1;
      try {
        pid = start(specs[next]);
      } catch (const Error&) {  // no process left behind
        for (const Running& r : running) kill(-r.pid, SIGKILL), waitpid(r.pid, nullptr, 0);
        throw;
      }
      running.push_back({next, pid, Clock::now(), false, false, Clock::now()});
      results[next].started = true;
      started[next] = true;
    }
    if (stopping) first_unstarted = specs.size();
    for (std::size_t k = 0; k < running.size();) {
      Running& r = running[k];
      int status = 0;
      const pid_t w = waitpid(r.pid, &status, WNOHANG);
      if (w == r.pid) {
        ProcessResult& res = results[r.index];
        res.seconds = since(r.start);
        res.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        res.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        res.killed_for_time = r.killed && !r.interrupted;
        res.interrupted = r.interrupted;
        ready[r.index] = true;
        if (o.on_finished) o.on_finished(r.index, res);
        running.erase(running.begin() + static_cast<long>(k));
        continue;
      }
      const double limit = specs[r.index].kill_after_s;
      if (!r.killed && ((limit > 0 && since(r.start) > limit) || (r.interrupted && since(r.interrupt_time) > o.stop_grace_s))) {
        kill(-r.pid, SIGKILL);
        r.killed = true;
      }
      ++k;
    }
    if (o.on_tick && since(last_tick) > 0.2) {
      o.on_tick();
      last_tick = Clock::now();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return results;
}

}  // namespace cg::study
