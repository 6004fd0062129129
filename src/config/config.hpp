#pragma once
// The CoolingGen configuration file (JSON, units mm and degrees), documented field by field in
// data/schema/coolinggen.schema.json. Parsing checks types, ranges and unknown keys and produces
// the blade model's definition structs; build_model() then runs the model's own checks
// (streamlines that cross, stations that miss a streamline, impossible sections), reporting every
// failure as ConfigError with the field's path.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/blade_import/import_options.hpp"
#include "src/blade_import/imported_blade.hpp"
#include "src/blade_import/section_table_reader.hpp"
#include "src/config/config_error.hpp"
#include "src/config/coolant_config.hpp"
#include "src/config/cooling_config.hpp"
#include "src/config/grid_config.hpp"
#include "src/config/output_format.hpp"
#include "src/core/progress.hpp"

namespace cg::config {

/// "output": plain options; the pipeline (src/pipeline/outputs.hpp) writes them.
struct OutputOptions {
  /// Model files to write (report.json is always written); default all (README, Outputs).
  std::vector<OutputFormat> formats = default_output_formats();
  std::string step_schema = "AP242";         ///< "AP214" | "AP242"
  std::string iges_mode = "faces";           ///< "faces" (144 trimmed surfaces) | "brep" (186 MSBO solids)
  std::string product_name;                  ///< name of the product in the STEP file (default: the config's name)
  double stl_deflection = 0.01;              ///< mm, chordal deflection of STL / VTK / preview triangles
  double stl_angular_deflection_deg = 20;    ///< deg
  std::vector<double> section_spans{0.1, 0.3, 0.5, 0.7, 0.9};  ///< spans of sections.svg and the passage table
};

/// "mesh": options of `coolinggen mesh` (plain; the pipeline hands them to src/mesh).
struct MeshConfig {
  double max_size = 1.5;                ///< mm
  double min_size = 0.05;               ///< mm
  int curvature_elements = 16;          ///< per 2 pi on every surface
  int feature_curvature_elements = 40;  ///< per 2 pi on the cooling-feature faces
  double size_growth = 0.3;            ///< size increase per mm away from those faces
  bool metal = true, coolant = true;    ///< "domains"
  bool msh = true, vtu = true, cgns = false;  ///< "formats" (default ["msh", "vtu"])
  bool group_by_face_name = false;      ///< "physical_groups": "face_name" (default "kind")
  int threads = 2;
  bool optimize = true;
};

/// Where a point section's points came from, so messages can speak of file lines (the model counts
/// points from 0).
struct PointSource {
  std::string field;       ///< "sections[2].points"
  std::string file;        ///< the file as read ("" for inline values)
  std::vector<int> lines;  ///< file line of each point (empty for inline values)
};

/// "blade.import": a blade designed by another tool (src/blade_import). The config reader reads the
/// file(s) (their syntax: a geomTurbo file or section table that is not one is refused naming its
/// line; a STEP / IGES file is only found readable); build_model (imported_model.hpp) cuts a STEP /
/// IGES file's faces at the flow path's stream surfaces into outlines (src/cad_import), makes the
/// section tables' sides, cuts the blade at the flow path's streamlines into point sections, builds the blade from them and measures it
/// against the file (the geometry checks: open or crossing sections, sections not reaching hub or
/// casing, fidelity beyond the tolerance).
struct BladeImport {
  std::string format = "geomturbo";  ///< "geomturbo" | "sections" | "step" | "iges" (read by build_model)
  std::string field = "blade.import.file";  ///< the field geometry errors name ("blade.import.files")
  std::vector<std::string> files;  ///< resolved paths (geomturbo: one)
  blade_import::ImportOptions options;
  std::shared_ptr<const blade_import::ImportedBlade> blade;  ///< geomturbo: as read
  std::vector<blade_import::SectionTable> tables;            ///< sections: as read, hub -> tip
  blade_import::TableFrame frame = blade_import::TableFrame::Xyz;
  int cuts = 0;  ///< stream-surface cuts = sections of the blade model (import_options.hpp)
};

struct Config {
  std::string name;         ///< "name", or the config file's stem
  std::string description;  ///< "description" (optional)
  blade::BladeDefinition blade;
  OutputOptions output;
  CoolingConfig cooling;    ///< "cooling" (optional; empty = an uncooled blade)
  /// "coolant" (optional): boundary conditions of the coolant flow network (src/network)
  std::optional<CoolantConfig> coolant;
  MeshConfig mesh;
  GridConfig grid;          ///< "grid" (structured grids around the sections; optional)
  /// One per section, in order; `field` is empty for parametric sections.
  std::vector<PointSource> point_sources;
  std::optional<BladeImport> blade_import;  ///< "blade.import" (then no "flow_path" and "sections")
  nlohmann::json source;    ///< the parsed document (for the report)
  std::string source_file;  ///< the config file read (empty when parsed from a document or text)
};

/// Parses a document. Relative section point files are resolved against `base_dir` and read here
/// (so a missing file is a config error). `default_name` is used when the document has no "name".
Config parse_config(const nlohmann::json& document, const std::filesystem::path& base_dir,
                    const std::string& default_name);
/// As parse_config, from JSON text. Syntax errors, duplicate keys and numbers beyond a double's range
/// are ConfigErrors naming `source_name` with line and column, or the duplicate key's path
/// (json_document.hpp).
Config parse_config_text(const std::string& text, const std::filesystem::path& base_dir,
                         const std::string& default_name, const std::string& source_name = "config");
/// Reads and parses a config file (base directory = the file's directory, default name = its stem).
/// A missing file, a directory or an unreadable file is a ConfigError saying which.
Config load_config_file(const std::filesystem::path& file);
/// Sections of the blade model: the config's, or an imported blade's cuts.
std::size_t section_count(const Config& config);

/// Builds the blade model from a parsed config; errors of the model are rethrown as ConfigError
/// naming the part of the config they come from ("flow_path", "sections[i]", "blade").
/// `progress` (optional) may stop it between its steps (Cancelled).
blade::BladeModel build_model(const Config& config, ProgressSink* progress = nullptr);

}  // namespace cg::config
