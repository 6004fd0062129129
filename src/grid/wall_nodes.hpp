#pragma once
// Wall node placement around a section: arc length from the LE over the suction side, the TE and the
// pressure side back to the LE, mapped to curve parameters through the section's chordwise coordinate
// (SectionProfile::params_at_chordwise: arc-length fractions per side).
#include <vector>

#include "src/analyze/arc_length.hpp"
#include "src/blade/section.hpp"

namespace cg::grid {

class WallArc {
 public:
  explicit WallArc(const blade::SectionProfile& section);
  double perimeter() const { return suction_ + pressure_; }
  double suction_length() const { return suction_; }
  double pressure_length() const { return pressure_; }
  /// Curve parameters at arc positions s (any real: wrapped by the perimeter, one period of parameter per
  /// perimeter, so increasing s gives increasing, unwrapped parameters).
  std::vector<double> params(const std::vector<double>& s) const;
  /// Arc position in [0, perimeter) of a curve parameter (any period).
  double position(double u) const;

 private:
  double wrap(double u) const;  // into the curve's base period
  const blade::SectionProfile* section_;
  ArcLength<2> table_;
  double suction_ = 0, pressure_ = 0, le_offset_ = 0;
};

/// Arc positions of `cells` + 1 nodes from the LE all the way round (first 0, last the perimeter) that
/// equidistribute 1 + clustering |curvature| perimeter / (2 pi), smoothed over about three mean cells.
std::vector<double> clustered_wall_positions(const blade::SectionProfile& section, const WallArc& arc, int cells,
                                             double clustering);

}  // namespace cg::grid
