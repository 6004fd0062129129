// Hand-off speed on a cooled blade (the built-in example with chambers, film holes and an insert, made
// as in tests/export/cooled_part.hpp): each exporter's time, the named XCAF STEP against OCCT's plain
// STEPControl_Writer of the same compound (the price of names, colours and layers), our binary STL
// writer against StlAPI_Writer on the same triangulation, and gmsh's meshing of metal + coolant (time
// per stage: geometry = coolant domain + conformal fuse + import, surface, volume).
//
// Exits non-zero when results disagree: the STEP files of both writers read back to different volumes
// (1e-6 relative), the STL triangle counts differ, the mesh has inverted elements or the coolant mesh
// volume is off the removed volume by more than 0.5 %.
// Usage: bench_export_mesh [--quick]   (--quick: one chamber, one hole, two sections, coarse mesh)
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
#include "src/mesh/blade_mesher.hpp"
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
  return test::volume_of(r.OneShape());
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

  // gmsh: metal + coolant.
  mesh::MeshOptions mo;
  if (quick) {
    mo.max_size = 6;
    mo.curvature_elements = 8;
    mo.feature_curvature_elements = 12;
    mo.optimize = false;
  }
  const mesh::MeshResult m = mesh::mesh_blade(p.part, p.uncooled, p.uncooled_faces, mesh::directory_writer(dir), mo);
  const double rel = (m.coolant_mesh_volume - (m.removed_volume - m.insert_volume)) / (m.removed_volume - m.insert_volume);
  const bool mesh_ok = m.inverted == 0 && (quick || std::abs(rel) <= 5e-3);
  failures += !mesh_ok;
  std::printf("  gmsh   metal + coolant: %zu nodes, %zu tetrahedra, %zu inverted, min quality %.3f, coolant volume %+.3f %%\n",
              m.nodes, m.tetrahedra, m.inverted, m.min_quality, 100 * rel);
  std::printf("         geometry %.2f s, surface %.2f s, volume %.2f s, total %.2f s (goal for the example: <= 60 s)\n",
              m.seconds_geometry, m.seconds_surface, m.seconds_volume, m.seconds_total);

  std::error_code ec;
  fs::remove_all(dir, ec);
  if (failures) std::printf("bench_export_mesh: %d disagreement(s)\n", failures);
  return failures ? 1 : 0;
}
