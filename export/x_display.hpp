#pragma once
// An X display for VTK's off-screen rendering. Debian's VTK 9.1 renders through GLX only (no OSMesa,
// no EGL) and aborts the process when it cannot reach an X server, so a renderer must make sure one is
// reachable first: the DISPLAY of the session when it answers, otherwise a private Xvfb started here
// (`Xvfb -displayfd`, so the server picks a free display number and tells it when it is ready),
// stopped when the process exits.
#include <string>

namespace cg::io {

struct DisplayStatus {
  bool available = false;
  std::string display;  ///< e.g. ":0" or the Xvfb display ":12"
  bool started_xvfb = false;
  std::string message;  ///< why no display is available (what to install or set), or what was used
};

/// Returns a usable display, starting Xvfb at most once per process (later calls reuse it; DISPLAY is
/// set for this process). Never throws and never aborts.
DisplayStatus ensure_x_display();

/// True when an X server answers on `display` (":N" or ":N.S": its unix socket accepts a connection;
/// a remote "host:N" display is assumed to answer).
bool x_display_answers(const std::string& display);

}  // namespace cg::io
