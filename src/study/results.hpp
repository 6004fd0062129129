#pragma once
// What a study knows about each variant, and the files that show it:
//   DIR/variants/<id>/status.json  the variant's status, exit code, one-line error and input hash
//                                  (written when its process ends, or when it is refused)
//   DIR/study_variants.json        the study's parameters and variants (what --collect reads)
//   DIR/results.csv                one row per variant: id, parameters, status, exit code, error and
//                                  the metrics of its report.json (atomic: temp file + rename)
//   DIR/study_report.md            status counts, refusals grouped by field, failures
//   DIR/study_report.html          the same with plots (study_html.hpp)
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cg::study {

/// "built" (exit 0, report.json valid), "refused" (invalid config, no process or exit 2), "failed"
/// (exit 3, 4, 5 or a signal), "timeout" (--timeout: exit 6 or killed), "pending" (not run yet).
enum class Status { kPending, kBuilt, kRefused, kFailed, kTimeout };
const char* status_name(Status s);
Status status_from_name(const std::string& s);

/// The report metrics of one variant (empty optionals: not in its report).
struct Metrics {
  std::optional<double> solid_volume_mm3, coolant_volume_mm3, min_wall_mm, min_rib_mm, build_s;
  std::optional<long> hole_count;
  struct Passage {
    std::string name;
    double dh_mean_mm = 0, dh_min_mm = 0;
  };
  std::vector<Passage> passages;
};

/// Metrics of a report.json document (pipeline/report.cpp, features/passage_report, film_report).
Metrics report_metrics(const nlohmann::json& report);
/// The scalar metrics by column name, in the order of results.csv (none: not in the report).
std::vector<std::pair<std::string, std::optional<double>>> metric_columns(const Metrics& metrics);

struct ResultRow {
  std::string id;
  std::vector<nlohmann::json> values;
  Status status = Status::kPending;
  std::optional<int> exit_code;
  std::string error;
  std::string input_hash;
  std::optional<double> process_s;  ///< wall time of the variant's process (none: no process ran)
  Metrics metrics;
};

/// status.json of a finished or refused variant.
void write_status(const std::filesystem::path& variant_dir, const ResultRow& row);
/// The row's status, exit code, error and hash from status.json (false: none there).
bool read_status(const std::filesystem::path& variant_dir, ResultRow& row);
/// report.json of the variant, or null when absent or unreadable.
nlohmann::json read_report(const std::filesystem::path& variant_dir);

struct StudyListing {
  std::string name;
  std::vector<std::string> parameters;
  std::vector<ResultRow> rows;  ///< id, values; refused ones with status and error
};
void write_listing(const std::filesystem::path& study_dir, const StudyListing& listing);
/// Throws config::ConfigError when DIR has no readable study_variants.json.
StudyListing read_listing(const std::filesystem::path& study_dir);

/// Writes DIR/results.csv atomically.
void write_results_csv(const std::filesystem::path& study_dir, const StudyListing& listing);
/// Writes DIR/study_report.md atomically.
void write_study_report(const std::filesystem::path& study_dir, const StudyListing& listing);
/// The field a refusal names: its message up to the first ": " ("cooling.core.ribs[0].thickness").
std::string refusal_field(const std::string& message);

/// Fills the rows of `listing` that are not refused from DIR/variants/<id>/ (status.json, report.json):
/// what `sweep --collect` merges.
void collect_rows(const std::filesystem::path& study_dir, StudyListing& listing);

/// Counts per status.
std::map<Status, int> status_counts(const StudyListing& listing);

}  // namespace cg::study
