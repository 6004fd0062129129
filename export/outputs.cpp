#include "export/outputs.hpp"

#include <chrono>

#include "export/atomic_file.hpp"
#include "export/brep_writer.hpp"
#include "export/iges_writer.hpp"
#include "export/preview.hpp"
#include "export/sections_svg.hpp"
#include "export/stl_writer.hpp"
#include "export/triangulation.hpp"
#include "export/vtk_writer.hpp"

namespace cg::io {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

}  // namespace

const std::vector<std::pair<const char*, OutputFormat>>& output_format_names() {
  static const std::vector<std::pair<const char*, OutputFormat>> names = {
      {"step", OutputFormat::Step},       {"iges", OutputFormat::Iges},       {"brep", OutputFormat::Brep},
      {"stl", OutputFormat::Stl},         {"vtk", OutputFormat::Vtk},         {"preview", OutputFormat::Preview},
      {"sections", OutputFormat::Sections}, {"report_md", OutputFormat::ReportMarkdown}};
  return names;
}

OutputFormat parse_output_format(const std::string& name) {
  std::string known;
  for (const auto& [n, f] : output_format_names()) {
    if (name == n) return f;
    known += std::string(known.empty() ? "" : ", ") + "\"" + n + "\"";
  }
  throw InvalidGeometry("unknown output format \"" + name + "\" (known: " + known + ")");
}

const char* output_format_name(OutputFormat f) {
  for (const auto& [n, g] : output_format_names())
    if (g == f) return n;
  return "?";
}

std::set<OutputFormat> all_output_formats() {
  std::set<OutputFormat> all;
  for (const auto& [n, f] : output_format_names()) all.insert(f);
  return all;
}

nlohmann::json sections_json(const std::vector<SectionCut>& cuts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : cuts) {
    nlohmann::json passages = nlohmann::json::array();
    for (const auto& p : c.passages)
      passages.push_back({{"name", p.name},
                          {"area_mm2", p.area},
                          {"wetted_perimeter_mm", p.wetted_perimeter},
                          {"hydraulic_diameter_mm", p.hydraulic_diameter}});
    out.push_back({{"span", c.span}, {"chord_mm", c.chord}, {"metal_area_mm2", c.metal_area}, {"passages", passages}});
  }
  return out;
}

HandoffResult write_handoff(const std::filesystem::path& dir, const brep::Part& part, const blade::BladeModel* model,
                            const HandoffOptions& o) {
  if (part.empty()) throw ExportError("nothing to export: the part has no bodies");
  if (!(o.stl_deflection > 0) || !(o.stl_angular_deflection_deg > 0))
    throw ExportError("STL deflections must be > 0");
  HandoffResult r;
  nlohmann::json timings = nlohmann::json::object();
  auto has = [&](OutputFormat f) { return o.formats.count(f) > 0; };
  auto timed = [&](const char* stage, const auto& write) {
    const auto t0 = std::chrono::steady_clock::now();
    write();
    timings[stage] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  if (has(OutputFormat::Step))
    timed(output_format_name(OutputFormat::Step), [&] {
      write_step(dir / "blade.step", part, {o.step_schema, o.product_name});
      r.files.push_back(dir / "blade.step");
    });
  if (has(OutputFormat::Iges))
    timed(output_format_name(OutputFormat::Iges), [&] {
      write_iges(dir / "blade.igs", part, {o.product_name});
      r.files.push_back(dir / "blade.igs");
    });
  if (has(OutputFormat::Brep))
    timed(output_format_name(OutputFormat::Brep), [&] {
      write_brep(dir / "blade.brep", part);
      r.files.push_back(dir / "blade.brep");
    });
  // One triangulation for STL, VTK and the preview.
  PartTriangles t;
  if (has(OutputFormat::Stl) || has(OutputFormat::Vtk) || has(OutputFormat::Preview))
    timed("triangulation", [&] { t = triangulate_part(part, {o.stl_deflection, o.stl_angular_deflection_deg * kDeg}); });
  if (has(OutputFormat::Stl))
    timed(output_format_name(OutputFormat::Stl), [&] {
      r.summary["stl_triangles"] = write_stl(dir / "blade.stl", t, o.product_name);
      r.files.push_back(dir / "blade.stl");
    });
  if (has(OutputFormat::Vtk))
      timed(output_format_name(OutputFormat::Vtk), [&] {
        const VtkFiles v = write_vtk(dir, "blade", part, t);
        r.files.insert(r.files.end(), v.pieces.begin(), v.pieces.end());
        r.files.push_back(v.multiblock);
      });
    if (has(OutputFormat::Preview))
      timed(output_format_name(OutputFormat::Preview), [&] {
        PreviewOptions po{o.preview_width, o.preview_height, 0.22, o.product_name, Eigen::Vector3d::Zero()};
        // Hub -> casing along the leading edge (u = 0 at the LE): the blade stands upright.
        if (model) po.up = model->surface.point(0, 1) - model->surface.point(0, 0);
        const PreviewResult p = write_preview(dir / "preview.png", t, po);
        if (p.written)
          r.files.push_back(dir / "preview.png");
        else
          r.notes.push_back(p.message);
      });
  if (has(OutputFormat::Sections)) {
    if (!model) {
      r.notes.push_back("sections.svg skipped: no blade model to place the section surfaces");
    } else {
      timed(output_format_name(OutputFormat::Sections), [&] {
        r.sections = cut_sections(part, blade_section_surfaces(*model, o.section_spans));
        write_sections_svg(dir / "sections.svg", r.sections, o.product_name);
        r.files.push_back(dir / "sections.svg");
      });
      r.summary["sections"] = sections_json(r.sections);
    }
  }
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : r.files) files.push_back(f.filename().string());
  r.summary["files"] = files;
  r.summary["notes"] = r.notes;
  r.summary["timings_s"] = timings;
  return r;
}

}  // namespace cg::io
