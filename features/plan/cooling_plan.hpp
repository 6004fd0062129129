#pragma once
// The planning stage: every placement of the cooling features that the build knows before its first
// boolean, from the blade model and the feature definitions alone, and every check that needs no
// boolean run on it, in this order (cheaper parts first). `coolinggen validate` is the plan;
// `coolinggen build` is the plan, then the booleans (src/pipeline/build.hpp) on what the plan placed
// (the core's walls and turnaround ends, the film cavity and every film hole: build_passages and
// build_film_cooling take them, nothing is placed twice), so what the plan refuses the build refuses,
// naming the same field:
//  - passages: the definition checks (validate_passages: ribs on five spans, every turnaround end
//    placed by its gap against its end wall (a gap the span cannot take), inlet sizes, wall features'
//    definitions, trailing-edge placement), before any fit;
//  - core (build_core_walls): the inner wall, the closed end walls and the chambers' chordwise extents;
//  - film (plan_film on film_cavity_of_core): each insert's chamber and input, the reach an insert
//    leaves the hole tools, every film and showerhead hole placed on its row with its axis, exit, the
//    wall it crosses and the chamber it reaches, its tool extent, and the ligaments to the ribs (mid-surface
//    +- thickness / 2 and the fillets' width), to the end walls and to the other holes.
//  - turbulators (build_turbulators' placement on those walls): spans, ends between the ribs' fillets,
//    height against the chamber (the tools and their volumes are the build's);
//  - trailing edge (plan_trailing_edge on those walls): the slots' layout between the end walls, each
//    slot's lip, floor and inlet station in the last chamber, the walls left beside it, its widths; the
//    pins' stations clear of the last rib and their axes across the chamber;
// What the plan leaves to the build (the turbulator, pin and slot tools, which cost seconds to make, with
// their volume quadratures, which also find a slot channel leaving the blade early or a pin not ending in
// both walls, and film holes against those tools; the inlets' rims in their chambers; the
// booleans with their volume checks; the design checks on the built solid; the inserts' offsets) is
// listed in docs/verification.md with its cost.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "features/film/film_cooling.hpp"
#include "features/film/film_definition.hpp"
#include "features/passages/core_passages.hpp"
#include "features/passages/passage_definition.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/turbulators.hpp"
#include "src/blade/blade_surface.hpp"

namespace cg::features {

struct CoolingPlan {
  /// The passages as planned: the definition given, or with the wall thickened toward the TE where a
  /// cutback's lip would lie over the last chamber (wall/cutback_wall.hpp). What the build builds.
  PassagesDefinition passages;
  /// What the plan changed in the definition, one line each (the report's warnings, `validate`'s output).
  std::vector<std::string> notes;
  /// The core's walls, chambers and turnaround ends (build_core_walls; no cells, no solid); none
  /// without a core.
  std::optional<CoreBuild> core;
  /// Every turbulator placed on the planned walls (span, ends between the ribs' fillets, height against
  /// the chamber; build_turbulators' placement, no tools).
  std::vector<TurbulatorInfo> turbulators;
  /// The trailing edge's slots and pins placed on the planned walls (plan_trailing_edge: layout, lip,
  /// floor, inlet station, widths; pins' stations clear of the last rib, axes and lengths; no tools):
  /// the cooling stage builds their tools where they are.
  TrailingEdgePlan trailing_edge;
  /// The film cavity of the planned core (hole target with its chambers' reach limited by the inserts,
  /// the inserts' chambers) and the inserts' chambers and film holes analysed against it; none without
  /// film input or without a core. The film stage builds on both (build_film_cooling).
  std::optional<FilmCavity> film_cavity;
  std::optional<FilmPlan> film;
  /// Seconds per part ("passages", "core", "film", "wall_features").
  std::vector<std::pair<std::string, double>> seconds;
};

/// Plans `passages` and `film` on `model` (which the result points to: it must outlive it). A
/// pressure-side cutback whose lip would lie over the last chamber (LipOverChamber) is planned again on
/// the wall thickened toward the TE (wall_for_cutback), when that helps: the plan's `passages` and
/// `notes` say so. Throws PassageInputError or FilmInputError naming the field below "cooling".
CoolingPlan plan_cooling(const blade::BladeModel& model, const PassagesDefinition& passages, const FilmCoolingDefinition& film);

}  // namespace cg::features
