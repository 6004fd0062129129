#pragma once
// The B-rep tool solid of one film hole (the solid the verified boolean cuts from the blade).
//
// Along the axis a hole is measured by s, the distance from the exit point E along d (s < 0 outside
// the blade). The tool runs from s_top (outside, its planar top end clear of the outer surface) to
// s_end (inside the chamber, its planar end just past the inner wall): tools trimmed to just cross the
// wall keep the booleans cheap and safe (../shared/notes/booleans.md).
//  - Cylindrical: BRepPrimAPI_MakeCylinder (a cylinder face and two discs; the boolean path detects its
//    axis for seam-rotating retries).
//  - Fan-shaped: metering cylinder from s_end to the diffuser start s_d (four quarter-cylinder faces),
//    diffuser from s_d to s_top: two lateral and the back and front walls are planar triangles, the four
//    corners ruled patches between the quarter arcs of the metering circle and the corner arcs of the
//    top section (exact: GeomFill ruled surfaces between circles), closed by the planar rounded-
//    rectangle top and the metering disc; faces sewn (BRepBuilderAPI_Sewing, 1e-7 mm) into one solid.
//  - An oblique end: the tool is built past the end plane and cut by it (BRepAlgoAPI_Common with a box
//    whose face lies on the plane); a cylinder cut by a plane keeps the volume pi r^2 times its length on
//    the axis, so the analytic volume stays exact.
#include <TopoDS_Shape.hxx>

#include "features/film/hole_shape.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct HoleToolExtent {
  double s_top = -1;       ///< mm along d from the exit point (< s_diffuser)
  double s_end = 1;        ///< mm along d where the end plane meets the axis (> s_diffuser for a fan-shaped hole)
  double s_diffuser = 0;   ///< diffuser start (fan-shaped only)
  double diffuser_length = 0;  ///< L_d the profile is defined with (fan-shaped only), mm
  /// Normal of the end plane (unit, towards the chamber, d . n >= 0.2); zero: the end is normal to the
  /// axis. An oblique end follows the cavity wall where the hole enters it at a shallow angle (e.g. a
  /// showerhead hole angled to the span), so the tool crosses the wall without reaching the far side.
  Eigen::Vector3d end_normal = Eigen::Vector3d::Zero();
};

/// The tool solid (outward oriented, valid). Throws InvalidGeometry for inconsistent extents and
/// AlgorithmFailure when OCCT cannot sew the faces into one closed solid.
TopoDS_Shape make_hole_solid(const HoleFrame& frame, const HoleShape& shape, const HoleToolExtent& extent);

/// The tool's own volume, analytic (cylinder; fan: metering cylinder + the integral of the exact
/// cross-section area polynomial), mm^3.
double hole_solid_volume(const HoleShape& shape, const HoleToolExtent& extent);

/// `solid` with every face named `name` (a hole's or an insert's tool).
brep::NamedShape named_all_faces(const TopoDS_Shape& solid, const std::string& name);

}  // namespace cg::features
