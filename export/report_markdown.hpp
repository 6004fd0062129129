#pragma once
// report.md: the report a cooling engineer reads, rendered from the report.json document (so the two
// never disagree): what was built, every check with its result, the faces per feature, the files
// written (and skipped, with the reason), the design-check tables — passage area, wetted perimeter and
// hydraulic diameter along span from the section cuts, and any "design_checks" tables features add —
// mesh statistics when a mesh was made, timings and warnings.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace cg::io {

/// Markdown text of a report.json document (export/report.hpp layout plus the "sections", "notes" and
/// "mesh" sections). Sections whose keys are missing are left out; unknown
/// "design_checks" entries (name -> array of flat objects) become one table each.
std::string report_markdown(const nlohmann::ordered_json& report);

/// Writes report_markdown(report) atomically. Throws ExportError.
void write_report_markdown(const std::filesystem::path& file, const nlohmann::ordered_json& report);

}  // namespace cg::io
