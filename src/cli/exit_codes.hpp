#pragma once
// Exit codes of coolinggen and the mapping of errors to them. Every error is one line on stderr:
// "coolinggen: error: <message>".
#include <functional>
#include <string>

#include "src/core/error.hpp"

namespace cg::cli {

enum ExitCode {
  kOk = 0,
  kUsage = 1,           ///< command line
  kBadConfig = 2,       ///< invalid configuration (config::ConfigError, names the field)
  kModelFailure = 3,    ///< CoolingGen failed: the model or solid could not be made, or a check failed
  kOutputFailure = 4,   ///< an output file could not be written
  kUnexpected = 5,      ///< anything else (a bug)
  kStopped = 6,         ///< --timeout reached or Ctrl-C: stopped cleanly at a check point
};

/// How the one line of exit 3 starts: a boolean, a check or a model step the tool could not complete is
/// CoolingGen's failure, never blamed on a field (an input out of range is a ConfigError, exit 2).
inline constexpr const char* kToolFailure = "CoolingGen failure (not an input error; please report it): ";

/// A command's checks failed after report.json was written (exit 3).
class ChecksFailed : public Error {
 public:
  using Error::Error;
};

/// A command stopped on request (exit 6); the message says why, where and what is on disk.
class Stopped : public Error {
 public:
  using Error::Error;
};

/// Prints "coolinggen: error: <message>" (one line) to stderr and returns `code`.
int error_exit(int code, std::string message);

/// Runs `command` and maps its exceptions to exit codes and one-line messages.
int run_command(const std::function<int()>& command);

}  // namespace cg::cli
