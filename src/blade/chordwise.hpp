#pragma once
// The chordwise coordinate of a closed blade section, in one place for the 2D profiles (section.hpp)
// and the 3D sections of the wall at any span (span_section.hpp, blade_coordinates.hpp).
//
// The section curve runs LE -> suction side -> TE -> pressure side -> LE with increasing parameter.
// Chordwise coordinate c in [-1, 1]: c = 0 at the LE; c in [0, 1] is the fraction of the suction side's
// arc length from the LE; c in [-1, 0] the same on the pressure side (|c| = fraction of the pressure
// side's arc length from the LE), so c = +1 and c = -1 are both the TE. c = 0, +-1 map to the LE and
// TE parameters exactly (not through the arc-length tables).
// Table: the arc-length table of the curve (ArcLength<Dim>, or IsoArcLength for the wall's iso-curves,
// which many spans build with shared Gauss nodes): total(), length_to(u), param_at(s).
#include <vector>

#include "src/analyze/arc_length.hpp"
#include "src/blade/iso_arc_length.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade {

/// How exactly a chordwise coordinate becomes a curve parameter: Exact, the table's inverse to its
/// rel_tol; Near, IsoArcLength::param_near (the wall's sections: within 1e-4 of the section's length,
/// at a seventh of the cost; other tables answer exactly), for scans that look for a neighbourhood and
/// refine it exactly, never for a placement.
enum class ChordAccuracy { Exact, Near };

template <int Dim, class Table = ArcLength<Dim>>
class ChordwiseMap {
 public:
  /// le_param, te_param: the LE and TE on the (periodic) curve, which must outlive the map.
  /// Throws InvalidGeometry for a non-periodic curve or LE == TE.
  ChordwiseMap(const BSplineCurve<Dim>& closed_curve, double le_param, double te_param)
      : ChordwiseMap(closed_curve, le_param, te_param, Table(closed_curve)) {}
  /// With the curve's table built by the caller.
  ChordwiseMap(const BSplineCurve<Dim>& closed_curve, double le_param, double te_param, Table table);

  double suction_length() const { return suction_; }
  double pressure_length() const { return table_.total() - suction_; }
  double perimeter() const { return table_.total(); }
  double le_param() const { return le_; }
  /// TE parameter in (le_param, le_param + period].
  double te_param() const { return te_; }
  /// Curve parameter at chordwise coordinate c in [-1, 1] (InvalidGeometry outside), in
  /// [le_param, le_param + period].
  double param_at(double c, ChordAccuracy accuracy = ChordAccuracy::Exact) const;
  /// Chordwise coordinate of curve parameter u (any u; wrapped by the period): in [0, 1] on the
  /// suction side, in (-1, 0) on the pressure side; the TE itself gives +1.
  double chordwise_at(double u) const;

 private:
  double length_to(double u) const;  // arc length from the curve's first parameter, continued by periods
  double param_at_length(double s, ChordAccuracy accuracy) const;
  const BSplineCurve<Dim>* curve_;
  Table table_;
  double first_, period_, le_, te_, at_le_, suction_;
};

extern template class ChordwiseMap<2>;
extern template class ChordwiseMap<3>;
extern template class ChordwiseMap<3, IsoArcLength>;

}  // namespace cg::blade
