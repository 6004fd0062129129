#pragma once
// report.html of a build: one self-contained offline page (no network, no neighbouring files: it works
// mailed alone, opened by double-click) with the model in 3D (the .glb inline as base64 with its face
// table; turn, zoom, show/hide bodies and feature kinds, pick a face for its name, kind and area), the
// sections drawing with its passage table, the checks, the film-hole table and every other section of
// report.json (the page reads the report's content generically: export/web/report_page.js). The
// viewer script is the committed bundle (export/web_assets.hpp). Written atomically.
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <string>

#include "export/gltf_writer.hpp"

namespace cg::io {

struct ReportHtmlContent {
  std::string title;                  ///< the product's name
  nlohmann::ordered_json report;      ///< what report.json holds
  const GltfModel* model = nullptr;   ///< the 3D view's model (null: the page has no 3D view)
  std::string sections_svg;           ///< the sections drawing ("" : none)
  std::array<double, 3> up{0, 0, 1};  ///< the view's up direction in the part's axes (hub -> tip)
};

/// The page's text.
std::string report_html(const ReportHtmlContent& content);

/// Writes report_html(content) atomically. Throws ExportError.
void write_report_html(const std::filesystem::path& file, const ReportHtmlContent& content);

/// Script or style text for an inline <script> or <style> element: "</script" and "</style" (any case)
/// become "<\/script", "<\/style" (the same text inside a JavaScript string or regular expression,
/// where they can occur), so the element cannot end early.
std::string inline_script(const std::string& text);

/// JSON text for an inline <script type="application/json">: every '<' becomes \u003c (only strings
/// hold '<' in JSON, and the parser reads the same string).
std::string inline_json(const nlohmann::ordered_json& value);

/// Base64 (RFC 4648, with padding) of bytes.
std::string base64(const std::string& bytes);

}  // namespace cg::io
