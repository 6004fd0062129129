#pragma once
// The study file of `coolinggen sweep` (JSON, data/schema/study.schema.json, docs/studies.md): a base
// config (inline or a path relative to the study file), parameters addressed by config field path, a
// design (full grid, Latin hypercube, CSV of overrides) and the outputs of each variant. Errors are
// config::ConfigError naming the study field and the allowed values, as for configs.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/config/output_format.hpp"
#include "src/study/field_path.hpp"

namespace cg::study {

struct Parameter {
  std::string name;   ///< "name", default the path; the column of results.csv and of a design CSV
  std::string field;  ///< "parameters[i]" (for messages)
  FieldPath path;
  ApplyMode mode = ApplyMode::kSet;
  std::vector<nlohmann::json> values;         ///< "values" (grid levels; Latin hypercube picks among them)
  std::optional<std::pair<double, double>> range;  ///< "range": [lo, hi]
  int levels = 0;                              ///< "levels" of a range in a grid (0: the design's)
  bool integer = false;                        ///< "integer": values rounded to whole numbers
};

enum class DesignKind { kGrid, kLatinHypercube, kCsv };

struct Design {
  DesignKind kind = DesignKind::kGrid;
  int levels = 3;                  ///< grid: points per range
  int samples = 0;                 ///< Latin hypercube
  std::uint64_t seed = 1;          ///< Latin hypercube
  int candidates = 20;             ///< Latin hypercube: draws, the one with the largest minimum distance wins
  std::filesystem::path csv_file;  ///< csv: resolved against the study file's directory
};

struct Study {
  std::string name;                 ///< "name", default the study file's stem
  std::filesystem::path file;       ///< the study file (absolute)
  nlohmann::json base;              ///< the base config document
  std::filesystem::path base_dir;   ///< where the base config's relative files are
  std::vector<Parameter> parameters;
  Design design;
  std::vector<config::OutputFormat> outputs;  ///< output formats of each variant (report.json always)
};

/// Reads and checks a study file: field paths that exist in the base config, ranges, the design.
/// Throws config::ConfigError naming the field.
Study load_study(const std::filesystem::path& file);

}  // namespace cg::study
