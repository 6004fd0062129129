#pragma once
// From an imported blade to the definition the blade model builds (the one path of every import):
// the input sections' surface (input_surface.hpp) is cut at OUR streamlines of the flow path (hub and
// casing from the file's channel, the casing moved inwards by the tip gap), at evenly spaced spans
// 0..1; each cut is a point section on its stream surface, placed so that the blade model puts it
// back where it was cut: annular rows in the conformal coordinates of blade_surface.hpp
// (a = r_ref (m' - m'_LE), b = r_ref theta, offset = the detected LE's a and the stacking point's b),
// cascades in the plane z = span * s. LE and TE are the file's (where its two sides meet). The blade
// model then interpolates between the cuts and fits the wall as for any point sections, so every
// feature, check and output works on it.
#include <memory>

#include "src/blade/blade_surface.hpp"
#include "src/blade_import/import_options.hpp"
#include "src/blade_import/imported_blade.hpp"
#include "src/blade_import/input_surface.hpp"

namespace cg::blade_import {

struct SlicedBlade {
  blade::BladeDefinition definition;  // flow path and point sections (options: the caller's)
  std::shared_ptr<const InputSurface> surface;
  std::vector<double> spans;
};

/// Throws InvalidGeometry "<file>:<line>: ..." for hostile input (input_surface.hpp) and for sections
/// that do not reach the hub or the casing (naming the section). `channel` (optional): the config's
/// meridional flow path (hub and casing equal to the blade's), whose explicit streamlines and sampling
/// the cuts follow; its LE, TE and station lines are not used (the LE line is the import's).
SlicedBlade slice_blade(const ImportedBlade& blade, const ImportOptions& options, const blade::BladeOptions& blade_options,
                        const blade::MeridionalNetDefinition* channel = nullptr);

}  // namespace cg::blade_import
