#pragma once
// Film-hole rows and the showerhead placed on the blade in blade-relative coordinates (hole frames
// for hole_analysis.hpp).
//
// Placement of a row: the row curve is the curve on the outer wall at the row's chordwise position
// (a constant chordwise coordinate, or a constant surface arc length from the LE measured along the
// section at each span) from span_start to span_end. Holes are spaced evenly in arc length along it:
// `count` holes one per cell of length/count, or holes at pitch P = pitch_d D centred in the range;
// `stagger` then shifts them along the row by a fraction of the pitch (holes pushed past the end of
// the range are left out).
//
// Hole axis at a hole (exit point on the outer wall, outward normal n): streamwise direction e_s =
// the surface direction LE -> TE normal to the span (BladeFrame::chord_tangent, reversed on the pressure
// side), e_p = the surface direction normal to e_s towards the tip. The axis' projection on the surface
// p = cos(beta) e_s + sin(beta) e_p (beta the compound angle), the coolant leaves along
// f = cos(alpha) p + sin(alpha) n (alpha the inclination), and the axis into the wall is d = -f. The
// laidback side of a shaped hole is e_f = sin(alpha) p - cos(alpha) n (normal to d, towards the
// downstream surface).
// Showerhead: rows at surface arc lengths stagnation_arc + (k - (n + 1) / 2) row_spacing_d D (k = 1 the
// most pressure-side row), alternate rows staggered by half the pitch, each hole in the plane of the
// span direction and n at the radial angle gamma to the span direction: f = cos(gamma) (+-e_span) +
// sin(gamma) n, e_span the surface direction towards the tip (towards the hub if !toward_tip).
#include <map>
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/hole_analysis.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {

/// Chordwise coordinate of a row position at a span. Arc lengths are exact: the chordwise coordinate is
/// the arc-length fraction of the side on the section at that span (src/blade/span_section.hpp), so
/// arc = chord * side length. Side lengths are cached by span.
class RowPositioner {
 public:
  explicit RowPositioner(const blade::BladeCoordinates& coords) : coords_(&coords) {}
  /// Throws InvalidGeometry for an arc length beyond the TE.
  double chord(const RowPosition& position, double span);
  /// Suction- and pressure-side arc lengths of the section at `span`, mm.
  std::pair<double, double> side_lengths(double span);

 private:
  const blade::BladeCoordinates* coords_;
  std::map<double, std::pair<double, double>> cache_;
};

/// The holes of every row and of the showerhead, named film_row_<k>_hole_<nnn> (k = 1-based index in
/// `rows`) and showerhead_<k>_hole_<nnn> (k = showerhead row, pressure side first), numbered from the
/// hub. Throws FilmInputError (field below "cooling") for a row outside the blade's span, a position
/// beyond the TE, a pitch below the diameter.
std::vector<HoleSpec> place_film_holes(const blade::BladeModel& model, const FilmCoolingDefinition& def);

/// The holes of one row (used by place_film_holes and the benches): `row_number` names it
/// film_row_<row_number>, `field` is its config path for errors.
std::vector<HoleSpec> place_row(const blade::BladeCoordinates& coords, RowPositioner& positioner,
                                const FilmRowDefinition& row, int row_number, const std::string& field);

/// The holes of a showerhead.
std::vector<HoleSpec> place_showerhead(const blade::BladeCoordinates& coords, RowPositioner& positioner,
                                       const ShowerheadDefinition& sh, const std::string& field);

}  // namespace cg::features
