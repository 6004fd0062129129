#pragma once
// report.json: what was built, from what, and whether every check passed. Written atomically.
// Layout (units mm, mm^2, mm^3, deg, seconds; keys in this order):
//   { "generator": "coolinggen", "version": "0.1.0", "input_hash": "sha256:...", "valid": bool,
//     "units": {...}, "model": <caller's model info>,
//     "solid": { "volume_mm3", "volume_error_mm3", "surface_area_mm2", "bbox_mm": {"min", "max", "size"},
//                "face_count", "solid_count", "faces": {name: count}, "mesh_triangles" },
//     "checks": { name: {"passed": bool, "message": str} }, "warnings": [str], "timings_s": {stage: s},
//     "threads": the most threads the job computed on (--threads, src/core/parallel.hpp),
//     "outputs": [file names written with this report, report.json included],
//     "bodies": [{"name", "valid", "volume_mm3", "surface_area_mm2", "face_count", "faces"}] (every body,
//                blade first; added by the pipeline), then the pipeline's other sections }
// "outputs" makes the report the index of its directory (src/pipeline/output_directory.hpp).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "src/brep/verify.hpp"

namespace cg::io {

struct ReportContent {
  std::string version;                         ///< tool version
  std::string input_hash;                      ///< fingerprint of the inputs ("sha256:...")
  brep::SolidCheck check;
  std::map<std::string, int> face_names;       ///< face name -> number of faces with it
  std::vector<std::string> warnings;           ///< e.g. general-fuse alerts
  nlohmann::ordered_json model = nlohmann::ordered_json::object();  ///< caller's model description
  nlohmann::ordered_json timings_s = nlohmann::ordered_json::object();  ///< stage -> seconds, in run order
  int threads = 1;                             ///< the job's thread budget (parallel_workers), for its timings
  std::vector<std::string> outputs;            ///< files written with the report
  /// Further top-level sections, appended after "outputs" in order (e.g. "sections": the passage table
  /// along span, "notes": outputs skipped and why, "mesh": mesh statistics).
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();
};

nlohmann::ordered_json report_json(const ReportContent& content);

/// report.json's "solid" object of a check (with `faces`, name -> count) and its "checks" object;
/// solid_check_of reads both back: the one serialisation of a SolidCheck (the stage cache stores its
/// checks this way). A check's seconds are not in the report (read back as 0); a NaN is null there and
/// NaN again when read. Throws std::runtime_error (nlohmann's) on a malformed object.
nlohmann::ordered_json solid_json(const brep::SolidCheck& check, const std::map<std::string, int>& faces);
nlohmann::ordered_json checks_json(const brep::SolidCheck& check);
brep::SolidCheck solid_check_of(const nlohmann::ordered_json& solid, const nlohmann::ordered_json& checks);

/// Writes report_json(content), pretty-printed, through write_atomically. Throws ExportError.
void write_report(const std::filesystem::path& file, const ReportContent& content);

}  // namespace cg::io
