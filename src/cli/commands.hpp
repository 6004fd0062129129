#pragma once
// The subcommands of coolinggen. Each add_*_command registers its subcommand and options on `app` and
// returns the function that runs it (after parsing); main.cpp dispatches and maps errors to exit codes
// (exit_codes.hpp). A new subcommand (mesh, grid) is one more file with an add_*_command, listed in
// main.cpp, built on the pipeline (src/pipeline) and the shared job options below.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "src/config/config.hpp"

namespace cg::cli {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_build_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_example_command(CLI::App& app);
Command add_mesh_command(CLI::App& app);
Command add_grid_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_network_command(CLI::App& app);

/// Options shared by the commands that run a job: CONFIG, -o DIR, -q, --timeout.
struct JobOptions {
  std::string config;                   ///< empty: the built-in example
  std::filesystem::path output;
  bool quiet = false;
  double timeout_s = 0;                 ///< 0: none
  /// Stage progress is shown when stdout is a terminal and not quiet.
  bool show_progress() const;
};
void add_job_options(CLI::App* command, JobOptions& options);

/// `coolinggen build`'s job (run_build + write_outputs, printed); `adjust` (optional) changes the loaded
/// config first (e.g. `coolinggen network` selects its output formats). Returns the exit code.
int run_build_job(const JobOptions& options, const std::string& stage_cache_dir,
                  const std::function<void(config::Config&)>& adjust);

/// The config named on the command line (empty: the built-in example). Throws ConfigError.
config::Config load_config_argument(const std::string& path);

}  // namespace cg::cli
