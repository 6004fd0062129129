// write_grid_outputs (grid_job.hpp): the grid files (CGNS, Plot3D, VTK) and grid_report.json, apart from
// run_grid so that computing the grids needs none of the writers' libraries (src/cli/output_jobs.hpp).
#include <fstream>

#include "export/atomic_file.hpp"
#include "export/grid_cgns.hpp"
#include "export/grid_plot3d.hpp"
#include "export/grid_vtk.hpp"
#include "export/version.hpp"
#include "src/core/parallel.hpp"
#include "src/pipeline/grid_job.hpp"
#include "src/pipeline/output_directory.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;

nlohmann::ordered_json section_grid_json(const SectionGridRun& run) {
  const grid::SectionGridReport& r = run.grid.report;
  const grid::MultiBlockGrid& g = run.grid.grid;
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.blocks.size(); ++k)
    blocks.push_back({{"name", g.blocks[k].name},
                      {"cells", {g.blocks[k].ni, g.blocks[k].nj}},
                      {"cell_count", g.blocks[k].cells()},
                      {"inverted_cells", r.blocks[k].inverted_cells},
                      {"min_scaled_jacobian", r.blocks[k].min_scaled_jacobian},
                      {"max_neighbour_cell_ratio", r.blocks[k].max_cell_ratio}});
  nlohmann::ordered_json bcs = nlohmann::ordered_json::array();
  for (const auto& bc : g.boundaries)
    bcs.push_back({{"name", bc.name}, {"type", grid::boundary_kind_name(bc.kind)},
                   {"block", g.blocks[static_cast<std::size_t>(bc.block)].name}});
  nlohmann::ordered_json conns = nlohmann::ordered_json::array();
  for (const auto& c : g.connections)
    conns.push_back({{"name", c.name},
                     {"block", g.blocks[static_cast<std::size_t>(c.block)].name},
                     {"donor", g.blocks[static_cast<std::size_t>(c.donor)].name},
                     {"periodic", c.periodic},
                     {"translation_mm", {c.translation.x(), c.translation.y()}}});
  return {{"section", run.section},
          {"span", run.span},
          {"layout", g.blocks.size() > 1 ? "cascade" : "o_grid"},
          {"cells", r.cells},
          {"inverted_cells", r.inverted_cells},
          {"valid", r.inverted_cells == 0},
          {"min_scaled_jacobian", r.min_scaled_jacobian},
          {"blocks", blocks},
          {"boundaries", bcs},
          {"connections", conns},
          {"max_connection_mismatch_mm", r.max_connection_mismatch},
          {"wall",
           {{"nodes", r.wall.wall_nodes},
            {"max_angle_deviation_deg", r.wall.max_angle_deviation_deg},
            {"patch_max_angle_deviation_deg", r.patch_wall_angle_deviation_deg},
            {"first_cell_height_mm",
             {{"configured", r.first_cell_height}, {"min", r.wall.min_first_cell_height}, {"max", r.wall.max_first_cell_height}}},
            {"growth_ratio", r.growth_ratio},
            {"orthogonal_layers", r.wall_layers},
            {"orthogonal_thickness_mm", r.thickness}}},
          {"patches", {{"count", r.wall_patches}, {"max_degree", r.wall_patch_degree}, {"thickness_fit_error", r.thickness_fit_error}}},
          {"build_s", run.seconds}};
}

WrittenGrid write_grid_outputs(const config::Config& c, const GridResult& r, const fs::path& dir, ProgressSink* progress) {
  std::vector<StageTiming> timings;
  StageRunner stages(progress, timings);
  if (progress && progress->stop_requested()) throw Cancelled("writing grids", "before");
  OutputDirectory od(dir, kGridReportFile, {kGridReportFile});
  std::vector<std::vector<std::string>> files_per_run;
  for (const SectionGridRun& run : r.runs) {
    stages.run("write_" + run.name, "write the grid files of " + run.name, [&] {
      const std::size_t first = od.files().size();
      std::vector<std::pair<std::string, std::string>> vts;
      for (std::size_t k = 0; k < run.grid.grid.blocks.size(); ++k) {
        const grid::Block& b = run.grid.grid.blocks[k];
        const std::string name = io::vts_file_name(run.name, b);
        od.write(name, [&](const fs::path& t) { io::write_vts(t, b, static_cast<int>(k)); });
        vts.emplace_back(b.name, name);
      }
      od.write(run.name + ".vtm", [&](const fs::path& t) { io::write_vtm_index(t, vts); });
      od.write(run.name + ".xyz", [&](const fs::path& t) { io::write_plot3d(t, run.grid.grid); });
      od.write(run.name + ".cgns", [&](const fs::path& t) { io::write_cgns(t, run.grid.grid, run.name); });
      files_per_run.emplace_back(od.files().begin() + static_cast<std::ptrdiff_t>(first), od.files().end());
    });
  }
  od.commit([&](const fs::path& target, const std::vector<std::string>& files) {
    // "generator" and "outputs" as in report.json: the next run in this directory removes these files.
    nlohmann::ordered_json rep = {{"generator", "coolinggen"},
                                  {"command", "grid"},
                                  {"version", io::tool_version()},
                                  {"valid", true},
                                  {"units", {{"length", "mm"}, {"angle", "deg"}}},
                                  {"model", {{"name", c.name}, {"source", c.source_file.empty() ? "<document>" : c.source_file}}},
                                  {"frame", "each section's own frame (a, b), mm: a axial, b across the passage"}};
    rep["sections"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < r.runs.size(); ++k) {
      nlohmann::ordered_json s = section_grid_json(r.runs[k]);
      s["files"] = files_per_run[k];
      rep["sections"].push_back(s);
    }
    nlohmann::ordered_json t = nlohmann::ordered_json::object();
    for (const std::vector<StageTiming>* list : {&r.timings, static_cast<const std::vector<StageTiming>*>(&timings)})
      for (const StageTiming& x : *list) t[x.stage] = x.seconds;
    rep["timings_s"] = t;
    rep["threads"] = parallel_workers();
    rep["outputs"] = files;
    io::write_atomically(target, [&](const fs::path& tmp) {
      std::ofstream out(tmp);
      out << rep.dump(2) << "\n";
      if (!out) throw io::ExportError("write error on " + tmp.string());
    });
  });
  return {dir, od.files()};
}

}  // namespace cg::pipeline
