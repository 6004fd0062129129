#pragma once
// How closely the built blade follows the imported one: the distance from the built wall surface
// (global projection) of the input surface's points inside the flow path (between hub and casing,
// the tip gap excluded): at the given points, half-way between consecutive points of each section
// (on its interpolant) and half-way between neighbouring sections (input_surface.hpp's samples).
#include "src/blade/blade_surface.hpp"
#include "src/blade_import/slice_blade.hpp"

namespace cg::blade_import {

/// The record for report.json. Throws InvalidGeometry "<file>:<line>: section k: ..." naming the
/// worst point when a distance exceeds `tolerance` (mm).
blade::ImportRecord measure_fidelity(const ImportedBlade& blade, const SlicedBlade& sliced, const blade::BladeModel& model,
                                     double tolerance);

}  // namespace cg::blade_import
