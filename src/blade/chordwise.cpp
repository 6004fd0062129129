#include "src/blade/chordwise.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade {

template <int Dim, class Table>
ChordwiseMap<Dim, Table>::ChordwiseMap(const BSplineCurve<Dim>& c, double le, double te, Table table)
    : curve_(&c), table_(std::move(table)), first_(c.first_param()), period_(c.period()) {
  require(c.is_periodic(), "chordwise coordinate: the section curve must be closed (periodic)");
  le_ = c.check_param(le);
  te_ = c.check_param(te);
  while (te_ <= le_) te_ += period_;
  require(te_ - le_ < period_, "chordwise coordinate: the LE and TE coincide");
  at_le_ = length_to(le_);
  suction_ = length_to(te_) - at_le_;
}

template <int Dim, class Table>
double ChordwiseMap<Dim, Table>::length_to(double u) const {
  const double k = std::floor((u - first_) / period_);
  return table_.length_to(std::clamp(u - k * period_, first_, first_ + period_)) + k * table_.total();
}

template <int Dim, class Table>
double ChordwiseMap<Dim, Table>::param_at_length(double s, ChordAccuracy accuracy) const {
  const double k = std::floor(s / table_.total());
  const double in = std::clamp(s - k * table_.total(), 0.0, table_.total());
  if constexpr (std::is_same_v<Table, IsoArcLength>)
    if (accuracy == ChordAccuracy::Near) return table_.param_near(in) + k * period_;
  return table_.param_at(in) + k * period_;
}

template <int Dim, class Table>
double ChordwiseMap<Dim, Table>::param_at(double c, ChordAccuracy accuracy) const {
  if (!(c >= -1 && c <= 1))  // (message built only on failure: hot path)
    throw InvalidGeometry("chordwise coordinate " + format_number(c) + " is outside [-1, 1]");
  if (c == 0) return le_;
  if (c == 1 || c == -1) return te_;  // exactly the TE, not its arc-length image
  if (c > 0) return param_at_length(at_le_ + c * suction_, accuracy);
  return param_at_length(at_le_ + suction_ + (1 + c) * pressure_length(), accuracy);
}

template <int Dim, class Table>
double ChordwiseMap<Dim, Table>::chordwise_at(double u) const {
  double d = u - le_;
  d -= std::floor(d / period_) * period_;  // [0, period): forward from the LE
  const double w = le_ + d;
  if (w == le_) return 0.0;
  if (w == te_) return 1.0;
  const double s = length_to(w) - at_le_;
  if (w < te_) return std::min(1.0, s / suction_);
  return std::max(-1.0, -(table_.total() - s) / pressure_length());
}

template class ChordwiseMap<2>;
template class ChordwiseMap<3>;
template class ChordwiseMap<3, IsoArcLength>;

}  // namespace cg::blade
