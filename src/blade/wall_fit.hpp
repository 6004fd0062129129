#pragma once
// The wall surface from the section family (internal to the blade model): the fewest poles that meet
// a stated tolerance (issue 8, items 1 and 5).
//
// Chordwise (u): every skinned section is fitted by least squares (The NURBS Book 9.4.1, periodic form)
// on ONE knot vector shared by all sections, so skinning needs no knot union (which is what made walls
// of ~1000 poles). The knot vector starts from a few uniform spans (or, for families whose slices are
// one spline each, that spline's knots) and spans whose error exceeds half the tolerance are halved
// until every section meets it. Slices that already are splines on the common knots in their plane
// (straight vanes with one section or parametric sections) are used exactly, without fitting.
// Spanwise (v): the sections are skinned (cubic interpolation across them, src/fit/skin.hpp, The NURBS
// Book 10.3) and the surface is compared with the family at 1/4, 1/2 and 3/4 of every interval between
// skinned spans; where it misses the tolerance the interval's middle becomes another skinned section.
// The error is measured as |S(u, s) - X_s(u)|, X_s the family's section at span s at the same u: it bounds
// both the distance to the intended shape and the error of the blade-relative coordinates.
// Past hub and casing the surface continues linearly (pole by pole) from the two nearest sections.
#include <vector>

#include "src/blade/section_family.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::blade::detail {

struct WallFitOptions {
  double tolerance = 1e-3;   // mm
  int min_samples_per_side = 97;  // least number of check points per section side
  double overbuild = 0.05;
};

struct WallFit {
  BSplineSurface<3> surface;
  std::vector<double> spans;  // skinned spans in [0, 1]
  double max_deviation = 0;   // largest |S(u, s) - X_s(u)| over every check point, mm
  long checked_points = 0;
  bool exact_sections = false;  // slices used as they are (no chordwise fit)
};

/// Throws AlgorithmFailure when the tolerance cannot be met with 4000 poles chordwise or 257 sections.
WallFit fit_wall(const SectionFamily& family, const WallFitOptions& options);

}  // namespace cg::blade::detail
