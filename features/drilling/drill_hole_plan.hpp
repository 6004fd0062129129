#pragma once
// The planning stage of direct drilling (drill_holes.hpp): the part's faces indexed for line queries,
// and per hole the faces it crosses, its loops and the preconditions it meets (or why not). Internal
// to drill_holes.cpp (drill_holes and drill_fallback_reasons).
#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "src/core/parallel.hpp"
#include "features/drilling/drill_hole_geometry.hpp"
#include "features/drilling/drill_hole_topology.hpp"
#include "features/drilling/drill_holes.hpp"

namespace cg::features::drill_detail {

/// A face of the (patched) part.
struct FaceInfo {
  TopoDS_Face face;      // oriented as in its shell (relative)
  TopoDS_Face oriented;  // oriented as in the solid (outward normal of the part)
  std::string name;
  int surface = -1;  // index into Part::surfaces; -1: not a B-spline face without location
  int shell = 0;
  Bnd_Box box;
};

/// The part's faces with their shells, and the distinct B-spline surfaces (ours and OCCT's) they lie on.
struct Part {
  std::vector<FaceInfo> faces;
  std::vector<TopoDS_Shell> shells;
  std::vector<std::shared_ptr<const BSplineSurface<3>>> surfaces;
  std::vector<WallFaceGeometry> occt_surfaces;
  std::vector<std::vector<int>> faces_on_surface;
  TopAbs_Orientation solid_orientation = TopAbs_FORWARD;
};

/// Indexes the faces of a one-solid part (throws InvalidGeometry otherwise).
Part index_part(const brep::NamedShape& part);

/// What the planning finds for one hole.
struct HolePlan {
  HoleCylinder cyl;
  Bnd_Box box;
  std::string reason;  // fallback reason ("" = drillable)
  int entry = -1, exit = -1;
  AxisHit entry_hit, exit_hit;
  HoleLoop entry_loop, exit_loop;
  double quadrature = std::numeric_limits<double>::quiet_NaN();
};

/// Validated holes (InvalidGeometry naming the hole) with their cylinders and boxes.
std::vector<HolePlan> initial_plans(const std::vector<CylindricalHole>& holes, const DrillOptions& o);

/// Plans every hole (parallel): faces crossed, loops, preconditions, quadrature volume; holes within
/// the margin of each other fall back together (the boolean path fuses overlapping tools).
void plan_holes(const Part& part, std::vector<HolePlan>& plans, const std::vector<CylindricalHole>& holes,
                const DrillOptions& o);

}  // namespace cg::features::drill_detail
