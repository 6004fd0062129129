#pragma once
// Writing the outer blade (the wall surface, before any cooling) and its channel as a geomTurbo file,
// for the aero and main-flow CFD side (AutoGrid / TurboGrid users) and for a round trip back into
// blade.import. Millimetres. Annular rows: the CHANNEL's hub and shroud are the model's hub and casing
// contours (zrcurve, z = x), the sections are iso-curves of the wall at evenly spaced spans from
// -overbuild to 1 + overbuild (past hub and casing, as aero tools write them) in ZRTH. Straight vanes:
// a linear cascade (`cascade yes`): hub r = 0 and shroud r = span, XYZ sections with X the spanwise
// coordinate, Y the pitchwise y and Z the axial x. Both sides run LE -> TE and share their end points.
// number_of_blades is written when known (an imported blade's); no tip gap (the blade reaches the
// casing the model was cut at).
#include <iosfwd>
#include <string>

#include "src/blade/blade_surface.hpp"

namespace cg::blade_import {

struct GeomTurboWriteOptions {
  int sections = 23;          // >= 2
  int points_per_side = 121;  // >= 3, clustered at the LE and TE
  int number_of_blades = 0;   // 0: the imported blade's, else not written
};

void write_geomturbo(std::ostream& out, const blade::BladeModel& model, const GeomTurboWriteOptions& options = {});
/// Writes to a file; throws Error when it cannot be written.
void write_geomturbo_file(const std::string& path, const blade::BladeModel& model, const GeomTurboWriteOptions& options = {});

}  // namespace cg::blade_import
