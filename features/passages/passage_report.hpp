#pragma once
// What the passage build measured on the built solid: design checks, the quantities a 1D flow-network
// model needs, feature volumes. A plain struct; to_json() gives the object report.json carries under
// "cooling" (units in the key names: _mm, _mm2, _mm3, _s), which is also how the stage cache stores it
// (from_json reads it back: one serialisation).
#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "src/brep/boolean/boolean_retries.hpp"

namespace cg::features {

/// A thickness measured on the built solid against its configured value.
struct ThicknessMeasure {
  std::string feature;     ///< "outer_wall", "tip_cap", "hub_floor", "rib_2", "radial_passage_3_wall"
  double configured = 0;   ///< mm, the configured thickness (the minimum of a varying one); NaN: none
  double min = 0;          ///< mm, measured minimum (BRepExtrema_DistShapeShape between the two sides)
  double max = std::numeric_limits<double>::quiet_NaN();  ///< mm, sampled maximum where measured
  double tolerance = 0;    ///< mm, allowed shortfall: max(0.01 mm, 1 % of the configured value)
  bool passed = true;      ///< min >= configured - tolerance
  std::string method;
};

/// One cross-section of a passage on a stream surface (straight vane: the plane z = span * span length).
struct CrossSection {
  double span = 0;                ///< span fraction of the section surface
  double area = 0;                ///< mm^2
  double wetted_perimeter = 0;    ///< mm
  double hydraulic_diameter = 0;  ///< mm, 4 area / wetted perimeter
};

struct PassageMeasure {
  std::string name;  ///< "chamber_2", "radial_passage_7"
  double volume = 0;  ///< mm^3 of coolant
  std::string fed_by;  ///< "inlet_1", "open tip", "turnaround from chamber_2", "both ends open"
  std::vector<CrossSection> sections;
};

struct FeatureVolume {
  std::string feature;  ///< "core", "chamber_2", "rib_1", "rib_1_fillets", "inlet_1", "radial_passage_3"
  double volume = 0;    ///< mm^3
  std::string meaning;  ///< "coolant", "material", "removed"
};

struct ToolVolumeCheck {
  std::string feature;
  double expected = 0, measured = 0;  ///< mm^3 removed from the blade
  bool passed = false;
  std::string how;  ///< "void" (inserted, strictly inside) or "cut"
};

struct PassageReport {
  std::vector<ThicknessMeasure> thickness;
  std::vector<PassageMeasure> passages;
  std::vector<FeatureVolume> volumes;
  std::vector<ToolVolumeCheck> tools;
  std::vector<PerturbedTool> perturbed;  ///< tools that went in after a perturbed retry
  int closed_cavities = 0;       ///< cavities without any opening (must be 0: every chamber is fed)
  bool all_chambers_fed = true;
  // Inner wall surface.
  int inner_wall_poles_u = 0, inner_wall_poles_v = 0;
  double inner_wall_fit_error = 0;  ///< mm
  double min_clearance = 0;         ///< mm, chambers to the blade's boundary (void insertion precondition)
  /// mm, chambers to the outer wall, measured when they were inserted as voids (NaN: not inserted)
  double wall_clearance = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::pair<std::string, double>> seconds;  ///< stage times
  bool passed() const;
  /// Every member (keys sorted as report.json has always shown them, `seconds` in run order; a
  /// non-finite number as null).
  nlohmann::ordered_json to_json() const;
  /// The report `to_json` wrote (null numbers as NaN; "passed" is derived, not read). Throws
  /// nlohmann::json::exception for an object it did not write.
  static PassageReport from_json(const nlohmann::ordered_json& j);
};

}  // namespace cg::features
