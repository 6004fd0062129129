#pragma once
// Hole fields for measuring and testing direct drilling (bench/bench_holes.cpp,
// tests/features/test_drill_*.cpp): N straight film holes on a cooled blade, from the outer wall
// through into the chambers, placed where every hole's exit lies on a chamber wall (not on a rib or
// fillet) -- what a film-row layout does. The film-cooling feature places real rows; this is a
// work load, not a design tool.
#include <string>
#include <vector>

#include "features/drilling/drill_holes.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct FilmFieldOptions {
  int count = 100;
  double diameter = 0.5;        ///< mm
  double inclination_deg = 30;  ///< between the axis and the surface, streamwise
  double clearance = 0.3;       ///< mm: the tool starts and ends this far (along the normal) off the walls
  double span_min = 0.12, span_max = 0.88;
  double chord_min = 0.08, chord_max = 0.92;  ///< chordwise band searched on each side
  double ring_margin = 0.15;    ///< mm: the exit ring r + margin must lie on one chamber wall face
  double min_row_gap = 0.4;     ///< mm between the footprints of neighbouring rows (along the surface)
  double min_pitch = 1.2;       ///< mm, smallest spanwise pitch
  std::string name_prefix = "film_row_";
};

/// `count` holes named <prefix><row>_hole_<nnn> in staggered rows on both sides of `part` (the cooled
/// blade of `model`: faces blade_wall and chamber_<k>_wall). Rows go where the exit lies on a chamber
/// wall over the whole span range. Throws InvalidGeometry when the chambers leave room for fewer holes.
std::vector<CylindricalHole> film_hole_field(const blade::BladeModel& model, const brep::NamedShape& part,
                                             const FilmFieldOptions& options);

/// The holes of cylinder tools made by make_hole_tools (boolean_sample_part.hpp): axis from the
/// tool's symmetry axis, length and diameter from its faces.
std::vector<CylindricalHole> holes_of_tools(const std::vector<FeatureTool>& tools);

}  // namespace cg::features
