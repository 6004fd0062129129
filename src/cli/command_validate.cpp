// coolinggen validate CONFIG: parse the config, build the blade model and plan the cooling features
// (pipeline::validate: every placement and check that needs no solid); write nothing, and say what only a
// build checks.
// coolinggen example: print the built-in example config.
#include <cstdio>

#include "src/cli/commands.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/config/builtin_example.hpp"
#include "src/pipeline/build.hpp"

namespace cg::cli {

Command add_validate_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("validate", "Parse and check a config (blade model, feature placements and sizes); writes nothing");
  cmd->add_option("config", *path, "Config file (JSON)")->required();
  return {cmd, [path] {
            const config::Config c = load_config_argument(*path);
            const pipeline::Validation v = pipeline::validate(c);
            std::printf("%s: valid (%s flow path, %zu sections)\n", path->c_str(),
                        v.model.trim.straight ? "straight" : "meridional", config::section_count(c));
            for (const std::string& note : v.notes) std::printf("planned: %s\n", note.c_str());
            if (!c.cooling.empty())
              std::printf("planned and checked: the core's walls, chambers, turnaround ends and inlets (their rims within the walls), "
                          "turbulators, trailing-edge slots and pin fins, every film and showerhead hole (wall crossing, chamber, "
                          "ligaments to other holes, ribs and end walls), the inserts' input; not checked before a build: the "
                          "turbulator, pin and slot tools and their volumes, the inlets' rims against the ribs' fillets, film holes "
                          "against turbulators, pin fins and trailing-edge slots, the booleans and the solid checks\n");
            return int{kOk};
          }};
}

Command add_example_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("example", "Print the built-in example config (JSON) to stdout");
  return {cmd, [] {
            std::fputs(config::builtin_example_json(), stdout);
            return int{kOk};
          }};
}

}  // namespace cg::cli
