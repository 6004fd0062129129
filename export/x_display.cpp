#include "export/x_display.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace cg::io {
namespace {

// The Xvfb this process started; terminated at exit.
struct OwnXvfb {
  pid_t pid = -1;
  std::string display;
  ~OwnXvfb() {
    if (pid > 0) {
      ::kill(pid, SIGTERM);
      int status = 0;
      ::waitpid(pid, &status, 0);
    }
  }
};
OwnXvfb& own_xvfb() {
  static OwnXvfb x;
  return x;
}

// Starts `Xvfb -displayfd W -screen 0 1280x1024x24 -nolisten tcp` and waits (<= 10 s) for the display
// number it writes to W when it accepts connections.
DisplayStatus start_xvfb() {
  DisplayStatus s;
  int fds[2];
  if (::pipe(fds) != 0) {
    s.message = "cannot create a pipe to start Xvfb";
    return s;
  }
  const std::string fd = std::to_string(fds[1]);  // before fork: the child only calls async-signal-safe functions
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    s.message = "cannot fork to start Xvfb";
    return s;
  }
  if (pid == 0) {
    ::close(fds[0]);
    // Keep the server's own output out of ours; it has nothing the user needs.
    if (const int null = ::open("/dev/null", O_RDWR); null >= 0) {
      ::dup2(null, STDIN_FILENO);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    ::setpgid(0, 0);  // not in the caller's process group: a terminal ^C reaches us, we stop it
    ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  for (int waited = 0; waited < 10000;) {
    const int r = ::poll(&p, 1, 200);
    waited += 200;
    if (r > 0) {
      char buf[32];
      const ssize_t n = ::read(fds[0], buf, sizeof buf);
      if (n <= 0) break;  // Xvfb exited (not installed: exec failed) or closed the pipe
      number.append(buf, static_cast<std::size_t>(n));
      if (number.find('\n') != std::string::npos) break;
    }
  }
  ::close(fds[0]);
  while (!number.empty() && (number.back() == '\n' || number.back() == ' ')) number.pop_back();
  if (number.empty()) {
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    s.message = "no X display (DISPLAY unset or not answering) and Xvfb could not be started; install it with "
                "`apt-get install xvfb xauth` (scripts/install-deps.sh) or set DISPLAY";
    return s;
  }
  own_xvfb().pid = pid;
  own_xvfb().display = ":" + number;
  s.available = true;
  s.started_xvfb = true;
  s.display = own_xvfb().display;
  s.message = "started Xvfb on display " + s.display;
  return s;
}

}  // namespace

bool x_display_answers(const std::string& display) {
  if (display.empty()) return false;
  const std::size_t colon = display.rfind(':');
  if (colon == std::string::npos) return false;
  const std::string host = display.substr(0, colon);
  if (!host.empty() && host != "unix" && host != "localhost") return true;  // remote: cannot tell cheaply
  const std::string number = display.substr(colon + 1, display.find('.', colon) - colon - 1);
  if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) return false;
  const std::string path = "/tmp/.X11-unix/X" + number;
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  if (sock < 0) return false;
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, path.c_str(), sizeof(addr.sun_path) - 1);
  const bool ok = ::connect(sock, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
  ::close(sock);
  return ok;
}

DisplayStatus ensure_x_display() {
  static std::mutex m;
  const std::lock_guard<std::mutex> lock(m);
  if (!own_xvfb().display.empty()) return {true, own_xvfb().display, true, "using Xvfb on " + own_xvfb().display};
  const char* env = std::getenv("DISPLAY");
  if (env && x_display_answers(env)) return {true, env, false, std::string("using DISPLAY ") + env};
  DisplayStatus s = start_xvfb();
  if (s.available) ::setenv("DISPLAY", s.display.c_str(), 1);
  return s;
}

}  // namespace cg::io
