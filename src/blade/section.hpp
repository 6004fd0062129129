#pragma once
// Blade sections (profiles) in their own 2D frame (a, b), mm: from a point list or from camber line +
// thickness. Every section becomes a closed, periodic cubic NURBS oriented so that it runs from the leading
// edge (LE) over the suction side to the trailing edge (TE) and back over the pressure side.
//
// How a section's (a, b) frame is placed:
//  - straight vane: (a, b) = (x, y) and the section lies in the plane z = span fraction * span;
//  - meridional blade: a runs along the streamline, b circumferentially, both scaled by a reference
//    radius r_ref (radius of the streamline at the section's LE): m' = m'_LE + (a - a_LE) / r_ref,
//    theta = (b - b_stack) / r_ref + theta_stack. On a cylinder (r = r_ref) this is an exact unrolling.
//    See blade_surface.hpp for the scaling to the LE/TE lines.
#include <Eigen/Core>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "src/blade/camber_edges.hpp"
#include "src/blade/leading_edge.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade {

/// Length units accepted for section point files; everything is converted to mm.
enum class LengthUnit { Millimetre, Centimetre, Metre, Inch };
/// Factor to mm.
double millimetres_per(LengthUnit unit);
/// "mm", "cm", "m", "in" (case-insensitive); throws InvalidGeometry otherwise.
LengthUnit parse_length_unit(const std::string& name);

/// Reads section points from a CSV ("x,y" or with a header naming x.. and y.. columns, e.g.
/// "point,x_cm,y_cm,side") or from the "x y" .dat layout (whitespace separated; a leading name line is
/// skipped). Without a header naming x and y, 2 columns are x, y and 3 columns are (point number, x, y)
/// when the first counts up by one; other layouts are refused as ambiguous. Lines starting with '#' are
/// comments. A last point repeating the first is dropped. Returns mm; `source_lines` (optional) gets the
/// file line of each point. Throws InvalidGeometry (naming the file and line) for unreadable lines,
/// ambiguous columns or < 4 points.
std::vector<Eigen::Vector2d> read_section_points(const std::string& path, LengthUnit unit,
                                                 std::vector<int>* source_lines = nullptr);
std::vector<Eigen::Vector2d> parse_section_points(std::istream& in, LengthUnit unit, const std::string& source_name,
                                                  std::vector<int>* source_lines = nullptr);

/// Which side of a point section is the suction side.
enum class SuctionSide {
  Longer,            // the longer side between LE and TE (true for turbine blades)
  CounterClockwise,  // the side reached by going counter-clockwise from the LE
  Clockwise,
};

/// A section given by points around the profile (closed loop, any start, either orientation).
struct PointSectionDefinition {
  std::vector<Eigen::Vector2d> points;  // mm; if empty, read from `file` in `unit`
  std::string file;
  LengthUnit unit = LengthUnit::Millimetre;
  /// Optional indices (into points) of the LE and TE; -1 = detect (see section_from_points).
  int le_index = -1;
  int te_index = -1;
  SuctionSide suction_side = SuctionSide::Longer;
  /// Optional edge-circle hints (mm, section frame): the LE/TE circle's radius (0 = not given) and/or
  /// centre. With a hint the points on that circle are found with it and the profile follows the
  /// circle exactly (see section_from_points).
  double le_radius = 0, te_radius = 0;
  std::optional<Eigen::Vector2d> le_centre, te_centre;
  /// Where a detected LE / TE sits on its edge (camber_edges.hpp); not used with le_index / te_index.
  EdgeRule edges = EdgeRule::CentreLine;
};

/// A section from camber line and thickness. Angles in degrees, measured in the section frame from the
/// +a axis (axial/meridional direction), positive towards +b.
/// Camber: cubic Bezier from the LE (origin) to the TE at chord * (cos stagger, sin stagger) with end
/// tangents at the inlet/outlet metal angles (the degree-elevated parabola through the tangent-line
/// intersection, or thirds of the chord when the tangent lines do not meet ahead of both ends).
/// Thickness: half-thickness normal to the camber h(t) = L sqrt(t (1 - t)) q(t) on the camber parameter t
/// (L = chord), q cubic on each side of the maximum, such that the radius of curvature at the LE/TE tip is
/// le_radius/te_radius (exact for a straight camber line, to leading order otherwise), and h reaches
/// max_thickness/2 with zero slope at the camber point whose chordwise position is
/// max_thickness_position * chord (C2 there, curvature of an ellipse through the maximum). With
/// t = (1 - cos phi)/2 the profile camber(t) + h(t) n(t) is one smooth function of phi in [0, 2 pi): the
/// suction (convex) side is phi in [0, pi]. Checked: h > 0, h <= max_thickness/2 everywhere, no folding.
struct ParametricSectionDefinition {
  double chord = 0;                  // mm, > 0
  double stagger_deg = 0;            // (-90, 90)
  double inlet_angle_deg = 0;        // (-90, 90), within 90 of the stagger
  double outlet_angle_deg = 0;       // (-90, 90), within 90 of the stagger
  double max_thickness = 0;          // mm, > 0, < chord
  double max_thickness_position = 0.3;  // fraction of chord, [0.1, 0.9]
  double le_radius = 0;              // mm, (0, max_thickness / 2] (and a valid thickness, checked)
  double te_radius = 0;              // mm, (0, max_thickness / 2]; te_radius <= le_radius is not required
  int points_per_side = 64;          // sample points per side used for the interpolation, [8, 2000]
};

