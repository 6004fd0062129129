#include "export/grid_job.hpp"

#include <chrono>
#include <fstream>

#include "export/atomic_file.hpp"
#include "export/grid_cgns.hpp"
#include "export/grid_plot3d.hpp"
#include "export/grid_vtk.hpp"

namespace cg::io {

std::vector<SectionGridRun> build_section_grids(const blade::BladeModel& model, const std::vector<int>& sections,
                                                const grid::SectionGridOptions& options) {
  std::vector<SectionGridRun> runs;
  for (int k : sections) {
    if (k < 0 || k >= static_cast<int>(model.profiles.size()))
      throw InvalidGeometry("grid.sections: index " + std::to_string(k) + " is outside [0, " +
                            std::to_string(model.profiles.size() - 1) + "]");
    SectionGridRun run;
    run.section = k;
    run.span = model.section_spans.at(static_cast<std::size_t>(k));
    run.name = "section_" + std::to_string(k);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      run.grid = grid::build_section_grid(model.profiles[static_cast<std::size_t>(k)], options);
    } catch (const AlgorithmFailure& e) {
      throw AlgorithmFailure("sections[" + std::to_string(k) + "]: " + e.what());
    } catch (const InvalidGeometry& e) {
      throw InvalidGeometry("grid." + std::string(e.what()) + " (sections[" + std::to_string(k) + "])");
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    runs.push_back(std::move(run));
  }
  return runs;
}

nlohmann::ordered_json section_grid_json(const SectionGridRun& run) {
  const grid::SectionGridReport& r = run.grid.report;
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.blocks.size(); ++k) {
    const grid::Block& b = run.grid.grid.blocks[k];
    blocks.push_back({{"name", b.name},
                      {"cells", {b.ni, b.nj}},
                      {"cell_count", b.cells()},
                      {"inverted_cells", r.blocks[k].inverted_cells},
                      {"min_scaled_jacobian", r.blocks[k].min_scaled_jacobian},
                      {"max_neighbour_cell_ratio", r.blocks[k].max_cell_ratio}});
  }
  nlohmann::ordered_json bcs = nlohmann::ordered_json::array();
  for (const auto& bc : run.grid.grid.boundaries)
    bcs.push_back({{"name", bc.name}, {"type", grid::boundary_kind_name(bc.kind)}, {"block", run.grid.grid.blocks[static_cast<std::size_t>(bc.block)].name}});
  nlohmann::ordered_json conns = nlohmann::ordered_json::array();
  for (const auto& c : run.grid.grid.connections)
    conns.push_back({{"name", c.name}, {"periodic", c.periodic}, {"translation_mm", {c.translation.x(), c.translation.y()}}});
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const auto& f : run.files) files.push_back(f.filename().string());
  nlohmann::ordered_json j = {
      {"section", run.section},
      {"span", run.span},
      {"layout", r.blocks.size() > 1 ? "cascade" : "o_grid"},
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
        {"first_cell_height_mm", {{"configured", r.first_cell_height}, {"min", r.wall.min_first_cell_height}, {"max", r.wall.max_first_cell_height}}},
        {"growth_ratio", r.growth_ratio},
        {"orthogonal_layers", r.wall_layers},
        {"orthogonal_thickness_mm", r.thickness}}},
      {"patches", {{"count", r.wall_patches}, {"max_degree", r.wall_patch_degree}, {"thickness_fit_error", r.thickness_fit_error}}},
      {"build_s", run.seconds},
      {"files", files}};
  return j;
}

void write_section_grids(const std::filesystem::path& dir, std::vector<SectionGridRun>& runs, const nlohmann::json& meta) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw ExportError("cannot create output directory " + dir.string() + ": " + ec.message());
  nlohmann::ordered_json report = {{"generator", "coolinggen grid"}, {"units", {{"length", "mm"}, {"angle", "deg"}}}};
  report["model"] = meta;
  report["sections"] = nlohmann::ordered_json::array();
  for (SectionGridRun& run : runs) {
    run.files = write_vtm(dir / (run.name + ".vtm"), run.grid.grid);
    write_plot3d(dir / (run.name + ".xyz"), run.grid.grid);
    run.files.push_back(dir / (run.name + ".xyz"));
    write_cgns(dir / (run.name + ".cgns"), run.grid.grid, run.name);
    run.files.push_back(dir / (run.name + ".cgns"));
    report["sections"].push_back(section_grid_json(run));
  }
  write_atomically(dir / "grid_report.json", [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp);
    out << report.dump(2) << "\n";
    if (!out) throw ExportError("write error on " + tmp.string());
  });
}

}  // namespace cg::io
