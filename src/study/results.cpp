#include "src/study/results.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "export/atomic_file.hpp"
#include "src/config/config_error.hpp"
#include "src/config/json_document.hpp"
#include "src/core/format.hpp"
#include "src/study/text_file.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kStatusFile = "status.json";
constexpr const char* kListingFile = "study_variants.json";

json read_json(const fs::path& f) {
  const std::string text = read_text(f);
  if (text.empty()) return nullptr;
  return json::parse(text, nullptr, /*allow_exceptions=*/false);  // discarded (an unfinished write) -> null
}

std::optional<double> number_at(const json& j, const json::json_pointer& p) {
  if (!j.contains(p) || !j.at(p).is_number()) return std::nullopt;
  return j.at(p).get<double>();
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string value_text(const json& v) { return v.is_number() ? format_round_trip(v.get<double>()) : v.is_string() ? v.get<std::string>() : v.dump(); }

std::string opt(const std::optional<double>& x) { return x ? format_round_trip(*x) : ""; }

}  // namespace

std::string refusal_field(const std::string& message) {
  const auto colon = message.find(": ");
  return colon == std::string::npos ? message : message.substr(0, colon);
}

std::vector<std::pair<std::string, std::optional<double>>> metric_columns(const Metrics& m) {
  return {{"solid_volume_mm3", m.solid_volume_mm3},
          {"coolant_volume_mm3", m.coolant_volume_mm3},
          {"min_wall_mm", m.min_wall_mm},
          {"min_rib_mm", m.min_rib_mm},
          {"hole_count", m.hole_count ? std::optional<double>(static_cast<double>(*m.hole_count)) : std::nullopt},
          {"build_s", m.build_s}};
}

const char* status_name(Status s) {
  switch (s) {
    case Status::kBuilt: return "built";
    case Status::kRefused: return "refused";
    case Status::kFailed: return "failed";
    case Status::kTimeout: return "timeout";
    case Status::kPending: break;
  }
  return "pending";
}

Status status_from_name(const std::string& s) {
  for (Status x : {Status::kBuilt, Status::kRefused, Status::kFailed, Status::kTimeout})
    if (s == status_name(x)) return x;
  return Status::kPending;
}

Metrics report_metrics(const json& r) {
  Metrics m;
  m.solid_volume_mm3 = number_at(r, "/solid/volume_mm3"_json_pointer);
  if (r.contains("timings_s") && r["timings_s"].is_object()) {
    double total = 0;
    for (const auto& t : r["timings_s"].items())
      if (t.value().is_number()) total += t.value().get<double>();
    m.build_s = total;
  }
  const json::json_pointer cooling("/model/cooling");
  if (!r.contains(cooling)) return m;
  const json& c = r.at(cooling);
  if (c.contains("thickness"))
    for (const json& t : c["thickness"]) {
      if (!t.contains("min_mm") || !t["min_mm"].is_number()) continue;
      const std::string f = t.value("feature", "");
      const double x = t["min_mm"].get<double>();
      const auto keep_min = [x](std::optional<double>& slot) { slot = slot ? std::min(*slot, x) : x; };
      if (f == "outer_wall") keep_min(m.min_wall_mm);
      if (f.rfind("rib_", 0) == 0) keep_min(m.min_rib_mm);
    }
  if (c.contains("passages")) {
    double coolant = 0;
    for (const json& p : c["passages"]) {
      coolant += p.value("volume_mm3", 0.0);
      Metrics::Passage ps{p.value("name", ""), 0, HUGE_VAL};
      int n = 0;
      for (const json& s : p.value("sections", json::array()))
        if (s.contains("hydraulic_diameter_mm") && s["hydraulic_diameter_mm"].is_number()) {
          const double dh = s["hydraulic_diameter_mm"].get<double>();
          ps.dh_mean_mm += dh, ps.dh_min_mm = std::min(ps.dh_min_mm, dh), ++n;
        }
      if (n > 0) ps.dh_mean_mm /= n, m.passages.push_back(ps);
    }
    m.coolant_volume_mm3 = coolant;
  }
  m.hole_count = c.contains("film") ? c["film"].value("hole_count", 0L) : 0L;
  return m;
}

void write_status(const fs::path& dir, const ResultRow& row) {
  json j{{"id", row.id}, {"status", status_name(row.status)}, {"exit_code", row.exit_code ? json(*row.exit_code) : json()},
         {"error", row.error}, {"input_hash", row.input_hash}, {"process_s", row.process_s ? json(*row.process_s) : json()}};
  write_text(dir / kStatusFile, j.dump(2) + "\n");
}

bool read_status(const fs::path& dir, ResultRow& row) {
  const json j = read_json(dir / kStatusFile);
  if (!j.is_object()) return false;
  row.status = status_from_name(j.value("status", ""));
  row.exit_code = j.contains("exit_code") && j["exit_code"].is_number_integer() ? std::optional<int>(j["exit_code"].get<int>()) : std::nullopt;
  row.error = j.value("error", "");
  row.input_hash = j.value("input_hash", "");
  row.process_s = j.contains("process_s") && j["process_s"].is_number() ? std::optional<double>(j["process_s"].get<double>()) : std::nullopt;
  return true;
}

json read_report(const fs::path& dir) { return read_json(dir / "report.json"); }

void write_listing(const fs::path& study_dir, const StudyListing& l) {
  json vs = json::array();
  for (const ResultRow& r : l.rows) {
    json v{{"id", r.id}, {"values", r.values}};
    if (r.status == Status::kRefused) v["refused"] = r.error;
    vs.push_back(v);
  }
  write_text(study_dir / kListingFile, json{{"study", l.name}, {"parameters", l.parameters}, {"variants", vs}}.dump(1) + "\n");
}

