#include "src/study/study_html.hpp"

#include "export/report_html.hpp"
#include "export/web_assets.hpp"
#include "export/xml_text.hpp"
#include "src/study/text_file.hpp"

namespace cg::study {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// The variant's page, relative to the study directory: report.html, else report.json, else none.
std::string variant_link(const fs::path& study_dir, const std::string& id) {
  for (const char* f : {"report.html", "report.json"})
    if (fs::exists(study_dir / "variants" / id / f)) return "variants/" + id + "/" + f;
  return "";
}

json study_data(const fs::path& study_dir, const StudyListing& l) {
  json counts = json::object();
  for (const auto& [s, n] : status_counts(l)) counts[status_name(s)] = n;
  json metrics = json::array();
  for (const auto& [name, value] : metric_columns(Metrics{})) metrics.push_back(name);
  json rows = json::array();
  for (const ResultRow& r : l.rows) {
    json m = json::object();
    for (const auto& [name, value] : metric_columns(r.metrics)) m[name] = value ? json(*value) : json();
    rows.push_back({{"id", r.id},
                    {"values", r.values},
                    {"status", status_name(r.status)},
                    {"refused_field", r.status == Status::kRefused ? refusal_field(r.error) : ""},
                    {"error", r.error},
                    {"metrics", m},
                    {"link", variant_link(study_dir, r.id)}});
  }
  return {{"study", l.name}, {"parameters", l.parameters}, {"metrics", metrics}, {"status_counts", counts}, {"rows", rows}};
}

}  // namespace

void write_study_html(const fs::path& study_dir, const StudyListing& l) {
  const std::string title = io::xml_escape(l.name);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Study " + title +
                  ": CoolingGen</title>\n<style>\n" + io::inline_script(io::web::kPageStyle) + "</style>\n</head>\n<body>\n";
  h += "<h1>Study " + title + "</h1>\n<p id=\"cg-summary\"></p>\n";
  h += "<p id=\"cg-verdict\" data-state=\"loading\">loading (this page needs JavaScript)</p>\n<div id=\"cg-content\"></div>\n";
  h += "<script type=\"application/json\" id=\"cg-study\">" + io::inline_json(study_data(study_dir, l)) + "</script>\n";
  h += "<script>\n" + io::inline_script(io::web::kStudyPage) + "\n</script>\n</body>\n</html>\n";
  write_text(study_dir / "study_report.html", h);
}

}  // namespace cg::study
