#pragma once
// What film holes are drilled into: the outer wall of the blade, the cavity wall behind it (the inner
// wall of the core) and how the cavity is divided: chambers, and the obstacles in it that a hole must
// keep clear of (ribs and their fillets, end walls, inserts).
//
// The cavity wall is one B-spline surface (the inner wall of src/blade/inner_wall.hpp, or any core
// surface); a hole's axis enters the cavity where it crosses it. The chamber it feeds is found from the
// chordwise coordinate of that point's foot on the outer wall (BladeCoordinates::locate: exact for an
// inner wall, which is a true offset), compared with each chamber's chordwise extent. Obstacles are
// signed distance functions (mm, negative inside the obstacle), so the passages, the inserts and test
// fixtures can all describe theirs without this file knowing their geometry.
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "features/film/film_definition.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

struct TargetChamber {
  int number = 1;                ///< 1-based, from the LE
  std::string name = "chamber_1";
  /// Chordwise extent (blade coordinates of the inner wall's feet on the outer wall): suction side
  /// [suction_from, suction_to] in [0, 1], pressure side [pressure_from, pressure_to] in [-1, 0].
  /// The LE chamber has suction_from = pressure_to = 0.
  double suction_from = 0, suction_to = 1, pressure_from = -1, pressure_to = 0;
  /// How far (mm, along the hole axis) a hole tool may reach past the cavity wall into this chamber
  /// (e.g. the jet-to-target gap of an insert minus a margin); infinity: limited by the far wall only.
  double reach = std::numeric_limits<double>::infinity();
  bool contains(double chord) const;
};

struct TargetObstacle {
  std::string name;  ///< "rib_1", "tip_cap", "insert_1" ...
  /// Signed distance from a point to the obstacle's material, mm (negative inside). Only needs to be
  /// exact near the obstacle (within a few hole diameters); far values may be any lower bound > 0.
  std::function<double(const Eigen::Vector3d&)> distance;
  /// True: a hole must keep the film ligament from it (ribs, end walls); false: the tool must only not
  /// touch it (an insert behind the gap).
  bool needs_ligament = true;
  /// The config field (suffix of the row's path) to name when a hole comes too close, e.g. ".span_end"
  /// for the tip cap; empty: the row's position field (".chord" ...).
  std::string field;
};

struct HoleTarget {
  const blade::BladeModel* model = nullptr;  ///< outer wall
  BSplineSurface<3> cavity_wall;             ///< the inner wall of the core
  std::vector<TargetChamber> chambers;
  std::vector<TargetObstacle> obstacles;
  /// Index into chambers of the chamber holding `chord` (-1: none).
  int chamber_at(double chord) const;
};

/// How far a hole tool may reach into a chamber that holds an insert of gap Z: Z less a margin,
/// max(0.05 mm, Z / 4) (film_cooling.hpp).
double insert_reach(double gap);

/// Sets the reach of every chamber of `target` that holds one of `inserts` (insert_reach).
void limit_reach_by_inserts(HoleTarget& target, const std::vector<InsertDefinition>& inserts);

/// Signed distance to an end wall given as an end trim (src/brep/blade_solid.hpp): a plane, or the
/// surface of revolution of a meridional curve about the x axis (distance in the (x, r) plane, which is
/// the 3D distance for a surface of revolution). Positive on the side of `inside`. Not thread-safe: one
/// function per thread.
std::function<double(const Eigen::Vector3d&)> end_wall_distance(const brep::EndTrim& trim, const Eigen::Vector3d& inside);

}  // namespace cg::features
