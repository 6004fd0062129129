#pragma once
// The outer blade surface: the blade's sections at every span (section_family.hpp) placed on the flow
// path and turned into one B-spline surface, periodic in u (chordwise) and built past hub and casing
// (over-build) so that features and the solid builder have wall beyond the end walls.
//
// Between defined sections the blade follows the sections a designer means (issue 8, item 1): the
// parameters of parametric sections, or stacking point, chord angle and chord-aligned shape of point
// sections, interpolated by natural cubic splines over span; see section_family.hpp.
//
// Surface parametrisation (relied on by blade_coordinates.hpp, span_section.hpp and the features):
//  - v = span fraction: 0 hub, 1 casing, the iso-curve v = s is the section at span s on its stream
//    surface (meridional) or in the plane z = s * span (straight) within surface_tolerance; domain
//    [-overbuild, 1 + overbuild] (linear continuation past the ends);
//  - u periodic with period 1; the seam (u = 0) lies at chordwise coordinate options.seam of the
//    mid-span section (default +1: the middle of the TE, exactly, on every span); the LE is at u = u_le
//    and the TE at u = u_te on every iso-curve; increasing u runs LE -> suction side -> TE -> pressure
//    side -> LE. u itself is a smooth parameter, not the chordwise coordinate: that is the arc-length
//    fraction computed on the iso-curve (chordwise.hpp, span_section.hpp);
//  - straight vane: 3D point (a, b, z), z = span fraction * span; with one section (or parametric
//    sections) the iso-curves at the skinned spans are the exact section curves;
//  - meridional: (x, r cos theta, r sin theta), x axial (see meridional_net.hpp); sections are mapped
//    conformally onto their stream surface: m' = m'_LE + (k (a - a_LE) + offset_a) / r_ref,
//    theta = theta_0 + (k (b - b_stack) + offset_b) / r_ref, r_ref the LE radius and k scaling the section
//    between the LE and TE lines.
// The surface has the fewest poles that meet surface_tolerance (wall_fit.hpp): the achieved deviation
// and the pole counts are part of the model.
//
// The JSON form of these structs is data/schema/coolinggen.schema.json (parsed by src/config); examples
// in data/examples/.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "src/blade/import_record.hpp"
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
  /// Least number of points per side (suction, pressure) at which every section is fitted and checked
  /// against the surface; more are used as the fit needs more knots. [8, 2000]. The pole count follows
  /// the tolerance, not this number.
  int chordwise_samples = 97;
  StackingPoint stacking = StackingPoint::Centroid;
  /// Largest distance of the wall surface from the blade's sections at the same (span, u), mm,
  /// [1e-5, 0.1]: the surface gets the fewest poles meeting it.
  double surface_tolerance = 1e-3;
  /// Chordwise coordinate of the wall's periodic seam, [-1, 1] (+1 or -1: the middle of the TE;
  /// 0 would put it at the LE, where showerhead holes go).
  double seam = 1;
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

namespace detail {
class SectionFamily;
}

/// What was built for one defined section (report.json): measured on the placed 2D profile.
struct SectionDiagnostics {
  double span = 0;
  double chord = 0;         // mm, |TE - LE|
  double stagger_deg = 0;   // angle of the chord line (LE -> TE) from the +a axis, deg
  double area = 0;          // mm^2, enclosed by the profile in the section frame
  EdgeCircle le_circle, te_circle;
  int le_circle_points = 0, te_circle_points = 0;  // point sections: given points on each circle
  bool le_arc = false, te_arc = false;              // the profile follows the circle as an exact arc
};

struct BladeModel {
  BSplineSurface<3> surface;
  double u_le = 0;    // u of the LE on every span (see the parametrisation above)
  double u_te = 0;    // u of the TE on every span; 0 with the seam at the TE
  double seam = 1;    // configured chordwise coordinate of the seam (u = 0)
  FlowPathTrim trim;
  double span_length = 0;                 // straight: span; meridional: (x, r) distance of the LE cuts hub-casing
  std::vector<double> section_spans;      // spans of the defined sections (one section: {0, 1})
  std::vector<SectionProfile> profiles;   // 2D profiles after placement transforms (section frame)
  std::vector<BSplineCurve<3>> section_curves;  // 3D section curves = the iso-curves v = section_spans[k]
  std::vector<SectionDiagnostics> diagnostics;  // per defined section (one section: one entry)
  std::vector<double> skinned_spans;      // spans of the sections the surface interpolates
  double surface_tolerance = 0;           // requested, mm
  double surface_deviation = 0;           // achieved: largest deviation found at the check points, mm
  long surface_check_points = 0;
  std::optional<MeridionalNet> net;
  BladeOptions options;
  /// The sections at every span the surface was fitted to (section_family.hpp); shared, immutable.
  std::shared_ptr<const detail::SectionFamily> family;
  /// Imported blades (blade.import): the file, its blade count and the measured fidelity.
  std::optional<ImportRecord> imported;

  /// Distinct poles of the surface chordwise (one period) and spanwise.
  int poles_u() const { return surface.is_periodic_u() ? surface.num_poles_u() - surface.degree_u() : surface.num_poles_u(); }
  int poles_v() const { return surface.num_poles_v(); }
};

/// Builds the blade. Throws InvalidGeometry for invalid definitions (naming the section / quantity).
BladeModel build_blade(const BladeDefinition& def);


}  // namespace cg::blade
