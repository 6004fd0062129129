// coolinggen: command-line front end, a thin layer over the pipeline (src/pipeline): argument parsing,
// printing and exit codes.
//   coolinggen build [CONFIG] -o DIR [-q] [--timeout S]   DIR/blade.step + DIR/report.json
//   coolinggen mesh [CONFIG] -o DIR [-q] [--timeout S]    DIR/mesh.msh, mesh_*.vtu, report.json, report.md
//   coolinggen validate CONFIG                             parse and check the config, write nothing
//   coolinggen example                                     print the built-in example config
//   coolinggen grid [CONFIG] -o DIR [-q] [--timeout S]     structured grids around the sections (grid_job.hpp)
//   coolinggen sweep STUDY -o DIR [--jobs N] [--timeout S]  a design study (src/study/sweep.hpp)
// Every command but example takes --threads N (src/cli/threads.hpp).
// Exit codes (exit_codes.hpp): 0 success, 1 command line, 2 invalid config, 3 model/solid failure or a
// failed check, 4 output error, 5 unexpected error, 6 stopped (--timeout, Ctrl-C). Errors are one line
// on stderr.
#include <CLI/CLI.hpp>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <malloc.h>

#include <string>
#include <vector>

#include "src/cli/commands.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/cli/suggest.hpp"
#include "src/cli/threads.hpp"
#include "export/version.hpp"

using namespace cg;
using namespace cg::cli;

namespace {

// OCCT's data exchange prints transfer statistics through the default messenger; keep stdout ours.
void silence_occt() {
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
}

// glibc's malloc gives the heap's free top back to the system past 128 KiB and serves large blocks by
// fresh mappings above a threshold it adjusts as it goes: the plan's fits and sections allocate and free
// such blocks thousands of times and fault their pages in again each time. Keeping them (trim past
// 256 MiB, blocks up to 64 MiB from the heap) made `validate` on the random designs bench's 12 slowest
// refusals 6-9 % faster (min of 5, 2026-12-07); builds the same to 1 %, peak memory within 2 %.
void keep_freed_memory() {
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
}

// The first argument when it is neither an option nor a subcommand: "unknown command 'biuld' (did you
// mean build?)", instead of CLI11's "A subcommand is required".
std::string unknown_command(int argc, char** argv, const std::vector<Command>& commands) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string word = argv[1];
  std::vector<std::string> names;
  for (const Command& c : commands) {
    if (c.app->get_name() == word) return "";
    names.push_back(c.app->get_name());
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  const std::string guess = closest_name(word, names);
  return "unknown command '" + word + "'" + (guess.empty() ? "" : " (did you mean " + guess + "?)") +
         "; commands: " + list + " (see coolinggen --help)";
}

}  // namespace

int main(int argc, char** argv) {
  keep_freed_memory();
  install_interrupt_handler();
  CLI::App app{"coolinggen: verified CAD models of cooled turbine blades (units mm, degrees)", "coolinggen"};
  app.set_version_flag("--version", std::string("coolinggen ") + io::tool_version());
  app.require_subcommand(1);
  const std::vector<Command> commands{add_build_command(app), add_mesh_command(app), add_validate_command(app),
                                      add_example_command(app), add_grid_command(app),
                                      add_sweep_command(app), add_network_command(app)};
  int threads = 0;
  for (const Command& c : commands)
    if (c.app->get_name() != "example") add_threads_option(c.app, threads);

  if (const std::string unknown = unknown_command(argc, argv, commands); !unknown.empty())
    return error_exit(kUsage, unknown);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return error_exit(kUsage, std::string(e.what()) + " (see coolinggen --help)");
  }

  try {
    apply_thread_budget(threads);
  } catch (const ThreadBudgetError& e) {
    return error_exit(kUsage, e.what());
  }
  silence_occt();
  for (const Command& c : commands)
    if (*c.app) return run_command(c.run);
  return error_exit(kUsage, "a command is required (see coolinggen --help)");
}
