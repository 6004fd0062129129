#pragma once
// The outer blade surface: sections placed on the flow path and skinned into one B-spline surface,
// periodic in u (chordwise) and built past hub and casing (over-build) so the solid builder can trim it
// with the flow-path end surfaces.
//
// Surface parametrisation (relied on by blade_coordinates.hpp and the cooling features):
//  - v = span fraction (0 hub, 1 casing), domain [-overbuild, 1 + overbuild];
//  - u periodic with period 1: u = 0 is the LE, u in [0, u_te] the suction side, u = u_te the TE,
//    u in [u_te, 1] the pressure side. u is the section curves' own parameter (each section curve has
//    its seam at the LE and period 1), so the iso-curve v = span of a defined section IS that section:
//    the section curves are skinned as they are (src/fit/skin.hpp: compatible knots by refinement, pole
//    columns interpolated across the spans; The NURBS Book 10.3). The TE is at u = 0.5 on sections from
//    parameters (their curve parameter is the angle phi / 2 pi of the thickness construction) and at the
//    detected te_param on point sections; u_te is the mean of the sections' values, so with several
//    point sections whose te_param differ, the TE of section k is at profiles[k].te_param, not u_te.
//  - the over-build sections at v = -overbuild and 1 + overbuild extrapolate the two end sections
//    linearly (pole by pole).
//  - straight vane: 3D point (a, b, z) with z = span fraction * span; the 3D sections are the 2D
//    curves themselves (exact);
//  - meridional: (x, r cos theta, r sin theta), x axial (see meridional_net.hpp); this placement is not
//    rational, so each 3D section interpolates the placed 2D section to 1e-6 mm (section_3d.hpp), at
//    the same parameter (LE at u = 0, TE at the 2D curve's te_param).
//
// The JSON form of these structs is data/schema/coolinggen.schema.json (parsed by src/config); examples
// in data/examples/.
#include <Eigen/Core>
#include <optional>
#include <variant>
#include <vector>

#include "src/blade/meridional_net.hpp"
#include "src/blade/section.hpp"
#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::blade {

/// Straight (prismatic-type) vane between the planes z = 0 (hub) and z = span (casing), mm.
struct StraightFlowPath {
  double span = 0;
};

/// Flow path given by a meridional net; sections are placed on its stream surfaces.
struct MeridionalFlowPath {
  MeridionalNetDefinition net;
};

/// The point of a section used as pivot for rotation/scale and, on a meridional flow path, put at theta.
enum class StackingPoint { LeadingEdge, Centroid, TrailingEdge };

/// Placement of one section.
struct SectionPlacement {
  double span = 0;            // span fraction, [0, 1]; sections strictly increasing in span
  double rotation_deg = 0;    // rotation in the section frame about the stacking point (counter-clockwise)
  double scale = 1;           // uniform scale about the stacking point, > 0 (straight vane only;
                              // on a meridional path the LE/TE lines fix the scale when both are given)
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // mm, added in the section frame (a, b)
  double theta_deg = 0;       // meridional: circumferential angle of the stacking point
};

struct BladeSectionDefinition {
  std::variant<PointSectionDefinition, ParametricSectionDefinition> shape;
  SectionPlacement placement;
};

struct BladeOptions {
  double overbuild = 0.05;       // fraction of span added beyond hub and casing, (0, 0.5]
  /// Meridional blades: least number of interpolation points per side of each stream-surface section
  /// (more are used until the 1e-6 mm tolerance is met), [8, 2000]. Unused by straight vanes, whose
  /// sections are exact.
  int chordwise_samples = 97;
  StackingPoint stacking = StackingPoint::Centroid;
};

struct BladeDefinition {
  std::variant<StraightFlowPath, MeridionalFlowPath> flow_path;
  /// >= 1 sections; a single section is used at hub and casing.
  std::vector<BladeSectionDefinition> sections;
  BladeOptions options;
};

/// The flow-path end surfaces for the solid builder.
struct FlowPathTrim {
  bool straight = true;
  /// Straight vane: the planes z = hub_z and z = casing_z (normal +z).
  double hub_z = 0, casing_z = 0;
  /// Meridional: hub and casing contours in (x, r), to be revolved about the x axis.
  BSplineCurve<2> hub, casing;
};

struct BladeModel {
  BSplineSurface<3> surface;
  double u_te = 0.5;  // u of the TE (see the parametrisation above)
  FlowPathTrim trim;
  double span_length = 0;                 // straight: span; meridional: (x, r) distance of the LE cuts hub-casing
  std::vector<double> section_spans;      // spans of the defined sections
  std::vector<SectionProfile> profiles;   // 2D profiles after placement transforms (section frame)
  std::vector<BSplineCurve<3>> section_curves;  // 3D section curves = the iso-curves v = section_spans[k]
  std::optional<MeridionalNet> net;
  BladeOptions options;
};

/// Builds the blade. Throws InvalidGeometry for invalid definitions (naming the section / quantity).
BladeModel build_blade(const BladeDefinition& def);

/// Chordwise coordinate c in [-1, 1] (see SectionProfile::param_at_chordwise) <-> surface u in [0, 1).
double surface_u_at_chordwise(double c, double u_te);
double chordwise_at_surface_u(double u, double u_te);

}  // namespace cg::blade
