#pragma once
// Internal cooling passages of a blade, end to end: core (chambers, ribs, fillets, turnarounds, inlets)
// and radial passages built as named tools (core_passages.hpp, radial_passages.hpp), applied to the blade
// (passage_boolean.hpp), then measured on the built solid (passage_checks.hpp).
#include <memory>
#include <optional>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_definition.hpp"
#include "features/passages/passage_report.hpp"
#include "features/wall/wall_features.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/boolean/feature_options.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"

namespace cg::features {


struct PassagesResult {
  brep::NamedShape blade;  ///< the cooled blade, every face named
  PassageReport report;
  brep::SolidCheck check;  ///< verify_solid of the cooled blade (run after the last boolean step), when `checked`
  bool checked = false;    ///< false: built with verify_solid deferred (see build_passages)
  WallFeatureBuild wall_features;  ///< turbulators, slots, pins: placement and boolean step reports
  /// The core's tools and geometry (inner wall, chambers, ribs, end walls) when a core was built: what
  /// later features (film holes, inserts: film_cavity.hpp) are placed against.
  std::shared_ptr<const CoreBuild> core;
};

/// The checks of build_passages that need no solid (definition, inner wall crossing, rib placement,
/// radial passages against the wall), in milliseconds. Throws PassageInputError.
void validate_passages(const blade::BladeModel& model, const PassagesDefinition& def);

/// Builds `def` into `blade` (the solid of `model`) from the core's walls and the trailing edge's
/// placement the plan made (`walls`: build_core_walls, required with a core; `trailing_edge`:
/// plan_trailing_edge; features/plan/cooling_plan.hpp). Throws PassageInputError for input that cannot be
/// built (field below "cooling" + where), FeatureFailure when a boolean or a design check fails (the
/// thickness minimums: measured on the built solid, must reach the configured values).
/// `verification` FinalOnly (or None): the boolean steps run their cheap checks and per-tool volume checks
/// but no verify_solid (BRepCheck, free edges, closed mesh: ~1 s each on the blade); the caller then
/// verifies the final solid once and, if that fails, builds again with it on to name the culprit.
PassagesResult build_passages(const blade::BladeModel& model, const brep::NamedShape& blade, const PassagesDefinition& def,
                              const std::optional<CoreBuild>& walls, const TrailingEdgePlan& trailing_edge,
                              Verification verification = Verification::EachStep);

}  // namespace cg::features
