#pragma once
// Reading a geomTurbo file (the blade exchange format of AutoGrid / TurboGrid users, written by
// T-Blade3, turbigen, ParaBlade and many in-house codes) into an ImportedBlade.
//
// What is read: the header's UNITS (Meters, Millimeters, Centimeters, Inches) and UNITS-FACTOR; a
// `cascade yes|no` line (anywhere; yes = linear cascade); the CHANNEL's `basic_curve`s with `zrcurve`
// point lists and its `channel_curve hub` / `channel_curve shroud` (the basic curves they name, in
// order; without them the basic curves whose names contain "hub" and "shroud"); one `nibladegeometry`
// with `number_of_blades`, `units` (a further factor on the blade's coordinates) and its `suction` and
// `pressure` sides, each `SECTIONAL` with N sections of `XYZ` or `ZRTH` points (LE -> TE); the row's
// `PERIODICITY` when number_of_blades is absent; `NITipGap` WIDTH_AT_LEADING_EDGE / _TRAILING_EDGE.
// Other blocks are skipped. geomTurbo's Z is the machine axis: annular XYZ (X, Y, Z) -> (x, y, z) =
// (Z, X, Y) so theta = atan2(Y, X); ZRTH (z, r, th) -> x = z, theta = th (radians). A cascade's r is the
// spanwise coordinate: XYZ (X, Y, Z) -> (Z, Y, X - r_hub), its hub and shroud must be lines of constant r.
#include <iosfwd>
#include <string>

#include "src/blade_import/imported_blade.hpp"

namespace cg::blade_import {

/// Reads the file. Throws InvalidGeometry "<file>:<line>: <what>" for anything it cannot read
/// (unknown units, a count that does not match its points, a line that is not numbers, sides with
/// different section counts, no hub or shroud curve, more than one blade).
ImportedBlade read_geomturbo(const std::string& path);
ImportedBlade parse_geomturbo(std::istream& in, const std::string& name);

}  // namespace cg::blade_import