StudyListing read_listing(const fs::path& study_dir) {
  const fs::path f = study_dir / kListingFile;
  const json j = read_json(f);
  if (!j.is_object() || !j.contains("variants"))
    throw config::ConfigError("--collect: " + f.string() + " is missing or unreadable (run coolinggen sweep STUDY -o " + study_dir.string() + " first, or --emit slurm)");
  StudyListing l;
  l.name = j.value("study", "");
  l.parameters = j.value("parameters", std::vector<std::string>{});
  for (const json& v : j["variants"]) {
    ResultRow r;
    r.id = v.value("id", "");
    r.values = v.value("values", std::vector<json>{});
    if (v.contains("refused")) r.status = Status::kRefused, r.error = v["refused"].get<std::string>();
    l.rows.push_back(r);
  }
  return l;
}

void collect_rows(const fs::path& study_dir, StudyListing& l) {
  for (ResultRow& r : l.rows) {
    if (r.status == Status::kRefused) continue;
    const fs::path dir = study_dir / "variants" / r.id;
    const bool has_status = read_status(dir, r);
    const json report = read_report(dir);
    const bool report_matches = report.is_object() && (!has_status || report.value("input_hash", "") == r.input_hash);
    if (!has_status && report.is_object()) {  // built before status.json was written (e.g. killed right after)
      r.status = report.value("valid", false) ? Status::kBuilt : Status::kFailed;
      r.exit_code = report.value("valid", false) ? 0 : 3;
    }
    if (report_matches) r.metrics = report_metrics(report);
  }
}

std::map<Status, int> status_counts(const StudyListing& l) {
  std::map<Status, int> n;
  for (const ResultRow& r : l.rows) ++n[r.status];
  return n;
}

void write_results_csv(const fs::path& study_dir, const StudyListing& l) {
  std::vector<std::string> passages;  // the union over the variants, in order of first appearance
  for (const ResultRow& r : l.rows)
    for (const Metrics::Passage& p : r.metrics.passages)
      if (std::find(passages.begin(), passages.end(), p.name) == passages.end()) passages.push_back(p.name);
  std::ostringstream o;
  o << "id";
  for (const std::string& p : l.parameters) o << "," << csv_cell(p);
  o << ",status,exit_code,error";
  for (const auto& [name, value] : metric_columns(Metrics{})) o << "," << name;
  o << ",process_s";
  for (const std::string& p : passages) o << "," << csv_cell(p + "_dh_mean_mm") << "," << csv_cell(p + "_dh_min_mm");
  o << "\n";
  for (const ResultRow& r : l.rows) {
    const Metrics& m = r.metrics;
    o << r.id;
    for (const json& v : r.values) o << "," << csv_cell(value_text(v));
    o << "," << status_name(r.status) << "," << (r.exit_code ? std::to_string(*r.exit_code) : "") << "," << csv_cell(r.error);
    for (const auto& [name, value] : metric_columns(m)) o << "," << opt(value);
    o << "," << opt(r.process_s);
    for (const std::string& name : passages) {
      const auto it = std::find_if(m.passages.begin(), m.passages.end(), [&](const Metrics::Passage& p) { return p.name == name; });
      o << "," << (it == m.passages.end() ? "" : format_round_trip(it->dh_mean_mm)) << "," << (it == m.passages.end() ? "" : format_round_trip(it->dh_min_mm));
    }
    o << "\n";
  }
  write_text(study_dir / "results.csv", o.str());
}

void write_study_report(const fs::path& study_dir, const StudyListing& l) {
  std::ostringstream o;
  o << "# Study " << l.name << "\n\n" << l.rows.size() << " variants, parameters: ";
  for (std::size_t i = 0; i < l.parameters.size(); ++i) o << (i ? ", " : "") << "`" << l.parameters[i] << "`";
  o << "\n\n| status | variants |\n|---|---|\n";
  for (const auto& [s, n] : status_counts(l)) o << "| " << status_name(s) << " | " << n << " |\n";
  std::map<std::string, std::vector<const ResultRow*>> refusals;
  for (const ResultRow& r : l.rows)
    if (r.status == Status::kRefused) refusals[refusal_field(r.error)].push_back(&r);
  if (!refusals.empty()) {
    o << "\n## Refusals by field\n\n| field | variants | ids | first message |\n|---|---|---|---|\n";
    for (const auto& [field, rows] : refusals) {
      o << "| `" << field << "` | " << rows.size() << " | ";
      for (std::size_t i = 0; i < rows.size(); ++i) o << (i ? ", " : "") << rows[i]->id;
      std::string msg = rows.front()->error;
      std::replace(msg.begin(), msg.end(), '|', '/');
      o << " | " << msg << " |\n";
    }
  }
  bool header = false;
  for (const ResultRow& r : l.rows) {
    if (r.status != Status::kFailed && r.status != Status::kTimeout) continue;
    if (!header) o << "\n## Failures and timeouts\n\n| id | status | exit code | error |\n|---|---|---|---|\n", header = true;
    std::string msg = r.error;
    std::replace(msg.begin(), msg.end(), '|', '/');
    o << "| " << r.id << " | " << status_name(r.status) << " | " << (r.exit_code ? std::to_string(*r.exit_code) : "-") << " | " << msg << " |\n";
  }
  write_text(study_dir / "study_report.md", o.str());
}

}  // namespace cg::study
