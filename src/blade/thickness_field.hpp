#pragma once
// Wall thickness over the blade (constant or a table over span and chord) and its interpolation.
#include <vector>

namespace cg::blade {

/// Wall thickness over the blade, mm: constant, or a table over span fraction and chordwise coordinate
/// (blade_coordinates.hpp: 0 LE, (0, 1] suction side, [-1, 0) pressure side). The table is interpolated
/// by monotone piecewise-cubic Hermite interpolation (Fritsch & Carlson 1980) along chord, then along
/// span: C1 where the data are monotone, never outside the range of the table, constant beyond its ends.
class ThicknessField {
 public:
  ThicknessField() = default;
  static ThicknessField constant(double thickness);
  /// values[i][j] at spans[i], chords[j]; spans and chords strictly increasing; values > 0.
  /// A single span or chord row is allowed (constant along that direction). Throws InvalidGeometry.
  static ThicknessField table(std::vector<double> spans, std::vector<double> chords,
                              std::vector<std::vector<double>> values);

  double at(double span, double chord) const;
  double min_value() const { return min_; }
  double max_value() const { return max_; }
  bool is_constant() const { return spans_.empty(); }
  /// False when the thickness is the same at every chord of a span (a constant, or a table of one chord).
  bool varies_along_chord() const { return chords_.size() > 1; }
  /// The thickness where it is the same at every span and every chord in [lo, hi] (every row's values at
  /// the chord nodes bracketing [lo, hi] equal: the interpolant is flat there), else NaN.
  double constant_over(double lo, double hi) const;

 private:
  std::vector<double> spans_, chords_;
  std::vector<std::vector<double>> values_;
  double min_ = 0, max_ = 0;
};

/// Monotone cubic Hermite interpolation of (x[i], y[i]) at t (Fritsch & Carlson 1980); x strictly
/// increasing; constant beyond the ends; a single point gives a constant.
double monotone_cubic(const std::vector<double>& x, const std::vector<double>& y, double t);

}  // namespace cg::blade
