// Hand-off speed on a cooled blade: each exporter's time on the test part of tests/export/cooled_part.hpp
// (the built-in example with chambers, film holes and an insert made there), the named XCAF STEP against
// OCCT's plain STEPControl_Writer of the same compound (the price of names, colours and layers), our
// binary STL writer against StlAPI_Writer on the same triangulation; then `coolinggen mesh` of the blade
// the features build: the full built-in example (153 film holes, ribs, fillets, turbulators, pins, TE
// slots) with the default sizes, timed per stage and against the goal of issue 20 (build + mesh
// <= 10 min and <= 4 GB peak memory on 2 cores).
//
// Exits non-zero when results disagree: the STEP files of both writers read back to different volumes
// (1e-6 relative), the STL triangle counts differ, the build fails its checks, the mesh has inverted
// tetrahedra or interface triangles not shared by both regions, the coolant mesh volume is off the
// removed volume (minus inserts) by more than 0.5 %, or (full run) the goal is missed.
// Usage: bench_export_mesh [--quick]   (--quick: one chamber, one hole, two sections; the mesh of a light
// variant of the example with coarse sizes, the goal not checked)
#include <sys/resource.h>

#include <BRepBuilderAPI_Copy.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StlAPI_Writer.hxx>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "export/brep_writer.hpp"
#include "export/iges_writer.hpp"
#include "export/part_document.hpp"
#include "export/preview.hpp"
#include "export/sections.hpp"
#include "export/sections_svg.hpp"
#include "export/step_writer.hpp"
#include "export/stl_writer.hpp"
#include "export/triangulation.hpp"
#include "export/vtk_writer.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/mesh/blade_mesher.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/mesh_job.hpp"
#include "tests/export/cooled_part.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

template <class Run>
double seconds(Run run) {
  const auto t0 = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double step_volume(const fs::path& file) {
  STEPControl_Reader r;
  if (r.ReadFile(file.string().c_str()) != IFSelect_RetDone) return -1;
  r.TransferRoots();
  return test::occt_volume(r.OneShape());
}

// The goal of issue 20 for `coolinggen mesh` of the built-in example with the default sizes on 2 cores.
constexpr double kGoalSeconds = 600, kGoalBytes = 4e9;

// Peak resident memory of this process so far, bytes.
double peak_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1024.0 * static_cast<double>(u.ru_maxrss);  // Linux: KiB
}

