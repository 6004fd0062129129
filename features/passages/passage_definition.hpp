#pragma once
// What a configuration asks for under "cooling" for the internal passages (parsed and range-checked
// by src/config/cooling_config.cpp; JSON form and ranges in data/schema/coolinggen.schema.json).
// Lengths mm. Chordwise positions are blade-relative coordinates (src/blade/blade_coordinates.hpp):
// 0 at the LE, (0, 1) on the suction side, (-1, 0) on the pressure side. Plain structs without OCCT, so
// the config stage can fill them.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "src/brep/boolean/boolean_retries.hpp"
#include "src/blade/inner_wall.hpp"

namespace cg::features {

/// An end of the span: the hub side or the tip (casing) side.
enum class SpanEnd { Hub, Tip };

/// A rib stops a gap short of an end wall, so the chambers on both sides join in a U-bend.
struct TurnaroundDefinition {
  SpanEnd end = SpanEnd::Tip;  ///< the end wall the rib stops short of (tip cap or hub floor)
  double gap = 0;              ///< mm, closest distance between the rib tip and that end wall, > 0
  double tip_radius = 0;       ///< mm, radius of the rounded rib tip, (0, thickness / 2]; = thickness / 2: full round
};

/// A partition wall between two chambers, from the suction to the pressure side.
struct RibDefinition {
  /// Where the rib's mid-surface meets the inner wall: the inner-wall points whose outer-wall feet lie
  /// at these chordwise coordinates (suction in (0, 1), pressure in (-1, 0)); different magnitudes give
  /// an inclined rib.
  double suction_chord = 0;
  double pressure_chord = 0;
  double thickness = 0;      ///< mm, normal to the mid-surface
  double fillet_radius = 0;  ///< mm, fillets in the concave corners with the inner wall; 0 = sharp
  std::optional<TurnaroundDefinition> turnaround;  ///< none: the rib runs from the hub floor to the tip cap
};

/// End wall of the core: the tip cap or the hub floor. open = the core runs through the end (the chambers
/// are open there, e.g. for an impingement insert or a passage fed from the casing).
struct EndWallDefinition {
  double thickness = 0;  ///< mm, normal to the flow-path surface, > 0 unless open
  bool open = false;
};

/// A circular coolant inlet through an end wall into a chamber, axis along the blade's span direction.
struct InletDefinition {
  int chamber = 1;             ///< 1-based, numbered from the LE
  SpanEnd end = SpanEnd::Hub;  ///< through the hub floor or the tip cap
  double diameter = 0;         ///< mm
  /// Chordwise position of the axis (midway between the chamber's suction- and pressure-side wall points
  /// at these chords); NaN: the middle of the chamber.
  double suction_chord = std::numeric_limits<double>::quiet_NaN();
  double pressure_chord = std::numeric_limits<double>::quiet_NaN();
};

/// Which chamber walls carry turbulators.
enum class TurbulatorWalls { Both, Suction, Pressure };

/// Rib turbulators on the suction- and/or pressure-side wall of one chamber: transverse ribs of
/// rectangular cross-section standing on the inner wall (fused onto the blade: material added).
struct TurbulatorDefinition {
  int chamber = 1;                  ///< 1-based, numbered from the LE
  TurbulatorWalls walls = TurbulatorWalls::Both;
  double height = 0;                ///< mm, e: normal to the inner wall, into the chamber
  double width = 0;                 ///< mm, across the turbulator (along the passage axis at 90 deg)
  double pitch = 0;                 ///< mm, P: along the passage axis (span), centre to centre
  double angle_deg = 90;            ///< angle to the passage axis (span direction), [30, 90]
  bool staggered = false;           ///< pressure-side row shifted by pitch / 2 against the suction side
  double end_gap = 0.2;             ///< mm, clear gap between a turbulator end and a rib fillet / the LE
  double span_margin = 1.0;         ///< mm, clear span between the turbulators and the end walls / U-bends
};

/// Pin fins across the last chamber upstream of the trailing-edge slots, staggered rows.
struct PinFinDefinition {
  double diameter = 0;           ///< mm
  double spanwise_pitch = 0;     ///< mm, S: between pins of one row
  double streamwise_pitch = 0;   ///< mm, X: between rows
  int rows = 1;
  double slot_gap = 0.5;         ///< mm, clear gap between the last row and the slots' inlet
};

enum class TrailingEdgeType { Centreline, PressureSideCutback };

/// Coolant ejection from the last chamber through the trailing edge: slots through the TE centreline, or
/// a pressure-side cutback (slots under a pressure-side lip, the pressure wall cut back to the lip).
struct TrailingEdgeDefinition {
  TrailingEdgeType type = TrailingEdgeType::PressureSideCutback;
  double slot_height = 0;      ///< mm, H: normal to the slot floor
  double slot_width = 0;       ///< mm, spanwise width of a slot at its inlet (and under the lip)
  double pitch = 0;            ///< mm, spanwise slot pitch; 0: from `count`
  int count = 0;               ///< slots (when pitch = 0)
  double lip_thickness = 0;    ///< mm, cutback: pressure-side lip over the slot at the cutback
  double cutback_length = 0;   ///< mm, cutback: from the lip to the TE (along the exit direction)
  double land_taper_deg = 0;   ///< deg, cutback: each land side turns by this angle, lands widen to the TE
  double span_margin = 1.0;    ///< mm, clear span between the outermost slots and the end walls
  std::optional<PinFinDefinition> pin_fins;
};

/// The hollow core: inner wall, end walls, ribs (LE to TE), inlets.
struct CoreDefinition {
  blade::ThicknessField wall_thickness;
  EndWallDefinition tip_cap, hub_floor;
  std::vector<RibDefinition> ribs;  ///< sorted from the LE to the TE
  std::vector<InletDefinition> inlets;
  std::vector<TurbulatorDefinition> turbulators;  ///< per chamber (at most one entry per chamber)
  std::optional<TrailingEdgeDefinition> trailing_edge;  ///< slots (and pin fins) from the last chamber
  double tolerance = 1e-3;  ///< mm, inner wall and rib surfaces against their exact definitions
};

/// A straight cylindrical passage through the whole span, open at both ends (e.g. the C3X vane's ten
/// radial passages). Axis: parallel to z through `position` for a straight vane; the radial line through
/// the point at the hub on a meridional blade.
struct RadialPassageDefinition {
  double diameter = 0;  ///< mm
  /// Axis position in the section frame (a, b) of the hub section (straight vane: x, y), mm.
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
};

/// A passage definition that cannot be built as asked. `field` is the JSON path below "cooling" of the
/// value to change (e.g. "core.ribs[1].suction_chord"); the message says where on the blade it fails
/// (span / chord) and what the limit is.
class PassageInputError : public InvalidGeometry {
 public:
  PassageInputError(std::string field, const std::string& what) : InvalidGeometry(what), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

struct PassagesDefinition {
  std::optional<CoreDefinition> core;
  std::vector<RadialPassageDefinition> radial_passages;
  PerturbedRetries retries = PerturbedRetries::Any;  ///< "booleans.allow_perturbation" (boolean_retries.hpp)
  bool empty() const { return !core && radial_passages.empty(); }
};

}  // namespace cg::features
