#pragma once
// The cooling stage of a build: the configured cooling features ("cooling" in the config) built into the
// blade solid (features/passages.hpp). Input the blade cannot take becomes ConfigError naming the field
// below "cooling" (cooling_config.hpp); failed booleans and design checks stay features::FeatureFailure.
#include "features/passages.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/config/cooling_config.hpp"

namespace cg::pipeline {

/// The cooling checks that need the blade model but no solid (features::validate_passages), as ConfigError.
void validate_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model);

features::PassagesResult apply_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const brep::NamedShape& blade);

}  // namespace cg::pipeline
