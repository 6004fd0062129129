#pragma once
// A hollow blade and a field of short inclined holes: the work load the verified boolean path is
// measured and tested on (bench/bench_holes.cpp), until the cooled example blade of the passage and
// film-cooling features replaces it.
//
// The part is the blade solid minus a core whose surface lies about `wall` mm inside the blade wall
// over the middle of the chord, closed by a hub floor and a tip cap. The core is NOT a true offset
// (that is the core feature's job): each core section is built from the blade section in blade
// coordinates, point pairs at the same chordwise fraction x on the suction and pressure side, S_ss and
// S_ps, around their mid point M:  core = M + (S - M) (1 - 2 wall / h) e(theta),  h = |S_ss - S_ps|,
// x = x0 + (x1 - x0)(1 - cos theta) / 2, e = 1 - (1 - sin theta)^3. So the wall is `wall` thick (along
// S - M) where e ~ 1 (within 5 % for x in the middle 76 % of [x0, x1]) and thickens smoothly towards
// rounded core ends at x0 and x1; x1 is chosen where the blade is still
// thick enough. The sections are interpolated (periodic cubic) and skinned (src/fit).
//
// The holes are cylinders drilled from outside through the wall into the core, inclined to the
// surface (streamwise), each just long enough to start clear of the outer surface and end clear of the
// core surface. Each carries an independent expected removed volume: the integral over the tool's
// cross-section disk of the chord of the axis-parallel line inside the wall, the chord found by ray
// casting against the exact blade and core surfaces with our own kernel (src/algo/ray_surface.hpp),
// integrated by Gauss-Legendre (radius) x trapezoid (angle, exponentially convergent for a smooth
// periodic integrand); no OCCT in that number.
#include <string>
#include <vector>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

struct HollowBladeOptions {
  double wall = 1.2;            ///< mm, wall thickness over the middle of the chord
  double end_wall = 2.0;        ///< mm, hub floor and tip cap thickness (radial / along z)
  double chord_start = 0.15;    ///< x0, chordwise fraction where the core starts (LE side)
  double min_cavity = 1.0;      ///< mm, blade thickness 2 wall + min_cavity decides x1 (TE side)
  int sections = 9;             ///< core sections over the over-built span
  int points_per_side = 24;     ///< core section points per side
  /// Verify the core cut with brep::verify_solid (the per-tool volume and history checks always
  /// run); off saves the whole-part volume and area integrals in smoke runs.
  bool verify = true;
};

struct HollowBlade {
  brep::NamedShape part;        ///< faces: blade_wall, hub, casing, chamber_1_wall, hub_floor, tip_cap
  BSplineSurface<3> core_surface;
  double chord_start = 0, chord_end = 0;  ///< x0, x1 of the core
  double volume = 0;            ///< mm^3, of the part (BRepGProp)
};

/// Builds the hollow part from a blade model (straight or meridional flow path). Throws
/// InvalidGeometry when the blade is too thin for the wall, AlgorithmFailure when a boolean fails.
HollowBlade make_hollow_blade(const blade::BladeModel& model, const HollowBladeOptions& options = {});

struct HoleFieldOptions {
  int count = 100;
  double diameter = 0.5;         ///< mm
  double inclination_deg = 30;   ///< angle between the hole axis and the surface (streamwise)
  double clearance = 0.3;        ///< mm, the tool's end disks stay this far from the surfaces
  double span_min = 0.12, span_max = 0.88;  ///< span fractions covered by the field
  /// Chordwise band of the field as fractions of the core's [x0, x1], on each side.
  double band_min = 0.18, band_max = 0.85;
  std::string name_prefix = "film_row_";  ///< holes are named <prefix><row>_hole_<nnn>
};

/// `count` holes on a staggered grid (rows chordwise on both sides, holes spanwise) filling the field,
/// each a FeatureTool with all faces named after the hole and the expected volume from ray casting.
/// Throws InvalidGeometry when a hole's tool would not cross the wall cleanly (the field is too
/// dense for the diameter or reaches past the core).
std::vector<FeatureTool> make_hole_tools(const blade::BladeModel& model, const HollowBlade& part,
                                         const HoleFieldOptions& options);

}  // namespace cg::features
