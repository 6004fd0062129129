#include "features/plan/cooling_plan.hpp"

#include <chrono>
#include <exception>

#include "features/film/film_cavity.hpp"
#include "features/film/film_prechecks.hpp"
#include "features/film/film_rows.hpp"
#include "features/internal_cooling.hpp"
#include "features/wall/cutback_wall.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/turbulators.hpp"
#include "src/core/format.hpp"

namespace cg::features {

namespace {

CoolingPlan plan_as_defined(const blade::BladeModel& model, const PassagesDefinition& passages, const FilmCoolingDefinition& film) {
  CoolingPlan plan;
  plan.passages = passages;
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

// What a refusal of the plan on the wall thickened for a cutback adds, so that the user knows the wall it
// speaks of is not the one given.
std::string thickened_note(const CutbackWall& wall) {
  return " (planned on the wall thickened toward the TE to at most " + format_number(wall.max_thickness) +
         " mm for the cutback, whose lip would lie over the last chamber of the given wall)";
}

}  // namespace

CoolingPlan plan_cooling(const blade::BladeModel& model, const PassagesDefinition& passages, const FilmCoolingDefinition& film) {
  try {
    return plan_as_defined(model, passages, film);
  } catch (const LipOverChamber& e) {
    // The lip over the last chamber: planned again on the wall thickened toward the TE. Should a slot
    // between its nodes still find the lip over the chamber, the first refusal is the one to act on.
    const std::exception_ptr refusal = std::current_exception();
    std::string why_not;
    const std::optional<CutbackWall> wall = wall_for_cutback(model, *passages.core, why_not);
    if (!wall && !why_not.empty()) throw LipOverChamber(e.field(), std::string(e.what()) + "; " + why_not);
    if (!wall) throw;
    PassagesDefinition thickened = passages;
    thickened.core->wall_thickness = wall->wall_thickness;
    try {
      CoolingPlan plan = plan_as_defined(model, thickened, film);
      plan.notes.push_back(wall->note);
      return plan;
    } catch (const LipOverChamber&) {
      std::rethrow_exception(refusal);
    } catch (const PassageInputError& other) {  // refused on the thickened wall: say it was
      throw PassageInputError(other.field(), std::string(other.what()) + thickened_note(*wall));
    } catch (const FilmInputError& other) {
      throw FilmInputError(other.field(), std::string(other.what()) + thickened_note(*wall));
    }
  }
}

}  // namespace cg::features
