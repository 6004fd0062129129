#include "src/pipeline/grid_job.hpp"

#include <chrono>

#include "src/pipeline/stage_runner.hpp"

namespace cg::pipeline {

GridResult run_grid(const config::Config& c, ProgressSink* progress) {
  GridResult out;
  StageRunner stages(progress, out.timings);
  stages.run("blade_model", "blade model", [&] { out.model = validate(c).model; });
  for (int k : config::grid_sections(c.grid, config::section_count(c))) {
    SectionGridRun run;
    run.section = k;
    run.span = out.model.section_spans.at(static_cast<std::size_t>(k));
    run.name = "section_" + std::to_string(k);
    stages.run(run.name, "grid around sections[" + std::to_string(k) + "]", [&] {
      const auto t0 = std::chrono::steady_clock::now();
      try {
        run.grid = grid::build_section_grid(out.model.profiles.at(static_cast<std::size_t>(k)), c.grid.options);
      } catch (const AlgorithmFailure& e) {
        throw AlgorithmFailure("sections[" + std::to_string(k) + "]: " + e.what());
      } catch (const InvalidGeometry& e) {
        throw config::ConfigError("grid." + std::string(e.what()) + " (sections[" + std::to_string(k) + "])");
      }
      run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    });
    out.runs.push_back(std::move(run));
  }
  return out;
}

}  // namespace cg::pipeline
