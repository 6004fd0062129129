#include "src/cli/handoff_commands.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include "export/atomic_file.hpp"
#include "export/outputs.hpp"
#include "export/report_markdown.hpp"
#include "src/brep/verify.hpp"
#include "src/config/builtin_example.hpp"
#include "src/mesh/blade_mesher.hpp"

namespace fs = std::filesystem;

namespace cg::cli {

nlohmann::json write_build_outputs(const fs::path& dir, const config::Config& c, const blade::BladeModel& model,
                                   const brep::BladeSolid& solid) {
  io::HandoffOptions o;
  o.formats = c.output.handoff.formats;
  o.formats.erase(io::OutputFormat::ReportMarkdown);  // written with report.json
  o.product_name = c.output.product_name.empty() ? c.name : c.output.product_name;
  o.step_schema = c.output.step_schema;
  o.stl_deflection = c.output.handoff.stl_deflection;
  o.stl_angular_deflection_deg = c.output.handoff.stl_angular_deflection_deg;
  o.section_spans = c.output.handoff.section_spans;
  const brep::Part part{{"blade", brep::NamedShape{solid.solid, solid.faces}}};
  return io::write_handoff(dir, part, &model, o).summary;
}

std::vector<fs::path> write_reports(const fs::path& dir, const io::ReportContent& content, const nlohmann::json& extra,
                                    bool markdown) {
  nlohmann::json j = io::report_json(content);
  for (const auto& [k, v] : extra.items()) j[k] = v;
  const fs::path json_file = dir / "report.json", md_file = dir / "report.md";
  const std::string text = j.dump(2) + "\n";
  io::write_atomically(json_file, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw io::ExportError("cannot write " + tmp.string());
  });
  if (!markdown) return {json_file};
  io::write_report_markdown(md_file, j);
  return {json_file, md_file};
}

int run_mesh(const std::string& path, const fs::path& out_dir, bool quiet) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const config::Config c = path.empty() ? config::builtin_example_config() : config::load_config_file(path);
  const blade::BladeModel model = config::build_model(c);
  const brep::BladeSolid solid = brep::build_blade_solid(model);
  io::ReportContent report;
  report.check = brep::verify_solid(solid.solid);
  for (const auto& f : solid.faces) ++report.face_names[f.name];
  report.warnings = solid.warnings;
  report.model = config::model_summary(c, model);
  report.model["source"] = path.empty() ? "<built-in example>" : path;
  if (!report.check.all_passed())
    throw AlgorithmFailure("solid checks failed (" + report.check.failed_names() + "): nothing to mesh");

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw io::ExportError("cannot create output directory " + out_dir.string() + ": " + ec.message());
  // Progress on a terminal only: a log file gets the summary lines, not carriage-return updates.
  const bool tty = !quiet && ::isatty(STDERR_FILENO);
  const mesh::ProgressFn progress = [&](const std::string& stage, double) {
    if (!tty) return;
    std::fprintf(stderr, "\r  mesh: %-45s %6.1f s", stage.c_str(), std::chrono::duration<double>(Clock::now() - t0).count());
    std::fflush(stderr);
  };
  // The blade as built today: cooling features, once they exist, come in as the cooled part with this
  // solid as the uncooled one, and their cavities become the coolant domain.
  const brep::Part part{{"blade", brep::NamedShape{solid.solid, solid.faces}}};
  const mesh::MeshResult m = mesh::mesh_blade(part, solid.solid, solid.faces, out_dir, c.mesh, progress);
  if (tty) std::fprintf(stderr, "\n");
  report.timings_s = {{"total", std::chrono::duration<double>(Clock::now() - t0).count()}};
  const auto reports = write_reports(out_dir, report, {{"mesh", m.to_json()}},
                                     c.output.handoff.formats.count(io::OutputFormat::ReportMarkdown) > 0);
  if (!quiet) {
    std::printf("%s: %zu nodes, %zu tetrahedra (%zu inverted), %zu boundary triangles, min quality %.3f\n", c.name.c_str(),
                m.nodes, m.tetrahedra, m.inverted, m.triangles, m.min_quality);
    for (const auto& r : m.regions)
      std::printf("  %-10s %s %zu tetrahedra, volume %.4f mm^3 (B-rep %.4f)\n", r.name.c_str(), r.fluid ? "fluid" : "solid",
                  r.tets.elements, r.tets.volume, r.brep_volume);
    std::printf("  time: geometry %.2f s, surface %.2f s, volume %.2f s, total %.2f s\n", m.seconds_geometry,
                m.seconds_surface, m.seconds_volume, m.seconds_total);
    for (const auto& n : m.notes) std::printf("  note: %s\n", n.c_str());
    std::printf("  wrote");
    for (const auto& f : m.files) std::printf(" %s", f.string().c_str());
    for (const auto& f : reports) std::printf(" %s", f.string().c_str());
    std::printf("\n");
  }
  if (m.inverted > 0) throw AlgorithmFailure(std::to_string(m.inverted) + " inverted tetrahedra in the mesh");
  return 0;
}

}  // namespace cg::cli
