#pragma once
// Every hand-off file of a build, selectable (config "output.formats", default all), written into one
// directory: blade.step, blade.igs, blade.brep, blade.stl, blade.vtm + blade_<body>.vtp, preview.png,
// sections.svg (report.json and report.md are written by the caller, who owns the report: see
// export/report_markdown.hpp). Each file is written atomically; the preview is skipped with a message
// (never an error) when no X display can be had.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "export/sections.hpp"
#include "export/step_writer.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::io {

enum class OutputFormat { Step, Iges, Brep, Stl, Vtk, Preview, Sections, ReportMarkdown };

/// Config names: "step", "iges", "brep", "stl", "vtk", "preview", "sections", "report_md".
const std::vector<std::pair<const char*, OutputFormat>>& output_format_names();
/// Name -> format; throws InvalidGeometry for an unknown name (the config reports it with its path).
OutputFormat parse_output_format(const std::string& name);
const char* output_format_name(OutputFormat f);
std::set<OutputFormat> all_output_formats();

struct HandoffOptions {
  std::set<OutputFormat> formats = all_output_formats();
  std::string product_name = "blade";
  StepSchema step_schema = StepSchema::AP242;
  double stl_deflection = 0.01;             ///< mm, STL chordal deflection (and the VTK/preview mesh), > 0
  double stl_angular_deflection_deg = 20;   ///< deg, > 0
  std::vector<double> section_spans = {0.1, 0.3, 0.5, 0.7, 0.9};  ///< span fractions of sections.svg
  int preview_width = 1280, preview_height = 960;                 ///< pixels
};

struct HandoffResult {
  std::vector<std::filesystem::path> files;  ///< written, in order
  std::vector<std::string> notes;            ///< skipped outputs and why (e.g. no X display)
  std::vector<SectionCut> sections;          ///< when sections were cut
  /// For report.json / report.md: {"files": [...], "notes": [...], "stl_triangles", "sections": [...],
  /// "timings_s": {format: s}}.
  nlohmann::json summary = nlohmann::json::object();
};

/// Writes the selected files of `part` into `dir` (which must exist). `model` gives the section
/// surfaces (sections are skipped with a note when it is null). Throws ExportError when a file cannot be
/// written.
HandoffResult write_handoff(const std::filesystem::path& dir, const brep::Part& part, const blade::BladeModel* model,
                            const HandoffOptions& options);

/// The sections table for the report: [{"span", "chord_mm", "metal_area_mm2", "passages": [{"name",
/// "area_mm2", "wetted_perimeter_mm", "hydraulic_diameter_mm"}]}].
nlohmann::json sections_json(const std::vector<SectionCut>& cuts);

}  // namespace cg::io
