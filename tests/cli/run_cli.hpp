#pragma once
// Runs the built coolinggen binary as a process (shared by the CLI process tests).
#include <boost/test/unit_test.hpp>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "brep/temp_files.hpp"

namespace cg::test {

inline const std::filesystem::path kCliBinary = std::filesystem::path(COOLINGGEN_BINARY_DIR) / "coolinggen";

struct Run {
  int exit_code;
  std::string out, err;
  double seconds;  // wall clock
};

/// Runs `coolinggen args` through the shell, capturing stdout and stderr in files of `dir`. With
/// `terminal`, stdout is a pseudo-terminal (util-linux script(1), Debian essential), copied to the file.
inline Run run_cli(const std::string& args, const std::filesystem::path& dir, bool terminal = false) {
  BOOST_TEST_REQUIRE(std::filesystem::exists(kCliBinary), "build the coolinggen target first: " << kCliBinary);
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string call = "'" + kCliBinary.string() + "' " + args;
  const std::string cmd = (terminal ? "script -qec \"" + call + " 2> '" + err.string() + "'\" /dev/null" : call + " 2> '" + err.string() + "'") +
                          " > '" + out.string() + "'";
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err), seconds};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// Quotes a path for the shell.
inline std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

}  // namespace cg::test
