#pragma once
// What a configuration asks for under "cooling" for film cooling and impingement (parsed and range-
// checked by src/config/cooling_film_config.cpp; JSON form and ranges in data/schema/coolinggen.schema.json,
// parameters described in the README, "Cooling features: film holes and inserts").
// Lengths mm, angles degrees. Chordwise positions are blade-relative (src/blade/blade_coordinates.hpp):
// 0 at the LE, (0, 1] on the suction side, [-1, 0) on the pressure side; span fractions 0 hub, 1 casing.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/brep/boolean/boolean_retries.hpp"
#include "features/film/hole_shape.hpp"
#include "src/core/error.hpp"

namespace cg::features {

/// Where a row lies chordwise: a blade chordwise coordinate, or a surface arc length (mm) from the
/// LE measured along the section at each hole's span (+ suction side, - pressure side).
struct RowPosition {
  enum class Kind { Chord, ArcLength } kind = Kind::Chord;
  double value = 0;
};

/// A row of film holes along the span.
struct FilmRowDefinition {
  HoleShape shape;
  RowPosition position;
  double span_start = 0.1, span_end = 0.9;  ///< span fractions of the first and last hole centre's range
  int count = 0;       ///< > 0: this many holes, one per pitch cell of the row length (pitch = length / count)
  double pitch_d = 0;  ///< > 0: pitch P / D along the row (holes centred in the span range)
  double stagger = 0;  ///< shift of the holes along the row, fraction of the pitch, [0, 1)
  /// Angle between the hole axis and the surface, (0, 90]; the axis leans downstream.
  double inclination_deg = 30;
  /// Angle between the axis' projection on the surface and the streamwise direction (LE -> TE),
  /// [-90, 90]; positive turns it towards the tip (+span).
  double compound_deg = 0;
  int chamber = 0;  ///< expected chamber (1-based); 0: whichever its holes reach (all the same)
};

/// Showerhead: staggered rows about the LE stagnation line, holes angled to the span direction.
struct ShowerheadDefinition {
  int rows = 5;
  double diameter = 0.99;       ///< mm
  double row_spacing_d = 4;     ///< row spacing along the surface (arc length), in D
  double pitch_d = 7.5;         ///< spanwise pitch, in D
  double stagnation_arc = 0;    ///< mm, surface arc length of the stagnation line from the LE (+ suction side)
  /// Angle between the hole axis and the span direction, in the plane of the span direction and the
  /// surface normal, (0, 90]; 90 = normal to the surface.
  double radial_angle_deg = 30;
  bool toward_tip = true;       ///< the coolant leaves towards the tip (false: towards the hub)
  double span_start = 0.1, span_end = 0.9;
  int chamber = 0;              ///< expected chamber (1-based), 0: any
};

/// Impingement insert: a thin-walled shell inside a chamber (its own body, not cut from the blade).
struct InsertDefinition {
  int chamber = 1;               ///< the chamber it sits in (1-based)
  double gap = 1.0;              ///< Z, jet-to-target distance: offset from the chamber wall, mm
  double sheet_thickness = 0.4;  ///< mm
  /// Distance of the insert's ends from the chamber's end walls (hub floor, tip cap), mm; NaN: the gap.
  double hub_gap = std::numeric_limits<double>::quiet_NaN(), tip_gap = std::numeric_limits<double>::quiet_NaN();
  bool hub_open = true, tip_open = true;  ///< open or closed (capped with a sheet) ends
  /// Jet holes through the sheet, normal to it.
  double jet_diameter = 0.5;     ///< D, mm
  double jet_spacing_x_d = 8;    ///< x / D, spacing along the sheet around the chamber (chordwise)
  double jet_spacing_y_d = 8;    ///< y / D, spacing along the span
  bool staggered = true;         ///< alternate chordwise lines shifted by half the spanwise spacing
  double jet_margin = 1.0;       ///< mm, jet hole edges kept this far from the insert's ends and corners
};

/// Limits of the design checks (errors when violated) and tool trimming.
struct FilmLimits {
  double min_ligament = 0.3;  ///< mm of metal between a hole and another hole, a rib or an end wall
  double clearance = 0.15;    ///< mm the tools overshoot the outer and cavity walls along their lines
};

struct FilmCoolingDefinition {
  std::vector<FilmRowDefinition> rows;              ///< "film_rows", named film_row_<k>
  std::optional<ShowerheadDefinition> showerhead;   ///< "showerhead", rows named showerhead_<k>
  std::vector<InsertDefinition> inserts;            ///< "inserts", named insert_<k>
  FilmLimits limits;                                ///< "film_limits"
  PerturbedRetries retries = PerturbedRetries::Any; ///< "booleans.allow_perturbation" (boolean_retries.hpp)
  bool has_holes() const { return !rows.empty() || showerhead.has_value(); }
  bool empty() const { return !has_holes() && inserts.empty(); }
};

/// Film or insert input that cannot be built on this blade. `field` is the JSON path below "cooling"
/// of the value to change (e.g. "film_rows[1].pitch_d"); the message names the hole and the limit.
class FilmInputError : public InvalidGeometry {
 public:
  FilmInputError(std::string field, const std::string& what) : InvalidGeometry(what), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

}  // namespace cg::features
