// coolinggen grid [CONFIG] -o DIR [-q] [--timeout S]: wall-orthogonal structured grids around the blade
// sections (src/pipeline/grid_job.hpp), printed.
#include <cstdio>

#include "src/cli/commands.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/cli/output_jobs.hpp"
#include "src/pipeline/grid_job.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::cli {
namespace {

void print_summary(const config::Config& c, const pipeline::GridResult& r, const pipeline::WrittenGrid& w) {
  std::printf("%s: %zu section grid%s\n", c.name.c_str(), r.runs.size(), r.runs.size() == 1 ? "" : "s");
  for (const pipeline::SectionGridRun& run : r.runs) {
    const grid::SectionGridReport& g = run.grid.report;
    std::printf("  sections[%d] (span %.3f): %s, %d cells (", run.section, run.span,
                run.grid.grid.blocks.size() > 1 ? "cascade" : "O-grid", g.cells);
    for (std::size_t k = 0; k < run.grid.grid.blocks.size(); ++k) {
      const grid::Block& b = run.grid.grid.blocks[k];
      std::printf("%s%s %dx%d", k ? ", " : "", b.name.c_str(), b.ni, b.nj);
    }
    std::printf("), inverted %d, min scaled Jacobian %.3f, wall angle deviation %.1e deg, first cell %.4g mm, %.3f s\n",
                g.inverted_cells, g.min_scaled_jacobian, g.wall.max_angle_deviation_deg, g.wall.min_first_cell_height,
                run.seconds);
  }
  std::printf("  wrote %zu files in %s (index %s)\n", w.files.size(), w.directory.string().c_str(), pipeline::kGridReportFile);
}

int run_grid(const JobOptions& o) {
  ConsoleProgress console(o.show_progress());
  pipeline::TimeLimit limit(&console, o.timeout_s);
  bool writing = false;
  try {
    find_output_jobs();  // a missing module fails now, not after the grids
    const config::Config c = load_config_argument(o.config);
    const pipeline::GridResult r = pipeline::run_grid(c, &limit);
    const OutputJobs& jobs = output_jobs();  // loads the writers' libraries (output_jobs.hpp)
    writing = true;
    const pipeline::WrittenGrid w = jobs.write_grid_outputs(c, r, o.output, &limit);
    console.interrupt_line();
    if (!o.quiet) print_summary(c, r, w);
    return kOk;
  } catch (const Cancelled& e) {
    console.interrupt_line();
    throw Stopped(limit.stop_reason() + ": " + e.what() + "; " +
                  (writing ? "the grid files of this run were removed" : "nothing written, " + o.output.string() + " left as it was"));
  } catch (...) {
    console.interrupt_line();
    throw;
  }
}

}  // namespace

Command add_grid_command(CLI::App& app) {
  auto o = std::make_shared<JobOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grid", "Structured wall-orthogonal grids around the blade sections (config \"grid\"; default: an O-grid around "
              "every section); write DIR/section_<k>.{vtm,vts,xyz,cgns} and DIR/grid_report.json");
  add_job_options(cmd, *o);
  return {cmd, [o] { return run_grid(*o); }};
}

}  // namespace cg::cli
