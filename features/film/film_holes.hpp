#pragma once
// Film holes end to end: placed holes (film_rows.hpp) analysed against the wall (hole_analysis.hpp),
// made into named tool solids with their independent expected volumes (hole_tool.hpp), checked against
// each other (ligaments), cut through the verified boolean path in one step, and reported per hole, per
// row and per chamber (film_report.hpp).
//
// Ligament between two holes: each hole's part between the outer and the cavity wall is enclosed in a
// chain of balls along its axis (radius: the cross-section's circumradius there; exact for cylinders);
// the ligament is the least distance between the two chains' capsules (segment-segment distance,
// Ericson, Real-Time Collision Detection 5.1.9) minus the radii: a lower bound of the metal between them,
// exact for parallel cylinders. Candidate pairs come from a sweep over the chains' bounding boxes.
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/film_report.hpp"
#include "features/film/hole_analysis.hpp"
#include "features/film/hole_target.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/progress.hpp"

namespace cg::features {

struct FilmHoleTools {
  std::vector<HoleSpec> holes;
  std::vector<HoleGeometry> geometry;  ///< per hole
  std::vector<FeatureTool> tools;      ///< per hole: faces all named after the hole
  std::vector<double> ligament;        ///< per hole, mm to the nearest other hole (infinity: none near)
  std::vector<std::string> ligament_to;
};

/// Analyses every hole (hole_analysis.hpp) and checks the ligaments between them, without making tools
/// (`tools` stays empty): the film holes' part of the plan (features/plan/cooling_plan.hpp), which needs
/// the hole target and no solid. Throws FilmInputError as make_film_hole_tools.
FilmHoleTools analyse_film_holes(const HoleTarget& target, const std::vector<HoleSpec>& holes, const FilmLimits& limits,
                                 const HoleQuadrature& quadrature = {});

/// analyse_film_holes, then every hole's tool. Throws FilmInputError (field + hole) for a hole that does not
/// fit (hole_analysis.hpp) and for two holes closer than limits.min_ligament: within a row (field
/// "<row>.pitch_d" or ".count") or between rows ("overlapping rows", field "<later row>.chord" / ".arc_length").
FilmHoleTools make_film_hole_tools(const HoleTarget& target, const std::vector<HoleSpec>& holes, const FilmLimits& limits,
                                   const HoleQuadrature& quadrature = {});

/// The analysed `holes` against further obstacles (check_hole_obstacle, hole by hole): how the build
/// checks the planned holes against the obstacles it learns only from their tools (turbulators, pins,
/// slots: film_cavity.hpp), without placing or analysing them again. Throws FilmInputError.
void check_film_holes_against(FilmHoleTools& holes, const std::vector<TargetObstacle>& obstacles, const FilmLimits& limits);

/// The tool of every analysed hole of `holes` (into holes.tools, one per hole).
void add_hole_tools(FilmHoleTools& holes);

/// Least ligament between the hole envelopes of two analysed holes (see the header comment), mm.
double hole_ligament(const HoleGeometry& a, const HoleGeometry& b);

struct FilmCutResult {
  brep::NamedShape blade;
  FilmReport report;
  brep::SolidCheck check;  ///< verify_solid of the result (run by the boolean step), when `checked`
  /// false: every hole was drilled directly (checked locally, drill_holes.hpp); the build's verify
  /// stage runs verify_solid on the result.
  bool checked = false;
};

/// Options of the film holes' boolean step: the volume tolerance of the step's per-tool check is
/// 1e-6 relative plus 1e-6 mm^3 by default; the quadrature is converged far below that (tests).
BooleanOptions film_boolean_options(ProgressSink* progress = nullptr);

/// Cuts the holes from `blade` and fills the report (measured volumes): straight square-ended cylinders
/// by direct drilling (drill_holes.hpp, local checks, fallback to the boolean step), the others (shaped
/// holes, oblique ends) in one verified boolean step. Throws FeatureFailure naming the holes that failed.
FilmCutResult cut_film_holes(const brep::NamedShape& blade, const HoleTarget& target, const FilmHoleTools& tools,
                             const BooleanOptions& options);

}  // namespace cg::features
