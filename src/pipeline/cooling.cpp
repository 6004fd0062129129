#include "src/pipeline/cooling.hpp"

#include "features/film/film_cavity.hpp"
#include "src/config/cooling_film_config.hpp"

namespace cg::pipeline {

namespace {

void check_film_has_core(const config::CoolingConfig& cooling) {
  if (!cooling.film.empty() && !cooling.passages.core)
    throw config::ConfigError("cooling: film rows, a showerhead and inserts need \"core\": the chambers they feed from or sit in");
}

}  // namespace

features::CoolingPlan plan_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model) {
  check_film_has_core(cooling);
  try {
    return features::plan_cooling(model, cooling.passages, cooling.film);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  } catch (const features::FilmInputError& e) {
    throw config::film_error(e);
  }
}

features::PassagesResult apply_cooling(const blade::BladeModel& model, const features::CoolingPlan& plan, const brep::NamedShape& blade,
                                       features::Verification verification) {
  try {
    return features::build_passages(model, blade, plan.passages, plan.core, plan.trailing_edge, verification);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  }
}

features::FilmCoolingResult apply_film(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const features::CoolingPlan& plan, const features::PassagesResult& cooled,
                                       const features::FeatureOptions& options) {
  check_film_has_core(cooling);
  require(cooled.core != nullptr && plan.film && plan.film_cavity, "film stage: no core was built or no film planned");
  try {
    features::FilmPlan film = *plan.film;
    features::check_film_holes_against(film.holes, features::wall_feature_obstacles(cooled.wall_features), cooling.film.limits);
    return features::build_film_cooling(model, cooled.blade, *plan.film_cavity, std::move(film), cooling.film, options);
  } catch (const features::FilmInputError& e) {
    throw config::film_error(e);
  }
}

}  // namespace cg::pipeline
