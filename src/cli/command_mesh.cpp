// coolinggen mesh [CONFIG] -o DIR [-q] [--timeout S]: the pipeline's run_build + write_mesh, printed.
#include <cstdio>

#include "src/cli/commands.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/exit_codes.hpp"
#include "src/cli/output_jobs.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/stage_runner.hpp"

namespace cg::cli {
namespace {

void print_summary(const config::Config& c, const pipeline::MeshOutputs& w) {
  const mesh::MeshResult& m = w.mesh;
  std::printf("%s: %zu nodes, %zu tetrahedra (%zu inverted), %zu boundary triangles, min quality %.3f\n", c.name.c_str(),
              m.nodes, m.tetrahedra, m.inverted, m.triangles, m.min_quality);
  std::printf("  interfaces: %zu triangles, %zu not shared by both sides; surfaces: %d Frontal-Delaunay, %d Delaunay, %zu re-meshed with MeshAdapt\n",
              m.interface_triangles, m.nonconformal_triangles, m.surfaces_frontal_delaunay, m.surfaces_delaunay, m.surfaces_remeshed.size());
  for (const mesh::RegionMesh& r : m.regions)
    std::printf("  %-10s %s %zu tetrahedra, volume %.4f mm^3 (B-rep %.4f)\n", r.name.c_str(), r.fluid ? "fluid" : "solid",
                r.tets.elements, r.tets.volume, r.brep_volume);
  std::printf("  time: geometry %.2f s, sizes %.2f s, surface %.2f s, volume %.2f s, quality and files %.2f s, total %.2f s\n",
              m.seconds_geometry, m.seconds_sizes, m.seconds_surface, m.seconds_volume, m.seconds_output, m.seconds_total);
  for (const std::string& n : m.notes) std::printf("  note: %s\n", n.c_str());
  std::printf("  wrote");
  for (std::size_t i = 0; i < w.files.size(); ++i)
    std::printf("%s %s", i ? "," : "", (w.directory / w.files[i]).string().c_str());
  std::printf("\n");
}

int run_mesh(const JobOptions& o) {
  ConsoleProgress console(o.show_progress());
  pipeline::TimeLimit limit(&console, o.timeout_s);
  bool writing = false;
  try {
    find_output_jobs();  // a missing module fails now, not after the build
    const config::Config c = load_config_argument(o.config);
    const pipeline::BuildResult r = pipeline::run_build(c, {}, &limit);
    const OutputJobs& jobs = output_jobs();  // loads the writers' libraries (output_jobs.hpp)
    writing = true;
    const pipeline::MeshOutputs w = jobs.write_mesh(c, r, o.output, &limit);
    console.interrupt_line();
    if (!r.valid())
      throw ChecksFailed("solid checks failed (" + r.failed_checks() + "); wrote " +
                         (o.output / pipeline::kReportFile).string() + " only (valid: false), no mesh");
    if (w.mesh.inverted > 0)
      throw ChecksFailed(std::to_string(w.mesh.inverted) + " inverted tetrahedra (see " +
                         (o.output / pipeline::kReportFile).string() + ")");
    if (w.mesh.nonconformal_triangles > 0)
      throw ChecksFailed(std::to_string(w.mesh.nonconformal_triangles) + " interface triangles not shared by both regions (see " +
                         (o.output / pipeline::kReportFile).string() + ")");
    if (!o.quiet) print_summary(c, w);
    return kOk;
  } catch (const Cancelled& e) {
    console.interrupt_line();
    throw Stopped(limit.stop_reason() + ": " + e.what() + "; " +
                  (writing ? "the outputs of this run were removed, " + o.output.string() + " holds none"
                           : "nothing written, " + o.output.string() + " left as it was"));
  } catch (...) {
    console.interrupt_line();
    throw;
  }
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
  auto o = std::make_shared<JobOptions>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh the blade metal and its coolant domain with gmsh; write DIR/mesh.msh, "
                                             "DIR/mesh_*.vtu, DIR/report.json and DIR/report.md");
  add_job_options(cmd, *o);
  return {cmd, [o] { return run_mesh(*o); }};
}

}  // namespace cg::cli
