#pragma once
// One film hole against the wall it crosses, computed with our own kernel (ray casting against the exact
// outer-wall and cavity-wall surfaces, src/algo/ray_surface.hpp), independently of OCCT:
//  - the chamber it feeds (where its axis enters the cavity), its length L and metering length;
//  - the tool extent: from just outside the outer wall to just past the cavity wall (FilmLimits::clearance
//    along every quadrature line), checked against the far wall, the chamber's reach (inserts) and the
//    obstacles (ribs, end walls: at least the ligament; inserts: not touched);
//  - the metal the tool removes (its expected volume in the verified boolean), the exit footprint area
//    on the outer surface and the breakout width along the row.
//
// Quadrature (why it is exact to ~1e-9 relative: every integrand below is smooth):
//  - Cylinder, and the metering part of a fan-shaped hole: lines parallel to the axis through the disc,
//    Gauss-Legendre in the radius (weight rho) x trapezoid in the angle (spectral for a periodic
//    integrand); a line contributes its length in the metal (cavity-wall hit minus outer-wall hit, or
//    minus the diffuser-start plane).
//  - Diffuser of a fan-shaped hole: its cross-section (hole_shape.hpp) is split into a centre rectangle,
//    four side strips and four corner quarter discs, each mapped from [0, 1]^2 by a map that is linear in
//    the axial distance t. So every reference point (a, b) moves on a straight line, crossing the outer
//    wall at t_c(a, b) (one ray cast), and the volume is the integral over (a, b) of the integral over
//    [0, t_c] of the map's Jacobian J(a, b, t), a quadratic in t integrated exactly (2-point Gauss).
//    Gauss-Legendre tensor rules on each piece.
//  - Footprint area: the same lines; the surface element crossed by the line tube of cross-section
//    J da db is J da db / |V . n| (V the line direction with unit axial component, n the surface normal).
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/hole_shape.hpp"
#include "features/film/hole_target.hpp"
#include "features/film/hole_tool.hpp"

namespace cg::features {

/// One hole to build, placed (film_rows.hpp makes these from rows).
struct HoleSpec {
  std::string name;   ///< face and feature name, e.g. "film_row_2_hole_014"
  std::string row;    ///< "film_row_2", "showerhead_3"
  std::string field;  ///< config path of the row below "cooling", for errors ("film_rows[1]")
  HoleFrame frame;    ///< exit on the outer wall, axis into the wall, forward (laidback side)
  HoleShape shape;
  double span = 0, chord = 0;  ///< blade coordinates of the exit point
  Eigen::Vector3d row_direction = Eigen::Vector3d::UnitZ();  ///< unit, along the row (breakout width)
  double pitch = 0;        ///< mm along the row
  std::string spacing_field = ".pitch_d";  ///< the row's field that sets the pitch (".count" for counted rows)
  /// The row's field that sets its chordwise position (".chord", ".arc_length"; showerhead:
  /// ".stagnation_arc_length"), named when the hole does not fit where it is.
  std::string position_field = ".chord";
  int required_chamber = 0;  ///< 1-based; 0: any
};

struct HoleQuadrature {
  int radial = 6;    ///< Gauss points in the radius of a disc
  int angular = 16;  ///< trapezoid points in the angle of a disc
  int piece = 5;     ///< Gauss points per direction on each diffuser piece
};

/// What the analysis found (lengths mm, areas mm^2, volumes mm^3).
struct HoleGeometry {
  HoleToolExtent extent;
  int chamber = -1;             ///< index into HoleTarget::chambers
  Eigen::Vector3d inlet = Eigen::Vector3d::Zero();  ///< where the axis enters the cavity
  double inlet_chord = 0;       ///< blade chordwise coordinate of the inlet's foot on the outer wall
  double length = 0;            ///< L: along the axis from the outer wall to the cavity wall
  double metering_length = 0;   ///< cavity wall to diffuser start (cylindrical: = length)
  double diffuser_length = 0;   ///< diffuser start to the exit point (cylindrical: 0)
  double inclination_deg = 0;   ///< angle between the axis and the outer surface at the exit
  double expected_volume = 0;   ///< metal removed by the tool
  double footprint_area = 0;    ///< exit footprint on the outer surface
  double metering_area = 0;     ///< pi D^2 / 4
  double exit_area = 0;         ///< fan: cross-section at L* (hole_shape.hpp); cylindrical: metering area
  double breakout_width = 0;    ///< extent of the footprint along the row direction
  double obstacle_ligament = std::numeric_limits<double>::infinity();  ///< to the nearest rib / end wall
  std::string nearest_obstacle;
  /// Envelope of the hole between the outer and the cavity wall, for ligaments between holes: points on
  /// the axis and the radius of a ball about each that contains the hole's cross-section there.
  std::vector<Eigen::Vector3d> envelope_points;
  std::vector<double> envelope_radii;
  /// Where the metering disc's rim lines enter the cavity, and the tool's end rim: what the ligament to
  /// an obstacle and the tool's clearance of it are measured at (check_hole_obstacle).
  std::vector<Eigen::Vector3d> inlet_rim, end_rim;
};

/// Analyses holes against one target. One per thread (owns ray casters and work buffers); the target
/// must outlive it.
class HoleAnalyser {
 public:
  HoleAnalyser(const HoleTarget& target, const FilmLimits& limits, const HoleQuadrature& quadrature = {});
  ~HoleAnalyser();
  HoleAnalyser(const HoleAnalyser&) = delete;
  HoleAnalyser& operator=(const HoleAnalyser&) = delete;

  /// Throws FilmInputError (field = hole.field, message naming the hole and the limit) when the hole
  /// does not cross the wall cleanly into a chamber, reaches no chamber or the wrong one, comes closer
  /// than the ligament to an obstacle, or is larger than the wall allows.
  HoleGeometry analyse(const HoleSpec& hole);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Hole `hole` (analysed into `g`) against one obstacle: the ligament from its inlet rim must be at least
/// limits.min_ligament (when the obstacle needs one; the nearest such obstacle is kept in `g`) and its
/// tool's end rim must not reach into the obstacle. The check HoleAnalyser::analyse runs on the target's
/// obstacles; the build runs it on the planned holes for the obstacles known only from their tools
/// (turbulators, pins, slots: film_cavity.hpp). Throws FilmInputError naming the obstacle's field or the
/// row's position field.
void check_hole_obstacle(const HoleSpec& hole, HoleGeometry& g, const TargetObstacle& obstacle, const FilmLimits& limits);

/// Gauss-Legendre nodes (ascending) and weights on [0, 1] (src/analyze/gauss_legendre.hpp mapped).
void gauss_legendre_01(int n, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace cg::features
