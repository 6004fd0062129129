#pragma once
// report.json: what was built and whether every check passed. Written atomically.
// Layout (units mm, mm^2, mm^3, seconds):
//   { "generator": "coolinggen", "valid": bool, "units": {...}, "model": <caller's model info>,
//     "solid": { "volume_mm3", "volume_error_mm3", "surface_area_mm2", "bbox_mm": {"min", "max", "size"},
//                "face_count", "solid_count", "faces": {name: count}, "mesh_triangles" },
//     "checks": { name: {"passed": bool, "message": str} }, "warnings": [str], "timings_s": {stage: s} }
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "src/brep/verify.hpp"

namespace cg::io {

struct ReportContent {
  brep::SolidCheck check;
  std::map<std::string, int> face_names;       ///< face name -> number of faces with it
  std::vector<std::string> warnings;           ///< e.g. general-fuse alerts
  nlohmann::json model = nlohmann::json::object();      ///< caller's model description
  nlohmann::json timings_s = nlohmann::json::object();  ///< stage -> seconds
};

nlohmann::json report_json(const ReportContent& content);

/// Writes report_json(content), pretty-printed, through write_atomically. Throws ExportError.
void write_report(const std::filesystem::path& file, const ReportContent& content);

}  // namespace cg::io
