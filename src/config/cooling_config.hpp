#pragma once
// The "cooling" section of the configuration (data/schema/coolinggen.schema.json): parsing into the
// feature definitions (features/passages/passage_definition.hpp) with field-path errors. The pipeline builds them
// (src/pipeline/cooling.hpp).
//
// Layout (each feature area adds its own key under "cooling"; unknown keys are errors):
//   "cooling": {
//     "core": {...},             internal passages: wall, end walls, ribs, turnarounds, inlets
//     "radial_passages": ...     straight passages through the span (C3X-type vanes)
//     "film_rows", "showerhead", "inserts", "film_limits": film cooling and impingement
//                                (cooling_film_config.hpp)
//   }
// Errors that need the blade (a rib outside the core, ribs closer than their thickness, a wall too thick
// for the blade, an inlet that does not fit ...) are found when the features are built and reported as
// ConfigError with the same "cooling.<...>" paths and the span / chord where they fail (cooling_error).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/passages/passage_definition.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/config/config_error.hpp"
#include "src/config/json_fields.hpp"

namespace cg::config {

struct CoolingConfig {
  features::PassagesDefinition passages;  ///< "core" and "radial_passages"
  features::FilmCoolingDefinition film;   ///< "film_rows", "showerhead", "inserts", "film_limits"
  std::vector<std::string> source_files;  ///< table files read (resolved paths), for the input hash
  bool empty() const { return passages.empty() && film.empty(); }
};

/// Parses the "cooling" object at `f` (relative files resolved against base_dir). Throws ConfigError.
CoolingConfig parse_cooling(const Field& f, const std::filesystem::path& base_dir);

/// The ConfigError for passage input the blade cannot take: "cooling.<field>: <what, where>".
ConfigError cooling_error(const features::PassageInputError& e);

}  // namespace cg::config
