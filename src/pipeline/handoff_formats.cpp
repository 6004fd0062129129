#include "src/pipeline/handoff_formats.hpp"

#include <algorithm>
#include <future>
#include <mutex>

#include "export/atomic_file.hpp"
#include "export/brep_writer.hpp"
#include "export/gltf_writer.hpp"
#include "export/iges_writer.hpp"
#include "export/preview.hpp"
#include "export/report_html.hpp"
#include "export/report_markdown.hpp"
#include "export/sections.hpp"
#include "export/sections_svg.hpp"
#include "export/stl_writer.hpp"
#include "export/triangulation.hpp"
#include "export/vtk_writer.hpp"
#include "export/x_display.hpp"
#include "src/blade_import/geomturbo_writer.hpp"
#include "src/core/background.hpp"
#include "src/core/constants.hpp"
#include "src/pipeline/network_format.hpp"
#include "src/pipeline/report.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;
namespace {

constexpr double kDeg = kPi / 180;

// What the formats of one build result share. The cache holds the blade's TShape, so a later result
// can never reuse its address and be mistaken for this one. The triangulation and the sections are
// made in the background once write_outputs has written the STEP file (prepare_shared_outputs), at the
// lowest priority (start_in_background): they take the cores the IGES writer, which runs on one, leaves
// idle.
struct Shared {
  std::mutex mutex;
  Handle(TopoDS_TShape) owner;
  std::shared_future<io::PartTriangles> triangles;
  std::shared_future<std::vector<features::SpanSection>> sections;
  std::shared_future<io::GltfModel> gltf;
  std::vector<std::string> notes;
};

Shared& shared_for(const BuildResult& r) {
  static Shared s;
  const Handle(TopoDS_TShape)& t = r.part.front().geometry.shape.TShape();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (s.owner != t) {
    if (s.triangles.valid()) s.triangles.wait();  // a background job of an earlier result still reads it
    if (s.sections.valid()) s.sections.wait();
    if (s.gltf.valid()) s.gltf.wait();
    s.owner = t;
    s.triangles = {};
    s.sections = {};
    s.gltf = {};
    s.notes.clear();
  }
  return s;
}

bool selected(const config::Config& c, std::initializer_list<config::OutputFormat> formats) {
  for (const config::OutputFormat f : formats)
    if (config::has_format(c.output.formats, f)) return true;
  return false;
}

// Starts the triangulation / the sections in the background when not yet started. They only read the
// part (each works on a copy of the shapes it meshes or cuts).
void start_triangles(const config::Config& c, const BuildResult& r) {
  Shared& s = shared_for(r);
  std::lock_guard<std::mutex> lock(s.mutex);
  if (s.triangles.valid()) return;
  const io::TriangulationOptions o{c.output.stl_deflection, c.output.stl_angular_deflection_deg * kDeg};
  s.triangles = start_in_background([&part = r.part, o] { return io::triangulate_part(part, o); }).share();
}

void start_sections(const config::Config& c, const BuildResult& r) {
  Shared& s = shared_for(r);
  std::lock_guard<std::mutex> lock(s.mutex);
  if (s.sections.valid()) return;
  s.sections = start_in_background([&r, spans = c.output.section_spans] {
                 return features::span_sections(r.part, features::span_surfaces(r.model, spans));
               }).share();
}

void start_gltf(const config::Config& c, const BuildResult& r) {
  Shared& s = shared_for(r);
  std::lock_guard<std::mutex> lock(s.mutex);
  if (s.gltf.valid()) return;
  io::GltfOptions o;
  o.product_name = c.output.product_name.empty() ? c.name : c.output.product_name;
  s.gltf = start_in_background([&part = r.part, o] { return io::make_gltf(part, o); }).share();
}

const io::PartTriangles& triangles(const config::Config& c, const BuildResult& r) {
  start_triangles(c, r);
  return shared_for(r).triangles.get();  // rethrows the triangulation's error
}

const io::GltfModel& gltf(const config::Config& c, const BuildResult& r) {
  start_gltf(c, r);
  return shared_for(r).gltf.get();
}

const std::vector<features::SpanSection>& sections(const config::Config& c, const BuildResult& r) {
  start_sections(c, r);
  return shared_for(r).sections.get();
}

std::string product(const config::Config& c) { return c.output.product_name.empty() ? c.name : c.output.product_name; }

void need_part(const BuildResult& r, const char* what) {
  if (r.part.empty()) throw io::ExportError(std::string(what) + ": the build produced no body");
}

}  // namespace

