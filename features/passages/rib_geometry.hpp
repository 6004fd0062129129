#pragma once
// Ribs (partition walls) as B-rep tubes that split the hollow core into chambers.
//
// Placement: the rib's mid-surface is the ruled surface M(a, s) = A(s) + a (B(s) - A(s)) between the
// inner-wall points A(s) (suction side) and B(s) (pressure side) at the rib's chordwise coordinates, s
// the span fraction; a in [0, 1] runs across the core and is extended past both walls. N(a, s) is its unit
// normal (towards the TE). The rib is the slab |w| <= thickness / 2 along N about M, closed at each span
// end by a rounded end in the plane (N, T), T the unit span tangent M_s: a full round (radius
// thickness / 2) or two quarter rounds of the tip radius joined by a flat.
//
// Construction (exact at stations, skinned across them): at stations a_k the profile is computed exactly:
// the two side curves M +- (thickness / 2) N interpolated through their points along the span (cubic,
// end tangents along T so they join the rounds with tangent continuity), the rounds as exact rational
// quarter circles (The NURBS Book 7.5). Each piece is skinned across the stations (The NURBS Book 10.3)
// into its own surface; neighbouring pieces share their boundary curve exactly (the same points
// interpolated with the same parameters), so the faces sew without gaps and meet with tangent
// continuity. The tube is open at both a-ends, which lie outside the core: it is a splitting tool, not a
// solid. Stations are added until midway stations agree with the skinned surface within the tolerance.
//
// Rib ends: at a turnaround the rounded end is placed, per station, so that its closest distance to
// the end wall (tip cap or hub floor) is the configured gap; other ends lie beyond the core's end.
//
// Face names (src/brep/named_shape.hpp): "rib_<i>" for both sides, "turnaround_<j>" for the rounded end
// at a turnaround, "rib_<i>_end" for rounded ends outside the core (they never reach the blade).
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "features/passages/end_walls.hpp"
#include "features/passages/passage_definition.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/blade/inner_wall.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

/// Where the rib's span ends lie: a turnaround end is placed by its gap; a through end extends to
/// `through_span` (beyond the core's end) with a full round.
struct RibEnds {
  double hub_through_span = 0;  ///< span of the hub-side junction of a through end (below the core)
  double tip_through_span = 1;  ///< span of the tip-side junction of a through end (above the core)
  const EndWall* hub_wall = nullptr;  ///< hub floor (for a hub turnaround)
  const EndWall* tip_wall = nullptr;  ///< tip cap (for a tip turnaround)
};

/// The exact mid-surface of a rib and its frame (no approximation; used to build and to measure).
class RibMidSurface {
 public:
  RibMidSurface(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall, const RibDefinition& rib);
  Eigen::Vector3d suction_point(double span) const;   ///< A(s)
  Eigen::Vector3d pressure_point(double span) const;  ///< B(s)
  Eigen::Vector3d point(double a, double span) const;  ///< M(a, s)
  /// Unit normal N (towards the TE) and unit span tangent T (M_s, orthogonal to N) at (a, s).
  void frame(double a, double span, Eigen::Vector3d& normal, Eigen::Vector3d& span_tangent) const;
  double span_scale(double a, double span) const;  ///< |M_s|, mm per unit span

 private:
  const blade::BladeCoordinates* coords_;
  const blade::ThicknessField* wall_;
  RibDefinition rib_;
  double sign_ = 1;
};

struct RibTube {
  int index = 0;                   ///< 1-based rib number (LE to TE)
  int turnaround = 0;              ///< 1-based turnaround number, 0 when the rib has none
  std::vector<brep::NamedFace> faces;  ///< sewn, open at both a-ends
  TopoDS_Shell shell;
  /// Sheet on the mid-surface from inside the rounded turnaround end through the gap to beyond the end
  /// wall (null without a turnaround): it separates the two chambers' faces in the U-bend for naming.
  TopoDS_Face turnaround_sheet;
  double a_min = 0, a_max = 1;     ///< extent of the tube along the rib line
  double max_station_error = 0;    ///< mm, skinned side surfaces vs exact offsets midway between stations
  std::vector<double> hub_junction, tip_junction;  ///< junction span per station
  std::vector<double> stations;
};

/// The rib's ends placed as build_rib_tube places them on its first stations (a turnaround end by its
/// gap against its end wall), without building a surface: the (hub, tip) junction spans per station.
/// Throws InvalidGeometry as build_rib_tube does (the gap leaves no rib, the end cannot be placed, the
/// ends overlap), so the plan refuses what the rib build would. Milliseconds.
std::vector<std::pair<double, double>> check_rib_ends(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                                                      const RibDefinition& rib, int index, const RibEnds& ends);

/// Builds rib `index` (1-based) of the core. Throws InvalidGeometry (with the rib named) when the rib
/// cannot be placed: gap leaves no rib, tip radius > thickness / 2, non-positive sizes.
RibTube build_rib_tube(const blade::BladeCoordinates& coords, const blade::ThicknessField& wall,
                       const RibDefinition& rib, int index, int turnaround_index, const RibEnds& ends,
                       double tolerance);

}  // namespace cg::features
