#pragma once
// The CoolingGen configuration file (JSON, units mm and degrees), documented field by field in
// data/schema/coolinggen.schema.json. Parsing checks types, ranges and unknown keys and produces
// the blade model's definition structs; build_model() then runs the model's own checks
// (streamlines that cross, stations that miss a streamline, impossible sections), reporting every
// failure as ConfigError with the field's path.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/config/config_error.hpp"
#include "src/config/grid_config.hpp"
#include "src/core/progress.hpp"

namespace cg::config {

/// "output": plain options; the pipeline (src/pipeline/outputs.hpp) checks the format names and writes.
struct OutputOptions {
  std::vector<std::string> formats{"step"};  ///< model files to write (report.json is always written)
  std::string step_schema = "AP214";         ///< "AP214" | "AP242"
  std::string product_name;                  ///< name of the product in the STEP file (default: the config's name)
};

struct Config {
  std::string name;         ///< "name", or the config file's stem
  std::string description;  ///< "description" (optional)
  blade::BladeDefinition blade;
  OutputOptions output;
  GridConfig grid;          ///< "grid" (structured grids around the sections; optional)
  nlohmann::json source;    ///< the parsed document (for the report)
  std::string source_file;  ///< the config file read (empty when parsed from a document or text)
};

/// Parses a document. Relative section point files are resolved against `base_dir` and read here
/// (so a missing file is a config error). `default_name` is used when the document has no "name".
Config parse_config(const nlohmann::json& document, const std::filesystem::path& base_dir,
                    const std::string& default_name);
/// As parse_config, from JSON text (syntax errors become ConfigError with line and column).
Config parse_config_text(const std::string& text, const std::filesystem::path& base_dir,
                         const std::string& default_name);
/// Reads and parses a config file (base directory = the file's directory, default name = its stem).
Config load_config_file(const std::filesystem::path& file);

/// Builds the blade model from a parsed config; errors of the model are rethrown as ConfigError
/// naming the part of the config they come from ("flow_path", "sections[i]", "blade").
/// `progress` (optional) may stop it between its steps (Cancelled).
blade::BladeModel build_model(const Config& config, ProgressSink* progress = nullptr);

}  // namespace cg::config