// Builds and meshes the built-in example (full: default sizes, against the goal; --quick: one film row
// and one showerhead row over 5 % of the span, fewer turbulators, slots and pins, coarse sizes).
// Returns the number of failed checks.
int mesh_real_blade(bool quick, const fs::path& out) {
  nlohmann::json doc = nlohmann::json::parse(config::builtin_example_json());
  if (quick) {
    auto& c = doc["cooling"];
    c["film_rows"] = nlohmann::json::array({c["film_rows"][1]});
    c["film_rows"][0]["span_start"] = 0.5;
    c["film_rows"][0]["span_end"] = 0.55;
    c["showerhead"]["rows"] = 1;
    c["showerhead"]["span_start"] = 0.5;
    c["showerhead"]["span_end"] = 0.55;
    for (auto& t : c["core"]["turbulators"]) t["pitch"] = 12.0;
    c["core"]["trailing_edge"]["pitch"] = 10.0;
    c["core"]["trailing_edge"]["pin_fins"]["spanwise_pitch"] = 10.0;
    doc["mesh"] = {{"max_size", 4.0}, {"min_size", 0.15}, {"curvature_elements", 8}, {"feature_curvature_elements", 16}, {"size_growth", 0.6}};
  }
  const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "hpt_rotor");
  pipeline::BuildResult b;
  const double t_build = seconds([&] { b = pipeline::run_build(c); });
  int failures = !b.valid();
  pipeline::MeshOutputs w;
  const double t_mesh = seconds([&] { w = pipeline::write_mesh(c, b, out); });
  const mesh::MeshResult& m = w.mesh;
  const double expected = m.removed_volume - m.insert_volume, rel = (m.coolant_mesh_volume - expected) / expected;
  const double total = t_build + t_mesh, peak = peak_bytes();
  const bool mesh_ok = m.inverted == 0 && m.nonconformal_triangles == 0 && std::abs(rel) <= 5e-3;
  const bool goal_ok = quick || (total <= kGoalSeconds && peak <= kGoalBytes);
  failures += !mesh_ok + !goal_ok;
  std::printf("  gmsh   %s: %d faces; %zu nodes, %zu tetrahedra (%zu inverted), %zu boundary triangles, min quality %.3f\n",
              quick ? "light variant of the built-in example, coarse sizes" : "built-in example, default sizes",
              m.surfaces_frontal_delaunay + m.surfaces_delaunay, m.nodes, m.tetrahedra, m.inverted, m.triangles, m.min_quality);
  for (const mesh::RegionMesh& r : m.regions)
    std::printf("         %-8s %zu tetrahedra, mesh volume %+.3f %% of the B-rep\n", r.name.c_str(), r.tets.elements,
                100 * (r.tets.volume - r.brep_volume) / r.brep_volume);
  std::printf("         interfaces %zu triangles, %zu not shared; coolant volume %+.3f %% of removed - inserts (bound 0.5 %%)\n",
              m.interface_triangles, m.nonconformal_triangles, 100 * rel);
  std::printf("         surfaces: %d Frontal-Delaunay, %d Delaunay, %zu re-meshed with MeshAdapt; %zu size samples\n",
              m.surfaces_frontal_delaunay, m.surfaces_delaunay, m.surfaces_remeshed.size(), m.size_samples);
  std::printf("         build %.1f s; mesh: geometry %.1f s, sizes %.1f s, surface %.1f s, volume %.1f s, quality and files %.1f s\n",
              t_build, m.seconds_geometry, m.seconds_sizes, m.seconds_surface, m.seconds_volume, m.seconds_output);
  std::printf("         build + mesh %.1f s (goal <= %.0f s: %s), peak memory %.2f GB (goal <= %.0f GB: %s)\n", total, kGoalSeconds,
              quick ? "not checked with --quick" : (total <= kGoalSeconds ? "met" : "MISSED"), peak / 1e9, kGoalBytes / 1e9,
              quick ? "not checked with --quick" : (peak <= kGoalBytes ? "met" : "MISSED"));
  if (!b.valid()) std::printf("         the build failed its checks: %s\n", b.failed_checks().c_str());
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // OCCT's data exchange prints transfer statistics through the default messenger: keep stdout ours.
  for (const Handle(Message_Printer)& printer : Message::DefaultMessenger()->Printers()) printer->SetTraceLevel(Message_Fail);
  const fs::path dir = fs::temp_directory_path() / ("cg_bench_export_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  int failures = 0;

  test::CooledPartOptions po;
  if (quick) {
    po.chambers = 1;
    po.holes = 1;
    po.insert = false;
    po.chamber_top = 0.4;
  }
  test::CooledPart p;
  const double t_part = seconds([&] { p = test::cooled_example(po); });
  int faces = 0;
  for (const auto& b : p.part) faces += static_cast<int>(b.geometry.faces.size());
  std::printf("bench_export_mesh%s: cooled example blade, %d chambers, %d film holes, %zu bodies, %d faces (made in %.2f s)\n",
              quick ? " --quick" : "", p.chambers, p.holes, p.part.size(), faces, t_part);

  // STEP: ours (XCAF, names, colours, layers) vs OCCT's plain writer of the same compound.
  const double t_step = seconds([&] { io::write_step(dir / "ours.step", p.part, {io::StepSchema::AP242, "bench"}); });
  const double t_step_occt = seconds([&] {
    STEPControl_Controller::Init();
    STEPControl_Writer w;
    w.Transfer(io::part_compound(p.part), STEPControl_AsIs);
    w.Write((dir / "occt.step").string().c_str());
  });
  const double v_ours = step_volume(dir / "ours.step"), v_occt = step_volume(dir / "occt.step");
  const bool step_ok = std::abs(v_ours - v_occt) <= 1e-6 * std::abs(v_occt);
  failures += !step_ok;
  std::printf("  STEP   ours %.3f s  OCCT plain %.3f s  ratio %.2fx  (read back %.6f vs %.6f mm^3: %s)\n", t_step,
              t_step_occt, t_step_occt / t_step, v_ours, v_occt, step_ok ? "same" : "DIFFERENT");

  // STL: our writer vs StlAPI_Writer on the same triangulation (mesh time separate).
  io::PartTriangles tri;
  const double dfl = quick ? 0.05 : 0.01;
  const double t_mesh = seconds([&] { tri = io::triangulate_part(p.part, {dfl, 0.35}); });
  const double t_stl = seconds([&] { io::write_stl(dir / "ours.stl", tri, "bench"); });
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(io::part_compound(p.part), false, false).Shape();
  BRepMesh_IncrementalMesh(copy, dfl, false, 0.35, true);
  const double t_stl_occt = seconds([&] {
    StlAPI_Writer w;
    w.ASCIIMode() = false;
    w.Write(copy, (dir / "occt.stl").string().c_str());
  });
  const auto n_ours = (fs::file_size(dir / "ours.stl") - 84) / 50, n_occt = (fs::file_size(dir / "occt.stl") - 84) / 50;
  failures += n_ours != n_occt;
  std::printf("  STL    ours %.3f s  StlAPI %.3f s  ratio %.2fx  (%ju vs %ju triangles; BRepMesh %.3f s at %.2f mm)\n", t_stl,
              t_stl_occt, t_stl_occt / t_stl, static_cast<std::uintmax_t>(n_ours), static_cast<std::uintmax_t>(n_occt), t_mesh, dfl);

  const double t_iges = seconds([&] { io::write_iges(dir / "blade.igs", p.part, {"bench"}); });
  const double t_brep = seconds([&] { io::write_brep(dir / "blade.brep", p.part); });
  const double t_vtk = seconds([&] { io::write_vtk(dir, "blade", p.part, tri); });
  std::vector<features::SpanSection> cuts;
  const std::vector<double> spans = quick ? std::vector<double>{0.2, 0.6} : std::vector<double>{0.1, 0.3, 0.5, 0.7, 0.9};
  const double t_sec = seconds([&] {
    cuts = features::span_sections(p.part, features::span_surfaces(p.model, spans));
    io::write_sections_svg(dir / "sections.svg", cuts, "bench");
  });
  io::PreviewResult prev;
  const double t_png = seconds([&] { prev = io::write_preview(dir / "preview.png", tri, {1280, 960, 0.22, "bench", {}}); });
  std::printf("  IGES %.3f s, BREP %.3f s, VTK %.3f s, sections (%zu cuts + SVG) %.3f s, preview %s %.3f s\n", t_iges, t_brep,
              t_vtk, spans.size(), t_sec, prev.written ? "PNG" : "(skipped)", t_png);

  // gmsh: the blade the features build, as `coolinggen mesh` does (run_build + write_mesh).
  failures += mesh_real_blade(quick, dir / "mesh");

  std::error_code ec;
  fs::remove_all(dir, ec);
  if (failures) std::printf("bench_export_mesh: %d disagreement(s)\n", failures);
  return failures ? 1 : 0;
}
