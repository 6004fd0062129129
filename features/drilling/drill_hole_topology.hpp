#pragma once
// B-rep of a drilled hole, built directly from its two loops (drill_hole_geometry.hpp): the loop edges
// carry a 3D curve and a pcurve on the wall and on the cylinder (shared by construction, no sewing),
// the hole face is the cylinder between them with one seam edge, and a wall face is rebuilt on its own
// surface with its own wires plus the holes' loops as inner wires.
//
// Orientation (OCCT's convention): in the (u, v) plane of a FORWARD face its material lies to the left
// of its oriented edges, so the outer wire runs counterclockwise and a hole's inner wire clockwise.
#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

#include <vector>

#include "features/drilling/drill_hole_geometry.hpp"

namespace cg::features {

/// A wall face's surface as OCCT holds it (the pcurves of loop edges are registered on it).
struct WallFaceGeometry {
  Handle(Geom_Surface) surface;  ///< BRep_Tool::Surface of the face (may be a trimmed B-spline)
  TopLoc_Location location;
};

/// A loop edge and the sense in which it runs in the wall's (u, v) plane.
struct LoopEdge {
  TopoDS_Edge edge;
  bool counterclockwise = true;  ///< the edge's FORWARD direction runs counterclockwise on the wall
  double tolerance = 0;          ///< mm
  double length = 0;             ///< mm (of the 3D curve, from the nodes)
  TopoDS_Wire wire;              ///< its inner wire in the rebuilt wall face (set by wall_with_holes)
};

/// The hole: its face (FORWARD: the cylinder's own normal, out of the hole's material) and loop edges.
struct HoleShape {
  TopoDS_Face face;
  LoopEdge entry, exit;
};

/// Builds the hole face between the loops on the entry and exit walls. Requires entry.t_max <
/// exit.t_min (the entry loop lies before the exit loop along the axis).
HoleShape build_hole_shape(const HoleCylinder& hole, const HoleLoop& entry, const WallFaceGeometry& entry_wall,
                           const HoleLoop& exit, const WallFaceGeometry& exit_wall);

/// `wall` (any orientation, kept) rebuilt with one inner wire per loop edge (stored in the loop edge).
TopoDS_Face wall_with_holes(const TopoDS_Face& wall, const std::vector<LoopEdge*>& loops);

/// The piece of `wall` inside a loop (same surface and orientation as `wall`): the material a hole
/// takes out of the wall's boundary, for the volume balance.
TopoDS_Face cap_face(const TopoDS_Face& wall, const LoopEdge& loop);

}  // namespace cg::features
