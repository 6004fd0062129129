#include "features/plan/cooling_plan.hpp"

#include <chrono>

#include "features/film/film_cavity.hpp"
#include "features/film/film_prechecks.hpp"
#include "features/film/film_rows.hpp"
#include "features/internal_cooling.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/turbulators.hpp"

namespace cg::features {

CoolingPlan plan_cooling(const blade::BladeModel& model, const PassagesDefinition& passages, const FilmCoolingDefinition& film) {
  CoolingPlan plan;
  auto t0 = std::chrono::steady_clock::now();
  const auto lap = [&](const char* part) {
    const auto t = std::chrono::steady_clock::now();
    plan.seconds.emplace_back(part, std::chrono::duration<double>(t - t0).count());
    t0 = t;
  };
  validate_passages(model, passages);
  const CoreDefinition* core = passages.core ? &*passages.core : nullptr;
  if (!film.empty()) {
    // The definition checks first: their messages say what to change in the definition's own terms.
    const std::vector<HoleSpec> holes = film.has_holes() ? place_film_holes(model, film) : std::vector<HoleSpec>();
    check_film_definition(model, core, film, holes);
  }
  lap("passages");
  if (!core) return plan;
  plan.core = build_core_walls(model, *core);
  lap("core");
  // The film before the wall features: it needs only the core and costs a fraction of the trailing
  // edge's placement, so a design it refuses is refused sooner (the order decides nothing else).
  if (!film.empty()) {
    plan.film_cavity = film_cavity_of_core(model, *core, *plan.core);
    plan.film = plan_film(model, *plan.film_cavity, film);
    lap("film");
  }
  if (!core->turbulators.empty() || core->trailing_edge) {
    WallLines lines(model.surface, plan.core->inner_wall.surface);
    plan.turbulators = build_turbulators(model, *core, *plan.core, lines, TurbulatorOutput::kPlacement).turbulators;
    plan.trailing_edge = plan_trailing_edge(model, *core, *plan.core, lines);
    lap("wall_features");
  }
  return plan;
}

}  // namespace cg::features