std::vector<OutputWriter> handoff_writers() {
  using F = config::OutputFormat;
  return {
      {F::Iges, "IGES (144 trimmed NURBS surfaces, names and levels per feature)", {"blade.igs"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "IGES");
         d.write("blade.igs", [&](const fs::path& t) { io::write_iges(t, r.part, {product(c), c.output.iges_mode == "brep" ? io::IgesMode::Brep : io::IgesMode::Faces}); });
       }},
      {F::Brep, "OCCT BREP of all bodies", {"blade.brep"},
       [](OutputDirectory& d, const config::Config&, const BuildResult& r, ProgressSink*) {
         need_part(r, "BREP");
         d.write("blade.brep", [&](const fs::path& t) { io::write_brep(t, r.part); });
       }},
      {F::Stl, "binary STL", {"blade.stl"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "STL");
         const io::PartTriangles& t = triangles(c, r);
         d.write("blade.stl", [&](const fs::path& target) { io::write_stl(target, t, product(c)); });
       }},
      {F::Vtk, "ParaView multiblock with feature ids", {"blade.vtm", "blade_blade.vtp"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "VTK");
         const io::PartTriangles& t = triangles(c, r);
         // The pieces first, then the multiblock that names them.
         for (std::size_t k = 0; k < r.part.size(); ++k)
           d.write("blade_" + r.part[k].name + ".vtp",
                   [&](const fs::path& target) { io::write_vtk_piece(target, r.part[k].name, t, static_cast<int>(k)); });
         d.write("blade.vtm", [&](const fs::path& target) { io::write_vtk_multiblock(target, r.part, "blade"); });
       }},
      {F::Glb, "blade.glb (glTF 2.0, metres, Y up, one primitive per face coloured by feature kind)", {"blade.glb"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "glTF");
         const io::GltfModel& m = gltf(c, r);
         d.write("blade.glb", [&](const fs::path& t) { io::write_glb(t, m); });
       }},
      {F::Preview, "preview.png (VTK; skipped without an X display)", {"preview.png"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "preview");
         const io::PartTriangles& t = triangles(c, r);
         io::PreviewOptions po;
         po.title = product(c);
         // Hub -> casing along the iso-curve u = 0: the blade stands upright.
         po.up = r.model.surface.point(0, 1) - r.model.surface.point(0, 0);
         bool written = false;
         std::string note;
         // No display: no file, a note in the report (OutputDirectory::write needs a file from its writer).
         const io::DisplayStatus display = io::ensure_x_display();
         if (!display.available) {
           shared_for(r).notes.push_back("preview.png skipped: " + display.message);
           return;
         }
         d.write("preview.png", [&](const fs::path& target) {
           const io::PreviewResult p = io::write_preview(target, t, po);
           written = p.written;
           note = p.message;
         });
         if (!written) shared_for(r).notes.push_back(note);
       }},
      {F::Sections, "sections.svg (sections at several spans with passages and dimensions)", {"sections.svg"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "sections");
         const auto& cuts = sections(c, r);
         d.write("sections.svg", [&](const fs::path& t) { io::write_sections_svg(t, cuts, product(c)); });
       }},
      {F::GeomTurbo, "blade.geomTurbo: the outer blade and its channel (linear cascade for straight vanes)", {"blade.geomTurbo"},
       [](OutputDirectory& d, const config::Config&, const BuildResult& r, ProgressSink*) {
         d.write("blade.geomTurbo", [&](const fs::path& t) { blade_import::write_geomturbo_file(t.string(), r.model); });
       }},
      {F::Html, "report.html (one offline page: the model in 3D by feature, sections, passages, checks, holes)", {"report.html"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         need_part(r, "report.html");
         std::vector<std::string> files = d.files();
         files.push_back("report.html");
         if (selected(c, {F::ReportMd})) files.push_back("report.md");
         files.push_back(kReportFile);
         io::ReportContent rc = report_content(c, r, files, r.timings);
         add_handoff_report(c, r, rc);
         io::ReportHtmlContent h{product(c), io::report_json(rc), &gltf(c, r), io::sections_svg(sections(c, r), product(c))};
         // Hub -> casing along the iso-curve u = 0, as preview.png: the blade stands upright.
         const Eigen::Vector3d up = r.model.surface.point(0, 1) - r.model.surface.point(0, 0);
         h.up = {up.x(), up.y(), up.z()};
         d.write("report.html", [&](const fs::path& t) { io::write_report_html(t, h); });
       }},
      {F::ReportMd, "report.md (rendered from report.json)", {"report.md"},
       [](OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
         std::vector<std::string> files = d.files();
         files.push_back("report.md");
         files.push_back(kReportFile);
         io::ReportContent rc = report_content(c, r, files, r.timings);
         add_handoff_report(c, r, rc);
         d.write("report.md", [&](const fs::path& t) { io::write_report_markdown(t, io::report_json(rc)); });
       }},
  };
}

void add_handoff_report(const config::Config& c, const BuildResult& r, io::ReportContent& report) {
  if (r.part.empty()) return;
  Shared& s = shared_for(r);
  if (selected(c, {config::OutputFormat::Sections, config::OutputFormat::ReportMd, config::OutputFormat::Html}) && r.valid())
    report.extra["sections"] = io::sections_json(sections(c, r));
  if (!s.notes.empty()) report.extra["notes"] = s.notes;
  add_network_report(r, report);
}

void prepare_shared_outputs(const config::Config& c, const BuildResult& r) {
  if (r.part.empty() || !r.valid()) return;
  if (selected(c, {config::OutputFormat::Stl, config::OutputFormat::Vtk, config::OutputFormat::Preview})) start_triangles(c, r);
  if (selected(c, {config::OutputFormat::Sections, config::OutputFormat::ReportMd, config::OutputFormat::Html}))
    start_sections(c, r);
  if (selected(c, {config::OutputFormat::Glb, config::OutputFormat::Html})) start_gltf(c, r);
}

void finish_shared_outputs(const BuildResult& r) noexcept {
  if (r.part.empty()) return;
  Shared& s = shared_for(r);
  // Errors stay in the futures: the format that needs the result reports them.
  if (s.triangles.valid()) s.triangles.wait();
  if (s.sections.valid()) s.sections.wait();
  if (s.gltf.valid()) s.gltf.wait();
}

}  // namespace cg::pipeline
