#pragma once
// The section of the wall at any span: the one definition of a section shared by the blade-relative
// coordinates and the cooling features (issue 8, item 3).
//
// The section at span s is the iso-curve v = s of the wall surface (exact: src/blade/surface_iso.hpp).
// It lies on the stream surface at span s (meridional; the plane z = s * span for straight vanes) and on
// the section the blade is defined to have there within the model's surface_tolerance (the fit checks
// both at the same parameter, wall_fit.hpp). Its LE is the point at u = model.u_le and its TE the point
// at u = model.u_te, on every span. The chordwise coordinate is the arc-length fraction of the side on
// this 3D curve (chordwise.hpp): 0 at the LE, +1 / -1 at the TE exactly, true mm along the wall.
#include <Eigen/Core>
#include <memory>

#include "src/blade/blade_surface.hpp"
#include "src/blade/chordwise.hpp"
#include "src/blade/iso_arc_length.hpp"

namespace cg::blade {

class SpanSection {
 public:
  /// span in the surface's v domain [-overbuild, 1 + overbuild] (InvalidGeometry outside).
  SpanSection(const BladeModel& model, double span);
  /// The same, with the Gauss nodes of the arc-length table shared by all spans (iso_arc_length.hpp:
  /// built from any iso-curve of model.surface): the section then costs a few multiply-adds per node.
  SpanSection(const BladeModel& model, double span, std::shared_ptr<const IsoArcLengthNodes> nodes);

  double span() const { return span_; }
  /// The 3D section curve; its parameter is the surface u (period 1, seam at 0).
  const BSplineCurve<3>& curve() const { return *curve_; }
  /// Surface u in [0, 1) of chordwise coordinate c in [-1, 1] (InvalidGeometry outside); Near: for
  /// scans (chordwise.hpp).
  double u_at_chordwise(double c, ChordAccuracy accuracy = ChordAccuracy::Exact) const;
  /// Chordwise coordinate of surface u (any u, wrapped).
  double chordwise_at_u(double u) const { return map_.chordwise_at(u); }
  Eigen::Vector3d point(double c) const { return curve_->point(u_at_chordwise(c)); }
  /// Arc lengths of the suction side (LE -> TE) and of the pressure side, mm.
  double suction_length() const { return map_.suction_length(); }
  double pressure_length() const { return map_.pressure_length(); }
  /// Chordwise coordinate of the wall's periodic seam (u = 0) on this span: +1 with the seam at the TE.
  double seam_chordwise() const;

 private:
  double span_ = 0;
  double u_te_ = 0;
  std::shared_ptr<const BSplineCurve<3>> curve_;  // shared, so copies keep map_ valid
  ChordwiseMap<3, IsoArcLength> map_;
};

}  // namespace cg::blade
