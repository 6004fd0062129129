#pragma once
// The blade's sections at every span (internal to the blade model): the defined sections where given
// and, between them, the sections a designer means (issue 8, item 1):
//  - all sections parametric (same points_per_side): every parameter (chord, stagger, metal angles,
//    thickness and its position, LE/TE radii) and every placement value (rotation, scale, offset,
//    theta) follows the natural cubic spline through the defined sections over span
//    (span_spline.hpp), and the section at a span is built from those parameters;
//  - otherwise (point sections, or mixed): each defined section is taken apart into its stacking point,
//    its chord angle (stagger) and its shape in the chord-aligned frame about the stacking point; the
//    stacking point, the angle and the aligned shape (point by point at equal chordwise coordinate,
//    chordwise.hpp) are interpolated over span by the same splines and put together again, so a twist
//    is a rotation of the blended shape, never a pole-by-pole blend of rotated outlines.
//  - one section: the same profile at every span.
// Each slice is then placed on its stream surface (meridional flow path: streamline at that span,
// fitted between the LE and TE lines, see blade_surface.hpp) or in the plane z = span * span length.
//
// Common parametrisation of all slices (the u of the wall surface): periodic, period 1, the seam at
// u = 0; the LE at u_le and the TE at u_te on every slice. The seam is the TE by default (u_te = 0),
// or the point at a given chordwise coordinate of the mid-span section (blended families: of a section
// whose sides split the perimeter as the mean of the defined sections'; its u is then common, its
// chordwise coordinate varies slightly with span).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/blade/chordwise.hpp"
#include "src/blade/span_spline.hpp"

namespace cg::blade::detail {

class SectionFamily;

/// The section at one span, ready to be sampled at surface parameters u.
class FamilySlice {
 public:
  double span() const { return span_; }
  /// Section-frame points (mm) at surface parameters u (any order, each in [0, 1]).
  std::vector<Eigen::Vector2d> points_2d(const std::vector<double>& u) const;
  /// 3D points at surface parameters u.
  std::vector<Eigen::Vector3d> points_3d(const std::vector<double>& u) const;
  /// The slice as an exact 3D curve on the family's common knots, when it is one (straight vane whose
  /// slices are splines on one parametrisation); empty otherwise.
  const std::optional<BSplineCurve<3>>& exact_3d() const { return exact_3d_; }
  /// LE and TE of the slice in the section frame.
  Eigen::Vector2d le() const { return le_; }
  Eigen::Vector2d te() const { return te_; }
  /// Maps a section-frame point to 3D (straight: (a, b, z); meridional: onto the stream surface).
  Eigen::Vector3d place(const Eigen::Vector2d& q) const;
  /// Inverse of place() for points on the slice's stream surface / plane: the section-frame points
  /// (meridional: m' of the closest streamline point, theta about the axis).
  std::vector<Eigen::Vector2d> unplace(const std::vector<Eigen::Vector3d>& p) const;

 private:
  friend class SectionFamily;
  const SectionFamily* family_ = nullptr;
  double span_ = 0;
  // Parametrisation by a spline curve (seam at u = 0), or by blending the defined shapes.
  std::optional<BSplineCurve<2>> curve_;
  std::vector<double> weights_;  // blending: cardinal weights of the defined sections at this span
  double angle_ = 0;             // blending: chord angle (rad)
  Eigen::Vector2d stack_ = Eigen::Vector2d::Zero();
  double lambda_ = 0.5;          // blending: pressure-side share of the perimeter at this span
  std::optional<BSplineCurve<3>> exact_3d_;
  Eigen::Vector2d le_ = Eigen::Vector2d::Zero(), te_ = Eigen::Vector2d::Zero();
  // Placement.
  double z_ = 0;  // straight vane
  std::shared_ptr<const Streamline> line_;
  double mp_le_ = 0, r_ref_ = 1, k_scale_ = 1, theta0_ = 0, a_le_ = 0, b_stack_ = 0;
  Eigen::Vector2d offset_ = Eigen::Vector2d::Zero();
};

class SectionFamily {
 public:
  enum class Kind { Single, Parametric, Blended };

  /// def must be validated (spans, overbuild); net is the built meridional net for a meridional path.
  SectionFamily(const BladeDefinition& def, const std::optional<MeridionalNet>& net, double span_mm);
  SectionFamily(const SectionFamily&) = delete;
  SectionFamily& operator=(const SectionFamily&) = delete;

  Kind kind() const { return kind_; }
  bool straight() const { return !net_; }
  /// The slice at span s (throws InvalidGeometry naming the span when the section there is invalid).
  FamilySlice slice(double s) const;
  /// Spans of the defined sections (a single section: {0, 1}); the placed profiles there.
  const std::vector<double>& defined_spans() const { return spans_; }
  const std::vector<SectionProfile>& defined_profiles() const { return profiles_; }
  /// Surface u of the LE and TE on every slice; the seam is at u = 0.
  double u_le() const { return u_le_; }
  double u_te() const { return u_te_; }
  /// Knots (one period in [0, 1), starting with 0) on which every slice is exact (Single and
  /// Parametric kinds); empty for blended families.
  const std::vector<double>& common_knots() const { return common_knots_; }

 private:
  friend class FamilySlice;
  SectionProfile profile_at(double s) const;  // Single / Parametric kinds
  void place(FamilySlice& f) const;
  Eigen::Vector2d blended_point(const FamilySlice& f, double u) const;

  Kind kind_ = Kind::Single;
  BladeOptions options_;
  std::optional<MeridionalNet> net_;
  double span_mm_ = 0;
  std::vector<double> spans_;
  std::vector<SectionProfile> profiles_;  // placed, one per defined span
  SpanSpline spline_;
  // Parametric kind: the definitions and placements along span.
  std::vector<ParametricSectionDefinition> parametric_;
  std::vector<SectionPlacement> placements_;
  // Blended kind: per defined section its aligned shape (chordwise coordinate -> parameter on its own
  // curve), chord angle, stacking point and pressure-side share.
  struct ArcTable;  // chordwise coordinate -> profile parameter, tabulated (section_family.cpp)
  std::vector<std::shared_ptr<const ArcTable>> tables_;
  std::vector<double> angles_, lambdas_;
  std::vector<Eigen::Vector2d> stacks_;
  double lambda_le_ = 0.5;  // common pressure-side share: u' of the LE (u' measured from the TE)
  double u_seam_ = 0;       // u' of the seam
  // Common parametrisation of the Single / Parametric kinds: profile parameter of the seam.
  double seam_param_ = 0;
  std::vector<double> common_knots_;
  double u_le_ = 0, u_te_ = 0;
};

/// Stacking point of a profile (LE, TE or centroid).
Eigen::Vector2d stacking_point(const SectionProfile& s, StackingPoint mode);

}  // namespace cg::blade::detail
