#include "export/report_html.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "export/atomic_file.hpp"
#include "export/feature_style.hpp"
#include "export/web_assets.hpp"
#include "export/xml_text.hpp"

namespace cg::io {
namespace fs = std::filesystem;
namespace {

// The face table of the .glb for the page: primitive i -> body, name, kind, area; the kinds' colours;
// the view's up direction.
nlohmann::ordered_json faces_json(const GltfModel& m, const std::array<double, 3>& up) {
  nlohmann::ordered_json faces = nlohmann::ordered_json::array(), kinds = nlohmann::ordered_json::array();
  std::vector<std::string> seen;
  for (const GltfFace& f : m.faces) {
    faces.push_back({{"body", f.body}, {"name", f.name}, {"kind", f.kind}, {"area_mm2", f.area}});
    if (std::find(seen.begin(), seen.end(), f.kind) == seen.end()) {
      seen.push_back(f.kind);
      kinds.push_back({{"kind", f.kind}, {"colour", hex_colour(kind_colour(f.kind))}});
    }
  }
  // glTF's axes are the part's (x, z, -y) (gltf_writer.hpp: Z up -> Y up).
  return {{"faces", faces}, {"kinds", kinds}, {"up", {up[0], up[2], -up[1]}}, {"triangles", m.triangles},
          {"deflection_mm", m.deflection}};
}

// The drawing without its XML declaration (inline SVG in HTML).
std::string inline_svg(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? std::string() : svg.substr(start);
}

}  // namespace

std::string inline_script(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] != '<' || i + 1 >= text.size() || text[i + 1] != '/') continue;
    std::string next = text.substr(i + 2, 6);
    for (char& ch : next) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (next == "script" || next.compare(0, 5, "style") == 0) out += '\\';
  }
  return out;
}

std::string inline_json(const nlohmann::ordered_json& value) {
  const std::string text = value.dump();
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) out += ch == '<' ? std::string("\\u003c") : std::string(1, ch);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4 + bytes.size() / 57 + 1);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t k) { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0u; };
    const unsigned v = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    if ((i / 3 + 1) % 19 == 0) out += '\n';  // 76 characters a line (atob skips white space)
  }
  return out;
}

std::string report_html(const ReportHtmlContent& c) {
  const std::string title = xml_escape(c.title);
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  h += "<title>" + title + ": CoolingGen report</title>\n<style>\n" + inline_script(web::kPageStyle) + "</style>\n</head>\n<body>\n";
  h += "<h1>" + title + "</h1>\n<p id=\"cg-summary\"></p>\n";
  h += "<p id=\"cg-verdict\" data-state=\"loading\">loading (this page needs JavaScript)</p>\n<div id=\"cg-content\">\n";
  if (c.model) {
    h += "<section id=\"model\"><h2>Model</h2>\n<p>Drag to turn, wheel to zoom, right-drag to pan; click a face for its "
         "name, kind and area.</p>\n<div class=\"viewer\"><canvas id=\"cg-canvas\"></canvas><div id=\"cg-controls\"></div></div>\n"
         "<p id=\"cg-picked\"></p></section>\n";
  }
  if (!c.sections_svg.empty()) h += "<section id=\"cg-sections\"><h2>Sections</h2>\n" + inline_svg(c.sections_svg) + "\n</section>\n";
  h += "</div>\n<script type=\"application/json\" id=\"cg-report\">" + inline_json(c.report) + "</script>\n";
  if (c.model) {
    h += "<script type=\"application/json\" id=\"cg-faces\">" + inline_json(faces_json(*c.model, c.up)) + "</script>\n";
    h += "<script type=\"application/octet-stream\" id=\"cg-model\">\n" + base64(c.model->glb) + "</script>\n";
    h += "<script>\n" + inline_script(web::kViewerBundle) + "\n</script>\n";
  }
  h += "<script>\n" + inline_script(web::kReportPage) + "\n</script>\n</body>\n</html>\n";
  return h;
}

void write_report_html(const fs::path& file, const ReportHtmlContent& content) {
  const std::string text = report_html(content);
  write_atomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

}  // namespace cg::io
