#pragma once
// The cooling stages of a build: the configured cooling features ("cooling" in the config) built into the
// blade solid: internal passages (features/internal_cooling.hpp), then film holes and impingement inserts against
// the core the passages built (features/film/film_cooling.hpp, film_cavity.hpp). Input the blade cannot take
// becomes ConfigError naming the field below "cooling" (cooling_config.hpp, cooling_film_config.hpp);
// failed booleans and design checks stay features::FeatureFailure.
#include "features/film/film_cooling.hpp"
#include "features/internal_cooling.hpp"
#include "features/plan/cooling_plan.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/boolean/feature_options.hpp"
#include "src/brep/named_shape.hpp"
#include "src/config/cooling_config.hpp"

namespace cg::pipeline {

/// The planning stage of the cooling features (features/plan/cooling_plan.hpp): every placement and
/// check that needs the blade model but no solid; its input errors as ConfigError. `model` must outlive
/// the result.
features::CoolingPlan plan_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model);

/// The passages of `plan` (plan_cooling on `model`) built into `blade`, as the plan took them
/// (`plan.passages`: the wall thickened toward the TE where the plan did). `verification`: see
/// features::build_passages.
features::PassagesResult apply_cooling(const blade::BladeModel& model, const features::CoolingPlan& plan, const brep::NamedShape& blade,
                                       features::Verification verification = features::Verification::EachStep);

/// The film stage: the film rows, showerhead and inserts of `cooling` built into `cooled` (the result of
/// apply_cooling, which must have built a core) on `plan`'s film cavity and holes; the planned holes are
/// checked against the turbulators, pins and slots `cooled` built. Film input the blade cannot take:
/// ConfigError. `options`: verification and progress (see features::build_film_cooling).
features::FilmCoolingResult apply_film(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const features::CoolingPlan& plan, const features::PassagesResult& cooled,
                                       const features::FeatureOptions& options = {});

}  // namespace cg::pipeline
