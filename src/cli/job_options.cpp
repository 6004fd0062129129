#include "src/cli/console_progress.hpp"
#include "src/cli/commands.hpp"
#include "src/config/builtin_example.hpp"

namespace cg::cli {

bool JobOptions::show_progress() const { return !quiet && ConsoleProgress::stdout_is_terminal(); }

void add_job_options(CLI::App* command, JobOptions& o) {
  command->add_option("config", o.config,
                      "Config file (JSON, see data/schema/coolinggen.schema.json); without it the built-in example "
                      "(coolinggen example) is used");
  command->add_option("-o,--output", o.output, "Output directory (created if missing)")->required();
  command->add_flag("-q,--quiet", o.quiet, "Print nothing on success (stage progress is shown only on a terminal)");
  command->add_option("--timeout", o.timeout_s,
                      "Stop cleanly after SECONDS (wall clock) at the next check point, naming the stage; exit 6")
      ->check(CLI::PositiveNumber)
      ->type_name("SECONDS");
}

config::Config load_config_argument(const std::string& path) {
  return path.empty() ? config::builtin_example_config() : config::load_config_file(path);
}

}  // namespace cg::cli
