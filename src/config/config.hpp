#pragma once
// The CoolingGen configuration file (JSON, units mm and degrees), documented field by field in
// data/schema/coolinggen.schema.json. Parsing checks types, ranges and unknown keys and produces
// the blade model's definition structs; build_model() then runs the model's own checks
// (streamlines that cross, stations that miss a streamline, impossible sections), reporting every
// failure as ConfigError with the field's path.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "export/step_writer.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/config/config_error.hpp"
#include "src/config/cooling_config.hpp"

namespace cg::config {

struct OutputOptions {
  io::StepSchema step_schema = io::StepSchema::AP214;
  std::string product_name;  ///< name of the product in the STEP file (default: the config's name)
};

struct Config {
  std::string name;         ///< "name", or the config file's stem
  std::string description;  ///< "description" (optional)
  blade::BladeDefinition blade;
  OutputOptions output;
  CoolingConfig cooling;    ///< "cooling" (optional; empty = an uncooled blade)
  nlohmann::json source;    ///< the parsed document (for the report)
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
blade::BladeModel build_model(const Config& config);

/// A small model description for the report: name, flow path type, section count and kinds, options.
nlohmann::json model_summary(const Config& config, const blade::BladeModel& model);

}  // namespace cg::config
