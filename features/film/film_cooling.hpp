#pragma once
// Film cooling and impingement end to end on a cooled blade: inserts built in their chambers
// (insert.hpp), film holes placed, analysed, checked and cut in one verified boolean step
// (film_rows.hpp, film_holes.hpp), inserts measured against the holed blade, one report.
//
// The features need the cavity the passages built: FilmCavity carries it (the hole target with its
// chambers and obstacles, and per chamber what an insert needs). A hole's tool may reach into a chamber
// with an insert no further than the insert's gap less a margin (max(0.05 mm, Z / 4)).
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/film_holes.hpp"
#include "features/film/film_report.hpp"
#include "features/film/hole_target.hpp"
#include "features/film/insert.hpp"
#include "src/brep/boolean/feature_options.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"

namespace cg::features {

struct FilmCavity {
  HoleTarget target;
  std::vector<InsertChamber> chambers;  ///< for inserts, one per chamber (any order; matched by number)
};

struct FilmCoolingResult {
  brep::NamedShape blade;                ///< with the film holes
  std::vector<brep::NamedBody> inserts;  ///< "insert_1", ...
  FilmReport report;
  brep::SolidCheck check;                ///< of the blade after the holes (verify_solid, run by the step)
  bool holes_cut = false;  ///< false: `blade` is the input blade, unchanged
  /// true: `check` is verify_solid of `blade` after its last step; false when holes were drilled after the
  /// last boolean step (checked locally, drill_holes.hpp): the build's verify stage checks the blade.
  bool blade_checked = false;
  std::vector<brep::SolidCheck> insert_checks;
};

/// What the film stage places before any solid: each insert's chamber (index into FilmCavity::chambers)
/// with its input checked (check_insert_input), and every film / showerhead hole placed on its row and
/// analysed against the cavity (the wall it crosses, the chamber it reaches, its tool extent, ligaments
/// to the obstacles and to the other holes; no tools yet).
struct FilmPlan {
  std::vector<std::size_t> insert_chambers;  ///< per insert of the definition
  FilmHoleTools holes;
};

/// The film plan on `cavity` (whose chambers' reach it limits by the inserts): the first part of
/// build_film_cooling, and all of it that needs no solid, so the planning stage
/// (features/plan/cooling_plan.hpp) runs the same code. Throws FilmInputError.
FilmPlan plan_film(const blade::BladeModel& model, FilmCavity& cavity, const FilmCoolingDefinition& def);

/// The film stage on its plan (`plan`: plan_film on `cavity`, as the planning stage made them; nothing
/// is placed again): the hole tools, inserts and booleans. Throws FilmInputError (field below "cooling")
/// for input the blade cannot take, FeatureFailure when a boolean or a check fails.
/// `cavity.target.model` must be `model`.
/// `options.verification` FinalOnly, None: the holes' boolean step skips verify_solid (as build_passages);
/// `options.progress`: progress and cancellation.
FilmCoolingResult build_film_cooling(const blade::BladeModel& model, const brep::NamedShape& blade, const FilmCavity& cavity,
                                     FilmPlan plan, const FilmCoolingDefinition& def, const FeatureOptions& options = {});

}  // namespace cg::features
