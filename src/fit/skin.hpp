#pragma once
// Skinning (lofting) of section curves into a B-spline surface (The NURBS Book 10.3).
//
// The sections become the u-iso curves of the surface: they are made compatible (common degree by
// degree elevation, common knot vector by knot refinement), then each column of homogeneous poles is
// interpolated across the sections with degree q in v (A9.1), so the surface reproduces every section
// exactly at its v parameter. Periodic sections (closed airfoils) give a surface periodic in u.
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/fit/interpolate.hpp"

namespace cg {

/// Returns the sections with a common degree (the highest) and a common knot vector (the union of
/// the knots, each with its largest multiplicity), all shapes unchanged. Non-periodic sections are
/// first reparametrised linearly onto [0, 1]; periodic ones onto period [0, 1) (their seam stays at
/// parameter 0). Throws InvalidGeometry when the list is empty or mixes periodic and non-periodic
/// sections.
std::vector<BSplineCurve<3>> make_compatible(const std::vector<BSplineCurve<3>>& sections);

struct SkinOptions {
  /// Degree across the sections; lowered to (number of sections - 1) when there are fewer sections.
  int degree_v = 3;
  /// How the v parameters are computed when `v_params` is empty: the method applied to each row of
  /// compatible poles, averaged over the rows (eq. 10.8 generalised), on [0, 1].
  ParamMethod method = ParamMethod::ChordLength;
  /// Explicit v parameter of each section (strictly increasing, one per section); empty = computed.
  std::vector<double> v_params;
};

struct SkinResult {
  BSplineSurface<3> surface;
  std::vector<double> v_params;  ///< v of each section: section k is the iso-curve S(., v_params[k])
};

/// Skins the sections (at least 2) into a surface S(u, v) with S(u, v_params[k]) = section k (after
/// make_compatible's reparametrisation of u onto [0, 1]). Rational sections are interpolated in
/// homogeneous form; throws AlgorithmFailure if an interpolated weight becomes non-positive.
/// Throws InvalidGeometry for fewer than 2 sections, bad v_params, or coincident consecutive sections.
SkinResult skin(const std::vector<BSplineCurve<3>>& sections, const SkinOptions& options = {});

}  // namespace cg
