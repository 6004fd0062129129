// coolinggen sweep STUDY -o DIR [--jobs N] [--timeout S] [--only ID] [--emit slurm] [--stage-cache off|disk] [-q]
// coolinggen sweep --collect DIR
// A design study (src/study/sweep.hpp): every variant of STUDY built by a `coolinggen build` process of
// this binary into DIR/variants/<id>/, DIR/results.csv and DIR/study_report.md. Exit 0 when every
// variant has a status (built, refused, failed or timeout: see results.csv), 2 for an invalid study,
// 6 when stopped by Ctrl-C (finished variants kept; a rerun continues).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <map>

#include "src/cli/commands.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/cli/watchdog.hpp"
#include "src/core/parallel.hpp"
#include "src/core/process_pool.hpp"
#include "src/study/sweep.hpp"

namespace cg::cli {
namespace {

// SIGTERM (e.g. Slurm's scancel, a shutdown) stops the study as Ctrl-C does: the variants' builds are
// asked to stop and finished ones stay.
std::atomic<bool> g_terminated{false};
extern "C" void on_sigterm(int) { g_terminated = true; }

void install_terminate_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_sigterm;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGTERM, &sa, nullptr);
}

struct SweepArguments {
  std::string study, output, only, emit, collect;
  std::string stage_cache = "disk";
  int jobs = 0;  // 0: the core count
  double timeout_s = 0;
  bool quiet = false;
};

std::string counts_text(const study::StudyListing& l) {
  std::string s;
  for (const auto& [status, n] : study::status_counts(l)) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + study::status_name(status);
  return s;
}

int run_sweep_command(const SweepArguments& a) {
  if (!a.collect.empty()) {
    if (!a.study.empty() || !a.output.empty()) return error_exit(kUsage, "--collect DIR takes no STUDY and no -o (see coolinggen sweep --help)");
    const study::StudyListing l = study::collect_study(a.collect);
    if (!a.quiet) std::printf("%s: %zu variants (%s); wrote %s/results.csv, %s/study_report.md\n", l.name.c_str(), l.rows.size(),
                              counts_text(l).c_str(), a.collect.c_str(), a.collect.c_str());
    return kOk;
  }
  if (a.study.empty() || a.output.empty()) return error_exit(kUsage, "sweep needs STUDY and -o DIR, or --collect DIR (see coolinggen sweep --help)");
  study::SweepOptions o;
  o.study_file = a.study;
  o.output = a.output;
  o.executable = study::current_executable();
  o.jobs = a.jobs > 0 ? a.jobs : parallel_workers();
  o.threads = study::variant_threads(parallel_workers(), o.jobs);
  o.timeout_s = a.timeout_s;
  // The build stops itself at the time limit (exit 6), its watchdog within the grace; beyond that the
  // process is killed.
  o.kill_after_s = a.timeout_s > 0 ? a.timeout_s + watchdog_grace(a.timeout_s) + 5 : 0;
  o.only = a.only;
  o.emit = a.emit == "slurm" ? study::Emit::kSlurm : study::Emit::kNone;
  o.stage_cache = pipeline::parse_stage_cache_mode(a.stage_cache, "--stage-cache");
  ConsoleProgress interrupt(false);  // reads the Ctrl-C flag (install_interrupt_handler in main)
  install_terminate_handler();
  o.stop_requested = [&interrupt] { return interrupt.stop_requested() || g_terminated; };
  const bool terminal = !a.quiet && ConsoleProgress::stdout_is_terminal();
  std::size_t width = 0;
  if (terminal)
    o.progress = [&width](const std::string& line) {
      std::printf("\r%s%*s", line.c_str(), static_cast<int>(width > line.size() ? width - line.size() : 0), "");
      std::fflush(stdout);
      width = line.size();
    };
  const study::SweepOutcome r = study::run_sweep(o);
  if (terminal && width > 0) std::printf("\n");
  if (o.emit == study::Emit::kSlurm) {
    if (!a.quiet)
      std::printf("wrote %s (%zu array tasks, %s); then: coolinggen sweep --collect %s\n", r.sbatch.string().c_str(),
                  r.listing.rows.size(), counts_text(r.listing).c_str(), a.output.c_str());
    return kOk;
  }
  if (r.interrupted)
    throw Stopped(std::string(g_terminated ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)") + ": " + counts_text(r.listing) + "; finished variants kept in " + a.output +
                  "/variants, results.csv lists the rest as pending; rerun the same command to continue");
  if (!a.quiet)
    std::printf("%s: %zu variants (%s); %d run now, %d up to date; %.1f s; wrote %s/results.csv\n", r.listing.name.c_str(),
                r.listing.rows.size(), counts_text(r.listing).c_str(), r.ran, r.skipped, r.wall_s, a.output.c_str());
  return kOk;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto a = std::make_shared<SweepArguments>();
  CLI::App* cmd = app.add_subcommand("sweep", "Design study: build every variant of STUDY (docs/studies.md) into DIR, results in DIR/results.csv");
  cmd->add_option("study", a->study, "Study file (JSON, see data/schema/study.schema.json)");
  cmd->add_option("-o,--output", a->output, "Study directory (created if missing; a rerun resumes)");
  cmd->add_option("-j,--jobs", a->jobs, "Variants built at a time (default: the CPUs; each build computes on --threads / N of them); with --emit slurm the array's %K")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--timeout", a->timeout_s, "Time limit of each variant's build, SECONDS (its status is then timeout)")
      ->check(CLI::PositiveNumber)
      ->type_name("SECONDS");
  cmd->add_option("--only", a->only, "Build only this variant (index or id; a Slurm array task); results.csv is left to --collect");
  cmd->add_option("--emit", a->emit, "Write a job script instead of running: slurm (DIR/study.sbatch)")->check(CLI::IsMember({"slurm"}));
  cmd->add_option("--stage-cache", a->stage_cache,
                  "disk (default): variants that differ only after the cooling stage share it through DIR/cache; off: "
                  "every variant builds every stage")
      ->check(CLI::IsMember({"off", "disk"}));
  cmd->add_option("--collect", a->collect, "Merge the variants' reports in DIR into DIR/results.csv and DIR/study_report.md")
      ->type_name("DIR");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success (the progress line is shown only on a terminal)");
  return {cmd, [a] { return run_sweep_command(*a); }};
}

}  // namespace cg::cli
