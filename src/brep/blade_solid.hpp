#pragma once
// Closed B-rep solid of a blade: the exact blade surface cut to the flow path by two end trims.
//
// Axis convention: the engine axis is the x axis; the radius of a point is r = sqrt(y^2 + z^2).
// A meridional curve (x, r) is revolved about the x axis.
//
// Method (the way turbine blades are cut to the flow path): the blade surface, periodic (closed) in
// u and over-built in v past both trims, becomes one face with a seam; each trim becomes one face
// (a bounded plane, or the surface of revolution of the meridional curve). One general fuse
// (BOPAlgo_Builder) splits all three faces along their intersection curves. The blade piece that
// meets both trims is the wall; the trim pieces bounded only by intersection edges with the wall are
// the end faces. These share their edges already, so they form a closed shell without sewing
// tolerances. OCCT gets the exact surface (no re-lofting); the trim surfaces are exact too.
#include <Geom_SurfaceOfRevolution.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"
#include "src/core/progress.hpp"

namespace cg::brep {

/// A planar end trim (straight vane end wall): a point on the plane and its normal (any sign;
/// the kept side follows from which part of the blade lies between the two trims).
struct PlaneTrim {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

/// An end trim on the surface of revolution of a meridional curve (x, r) about the x axis
/// (hub or casing of the flow path). The curve's x range must cover the blade where it cuts it,
/// and r > 0 is required on every pole (so r > 0 on the whole curve, by the convex hull property).
struct RevolvedTrim {
  BSplineCurve<2> meridional;
};

using EndTrim = std::variant<PlaneTrim, RevolvedTrim>;

/// Face names carried into the STEP file.
inline constexpr const char* kWallFaceName = "blade_wall";
inline constexpr const char* kHubFaceName = "hub";
inline constexpr const char* kCasingFaceName = "casing";

struct BladeSolid {
  TopoDS_Solid solid;
  std::vector<NamedFace> faces;  ///< every face of `solid`, named by the surface it lies on
  /// Warnings of the general fuse (BOPAlgo alert names). Empty in a clean run; the notes on
  /// booleans list warnings that came with silently wrong results, so callers should report them.
  std::vector<std::string> warnings;
  /// How the wall was cut to the flow path: along its own iso-curves v = 0 and 1 (a blade model whose
  /// end sections lie on the trims), or by the general fuse with the trim surfaces.
  bool trimmed_along_iso_curves = false;
};

/// Builds the blade solid between the `hub` and `casing` trims.
/// `surface`: u periodic (chordwise, closed section), v spanwise and extending past both trims.
/// Throws InvalidGeometry on bad input (surface not u-periodic, v-periodic, degenerate plane
/// normal, meridional curve with r <= 0) and AlgorithmFailure when the trims do not cut the blade
/// into one wall between them (e.g. not enough over-build, trims that cross inside the blade).
/// `progress` (optional) sees the general fuse's progress; a stop request ends it with Cancelled.
BladeSolid build_blade_solid(const BSplineSurface<3>& surface, const EndTrim& hub, const EndTrim& casing,
                             ProgressSink* progress = nullptr);

/// The whole surface of revolution of the trim's meridional curve about the x axis, its basis curve at
/// angle theta0 (rad). Throws InvalidGeometry (naming `which`) for a periodic curve or a pole with r <= 0.
Handle(Geom_SurfaceOfRevolution) revolved_surface(const RevolvedTrim& t, double theta0, const char* which);

/// The end trims of a blade model's flow path: the planes z = hub_z and z = casing_z (straight vane)
/// or the revolved hub and casing contours (meridional).
EndTrim hub_trim(const blade::FlowPathTrim& trim);
EndTrim casing_trim(const blade::FlowPathTrim& trim);

/// The model's solid. Its sections at span 0 and 1 lie on hub and casing within the model's surface
/// tolerance, so the wall is cut along its own iso-curves v = 0 and 1: the wall face is the surface on
/// v in [0, 1] (edges: exact iso-curves, straight pcurves), each end face is the trim surface bounded
/// by that edge (pcurve on a surface of revolution: the edge's foot points interpolated at its own
/// parameter); edge tolerance = the iso-curve's measured distance from the trim (x 1.5) plus the
/// pcurve's error. No intersection curves, so the boundary stays as light as the wall. Falls back to
/// build_blade_solid(model.surface, hub_trim(model.trim), casing_trim(model.trim), progress) when the
/// end sections are farther from the trims than the surface tolerance.
BladeSolid build_blade_solid(const blade::BladeModel& model, ProgressSink* progress = nullptr);

}  // namespace cg::brep
