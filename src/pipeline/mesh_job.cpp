#include "src/pipeline/mesh_job.hpp"

#include <algorithm>

#include "export/report.hpp"
#include "export/report_markdown.hpp"
#include "src/pipeline/output_directory.hpp"
#include "src/pipeline/outputs.hpp"
#include "src/pipeline/report.hpp"
#include "src/pipeline/stage_runner.hpp"
#include "src/core/parallel.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;

mesh::MeshOptions mesh_options(const config::MeshConfig& c) {
  mesh::MeshOptions m;
  m.max_size = c.max_size;
  m.min_size = c.min_size;
  m.curvature_elements = c.curvature_elements;
  m.feature_curvature_elements = c.feature_curvature_elements;
  m.size_growth = c.size_growth;
  m.metal = c.metal;
  m.coolant = c.coolant;
  m.write_msh = c.msh;
  m.write_vtu = c.vtu;
  m.write_cgns = c.cgns;
  m.groups = c.group_by_face_name ? mesh::GroupBy::FaceName : mesh::GroupBy::Kind;
  m.threads = std::min(c.threads, parallel_workers());  // at most the job's threads (--threads)
  m.optimize = c.optimize;
  return m;
}

MeshOutputs write_mesh(const config::Config& c, const BuildResult& r, const fs::path& dir, ProgressSink* progress) {
  MeshOutputs out;
  out.directory = dir;
  StageRunner stages(progress, out.timings);
  check_cancel(progress, "meshing");
  std::vector<std::string> owned{kReportFile, "report.md", "mesh.msh", "mesh.cgns", "mesh_surfaces.vtu", "mesh_coolant.vtu"};
  for (const brep::NamedBody& b : r.part) owned.push_back("mesh_" + b.name + ".vtu");
  OutputDirectory od(dir, kReportFile, owned);
  if (r.valid())
    stages.run("mesh", "mesh metal and coolant (gmsh)", [&] {
      out.mesh = mesh::mesh_blade(
          r.part, r.uncooled.shape, r.uncooled.faces,
          [&](const std::string& name, const std::function<void(const fs::path&)>& writer) { od.write(name, writer); },
          mesh_options(c.mesh), progress);
    });
  const bool markdown = config::has_format(c.output.formats, config::OutputFormat::ReportMd);
  stages.run("report", "write report.json", [&] {
    std::vector<StageTiming> timings = r.timings;
    timings.insert(timings.end(), out.timings.begin(), out.timings.end());
    auto content = [&](const std::vector<std::string>& files) {
      io::ReportContent rc = report_content(c, r, files, timings);
      if (r.valid()) rc.extra["mesh"] = out.mesh.to_json();
      return rc;
    };
    if (markdown) {
      std::vector<std::string> files = od.files();
      files.push_back("report.md");
      files.push_back(kReportFile);
      od.write("report.md", [&](const fs::path& t) { io::write_report_markdown(t, io::report_json(content(files))); });
    }
    od.commit([&](const fs::path& target, const std::vector<std::string>& files) { io::write_report(target, content(files)); });
  });
  out.files = od.files();
  return out;
}

}  // namespace cg::pipeline
