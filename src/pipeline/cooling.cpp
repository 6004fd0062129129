#include "src/pipeline/cooling.hpp"

#include "features/film/film_cavity.hpp"
#include "features/film/film_prechecks.hpp"
#include "features/film/film_rows.hpp"
#include "src/config/cooling_film_config.hpp"

namespace cg::pipeline {

void validate_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model) {
  try {
    features::validate_passages(model, cooling.passages);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  }
  try {
    if (cooling.film.empty()) return;
    std::vector<features::HoleSpec> holes;
    if (cooling.film.has_holes()) holes = features::place_film_holes(model, cooling.film);  // ms: rows on the outer wall
    const auto& core = cooling.passages.core;
    features::check_film_definition(model, core ? &*core : nullptr, cooling.film, holes);
  } catch (const features::FilmInputError& e) {
    throw config::film_error(e);
  }
}

features::PassagesResult apply_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const brep::NamedShape& blade, features::Verification verification) {
  try {
    return features::build_passages(model, blade, cooling.passages, verification);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  }
}

features::FilmCoolingResult apply_film(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const features::PassagesResult& cooled,
                                       const features::FeatureOptions& options) {
  if (!cooled.core || !cooling.passages.core)
    throw config::ConfigError("cooling: film rows, a showerhead and inserts need \"core\": the chambers they feed from or sit in");
  try {
    features::FilmCavity cavity = features::film_cavity_of_core(model, *cooling.passages.core, *cooled.core);
    features::add_wall_feature_obstacles(cavity.target, cooled.wall_features);
    return features::build_film_cooling(model, cooled.blade, std::move(cavity), cooling.film, options);
  } catch (const features::FilmInputError& e) {
    throw config::film_error(e);
  }
}

}  // namespace cg::pipeline
