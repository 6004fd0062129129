#pragma once
// Inner wall of a hollow blade: the outer wall offset inward by the wall thickness t, in true mm
// normal to the 3D wall, as one NURBS surface within a tolerance, with the loop that forms where the
// blade is thinner than 2t (at the trailing edge) trimmed away.
//
// Method (offset surfaces after Piegl & Tiller, "Computing offsets of NURBS curves and surfaces",
// CAD 31 (1999): sample the exact offset, fit, verify):
//  - The exact offset point of the wall point at blade coordinate (span, chord) is
//    I(span, chord) = P - t(span, chord) n (BladeCoordinates::frame: n the outward unit normal). P is a
//    critical point of the distance from I to the wall, so the distance is exactly t (also for a
//    varying t) wherever t is below the wall's radius of curvature and half the blade thickness.
//  - Trailing edge: where the blade is thinner than 2t, the suction- and pressure-side offsets cross
//    and form a loop (Farouki & Neff 1990: a global self-intersection of the offset). Per span the
//    first suction-side offset point (walking from the LE) closer than t to the pressure side brackets
//    the crossing; Newton's method then solves I(span, c_s) = I(span_p, c_p) for (c_s, c_p, span_p) in
//    3D (the two offset sheets meet along a space curve, not exactly on one span). The crossing point
//    is at distance t from both sides: it is the crease of the inner wall, and everything between it and
//    the TE (the loop) is dropped. A TE radius >= t gives no crossing: the inner wall then rounds the TE.
//  - Each inner section runs from the crease over the pressure side, the LE and the suction side back
//    to the crease (the outer wall's direction). The pressure half is taken at a span blended smoothly
//    (C1) from span_p at the crease to the section's span a quarter of the way to the LE, so every
//    sample is an exact offset point (and the rest of the half shares the section's span, whose
//    arc-length table is then built once).
//  - Sections are sampled adaptively (at most 2 degrees of normal turning per step), parametrised by
//    normalised chord length, fitted by least squares (The NURBS Book 9.4.1) on ONE knot vector shared
//    by all spans (refined until every section is within tol / 2 at its samples), and skinned across the
//    spans (The NURBS Book 10.3). Spans are bisected until exact sections midway between fitted spans
//    lie within tol of the surface (distance by Newton foot points on the surface).
//  - The clamped, closed (C0 at the crease) result is stored u-periodic with a knot of full
//    multiplicity at the seam, so the crease is the seam edge of the B-rep face.
// A fold (t larger than the wall's radius of curvature, e.g. at a sharp LE) or a second crossing away
// from the TE cannot be trimmed this way and throws InnerWallError naming the span and chord.
#include <Eigen/Core>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "src/blade/blade_coordinates.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/blade/thickness_field.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/error.hpp"

namespace cg::blade {

/// The inner wall cannot be built as asked; names where on the blade.
class InnerWallError : public InvalidGeometry {
 public:
  InnerWallError(const std::string& what, double span, double chord)
      : InvalidGeometry(what), span_(span), chord_(chord) {}
  double span() const { return span_; }
  double chord() const { return chord_; }

 private:
  double span_, chord_;
};

struct InnerWallOptions {
  double tolerance = 1e-3;  ///< mm, largest distance of the surface from the exact trimmed offset
  /// Span range of the surface; NaN: the blade's over-built range shrunk by 20 % of the over-build at
  /// each end (so cutting surfaces just outside the blade still meet it).
  double span_min = std::numeric_limits<double>::quiet_NaN();
  double span_max = std::numeric_limits<double>::quiet_NaN();
};

/// The span range [lo, hi] of the inner wall build_inner_wall fits for `options` (no fit: cheap), so
/// placements that depend on it (rib ends) can be planned before the fit.
std::pair<double, double> inner_wall_span_range(const BladeModel& model, const InnerWallOptions& options);

/// Where the inner wall's crease (trailing-edge trim) lies on one fitted span.
struct InnerWallSection {
  double span = 0;
  double suction_chord = 1;    ///< chordwise coordinate of the crease's suction-side foot point
  double pressure_chord = -1;  ///< ... of its pressure-side foot point (negative)
  double pressure_span = 0;    ///< span of the pressure-side foot point
  bool trimmed = false;        ///< false: no crossing (TE radius >= t), the inner wall rounds the TE
  Eigen::Vector3d crease = Eigen::Vector3d::Zero();
};

struct InnerWall {
  /// u periodic (period 1, seam = crease, C0 there), from the crease over the pressure side, the LE and
  /// the suction side back to the crease (the outer wall's sense); v = span fraction on [span_min, span_max].
  BSplineSurface<3> surface;
  std::vector<InnerWallSection> sections;  ///< one per fitted span
  double max_fit_error = 0;  ///< mm, largest verified distance of the checked exact points from the surface
  int checked_points = 0;
  /// Chordwise extent of the core over all spans: the crease lies at chord >= min_suction_chord on the
  /// suction side and <= max_pressure_chord on the pressure side.
  double min_suction_chord = 1, max_pressure_chord = -1;
  int poles_u() const { return surface.num_poles_u() - surface.degree_u(); }
  int poles_v() const { return surface.num_poles_v(); }
};

/// Builds the inner wall of `model` for the thickness field (see the header comment). Throws
/// InnerWallError for a wall too thick for the blade (fold, crossing away from the TE, nothing left),
/// InvalidGeometry for bad options.
InnerWall build_inner_wall(const BladeModel& model, const ThicknessField& thickness, const InnerWallOptions& options = {});

/// The exact (untrimmed) inner wall point at a blade coordinate: frame point - t * outward normal
/// (Near: the frame's chord as BladeCoordinates::frame takes it, for scans).
Eigen::Vector3d inner_wall_point(const BladeCoordinates& coords, const ThicknessField& thickness, double span,
                                 double chord, ChordAccuracy accuracy = ChordAccuracy::Exact);

/// Where the inner wall's crease lies at `span`: Newton's solution of the two offsets' crossing (see
/// the header comment), or an untrimmed section (trimmed = false) when the offsets do not cross.
/// Throws InnerWallError when the wall is too thick there.
InnerWallSection inner_wall_crease(const BladeCoordinates& coords, const ThicknessField& thickness, double span);

}  // namespace cg::blade
