#pragma once
// The "cooling" section of the configuration (data/schema/coolinggen.schema.json): parsing with
// field-path errors, and the step that builds the configured features into the blade solid.
//
// Layout (each feature area adds its own key under "cooling"; unknown keys are errors):
//   "cooling": {
//     "core": {...},             internal passages: wall, end walls, ribs, turnarounds, inlets
//     "radial_passages": ...     straight passages through the span (C3X-type vanes)
//   }
// Errors that need the blade (a rib outside the core, ribs closer than their thickness, a wall too thick
// for the blade, an inlet that does not fit ...) are found when the features are built and reported as
// ConfigError with the same "cooling.<...>" paths and the span / chord where they fail.
#include <nlohmann/json.hpp>

#include <filesystem>

#include "features/passage_definition.hpp"
#include "features/passages.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/config/json_fields.hpp"

namespace cg::config {

struct CoolingConfig {
  features::PassagesDefinition passages;  ///< "core" and "radial_passages"
  bool empty() const { return passages.empty(); }
};

/// Parses the "cooling" object at `f` (relative files resolved against base_dir). Throws ConfigError.
CoolingConfig parse_cooling(const Field& f, const std::filesystem::path& base_dir);

/// Builds the configured cooling features into `blade` (the solid of `model`). Input that cannot be built
/// on this blade becomes ConfigError naming "cooling.<field>"; feature failures (booleans, design checks)
/// stay features::FeatureFailure.
features::PassagesResult apply_cooling(const CoolingConfig& cooling, const blade::BladeModel& model,
                                       const brep::NamedShape& blade);

}  // namespace cg::config
