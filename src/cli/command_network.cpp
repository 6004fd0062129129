// coolinggen network [CONFIG] -o DIR [-q] [--timeout S] [--stage-cache DIR]: the build, then only the
// flow network's files (network.json, network.inp, network_results.json, film_holes.csv), report.json
// and report.md. The config needs a "coolant" section (the built-in example has one).
#include "src/cli/commands.hpp"
#include "src/config/json_fields.hpp"

namespace cg::cli {

Command add_network_command(CLI::App& app) {
  auto o = std::make_shared<JobOptions>();
  CLI::App* cmd = app.add_subcommand(
      "network", "Build the blade, then solve its coolant flow network with CalculiX (ccx); write DIR/network.json, "
                 "network.inp, network_results.json, film_holes.csv and report.json (docs/network.md)");
  add_job_options(cmd, *o);
  auto cache_dir = std::make_shared<std::string>();
  cmd->add_option("--stage-cache", *cache_dir, "Take the cooling stage from DIR, as for build (docs/studies.md)")->type_name("DIR");
  return {cmd, [o, cache_dir] {
            return run_build_job(*o, *cache_dir, [](config::Config& c) {
              if (!c.coolant) config::fail("coolant", "required by coolinggen network (supply, sinks: docs/configuration.md)");
              c.output.formats = {config::OutputFormat::Network, config::OutputFormat::ReportMd};
            });
          }};
}

}  // namespace cg::cli