/// A closed section curve with its LE and TE.
struct SectionProfile {
  BSplineCurve<2> curve;  // periodic, period 1; LE -> suction side -> TE -> pressure side -> LE
  double le_param = 0;    // curve parameter of the LE: 0, the seam (sections built here)
  double te_param = 0;    // curve parameter of the TE, in (le_param, le_param + period)
  Eigen::Vector2d le = Eigen::Vector2d::Zero();
  Eigen::Vector2d te = Eigen::Vector2d::Zero();
  /// Unit direction of the chord line, LE towards TE.
  Eigen::Vector2d chord_direction = Eigen::Vector2d::UnitX();
  /// True chord |te - le| (te - le is along chord_direction).
  double chord() const { return (te - le).dot(chord_direction); }
  /// Edge circles: fitted to the curve at both ends (leading_edge.hpp), or the circle the given points
  /// lie on at that end (point sections, see section_from_points), or the hinted circle.
  EdgeCircle le_circle, te_circle;
  /// Point sections: number of given points found on each edge circle (0 = none detected), and whether
  /// the profile follows that circle as an exact rational arc between them.
  int le_circle_points = 0, te_circle_points = 0;
  bool le_arc = false, te_arc = false;
  /// Curve parameter at a chordwise coordinate c in [-1, 1]: c in [0, 1] runs from the LE over the
  /// suction side to the TE at fraction c of that side's arc length; c in [-1, 0] likewise over the
  /// pressure side (c = -1 is the TE again). The one definition of the chordwise coordinate, shared
  /// with the 3D sections of the wall: src/blade/chordwise.hpp.
  double param_at_chordwise(double c) const;
  /// Batched form (the arc-length tables are built once). Parameters lie in [le_param, le_param + period].
  std::vector<double> params_at_chordwise(const std::vector<double>& c) const;
  /// Inverse: chordwise coordinate of curve parameter u.
  double chordwise_at_param(double u) const;
  double suction_length() const;
  double pressure_length() const;
};

/// Closed periodic cubic interpolation of the points (centripetal parameters), reproducing them exactly.
/// LE/TE unless indices are given: the edge-circle definition (leading_edge.hpp): the chord line joins
/// the centres of the circles fitted at both ends, LE and TE are where it leaves the profile, chord =
/// |LE - TE|. With indices, LE and TE are those data points. The curve's seam is then moved to the LE
/// (le_param = 0, period 1).
/// Edge circles of sparse tables (edge_arcs.hpp): around each edge the longest run of consecutive points
/// on one circle (>= 4 points within 0.005 mm; >= 3 with a radius hint; >= 2 with a centre hint) is
/// found. Where the spline through the points leaves that circle by more than 0.002 mm between them (or
/// a hint is given), the profile follows the circle exactly there (rational arc, G1 to splines through
/// the other points); otherwise (dense tables such as C3X) the spline through every point is kept. The
/// circles found are reported in le_circle/te_circle with their point counts.
/// Throws InvalidGeometry for < 4 points, coincident consecutive points, a self-intersecting polygon,
/// or a hint that no run of given points fits.
SectionProfile section_from_points(const PointSectionDefinition& def);

/// The parametric section. Throws InvalidGeometry for chord/thickness/radii <= 0, angles out of range,
/// or parameters giving a non-positive or self-overlapping thickness distribution.
SectionProfile section_from_parameters(const ParametricSectionDefinition& def);

/// Enclosed (signed, counter-clockwise positive) area and centroid of the closed curve (Green's theorem,
/// Gauss-Legendre per knot span).
struct SectionProperties {
  double area = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  double perimeter = 0;
};
/// with_perimeter = false skips the arc length (perimeter stays 0).
SectionProperties section_properties(const BSplineCurve<2>& closed_curve, bool with_perimeter = true);

}  // namespace cg::blade
