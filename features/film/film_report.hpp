#pragma once
// What the film-hole and insert build measured: per hole, per row, per chamber, per insert. A plain
// struct; to_json() gives the object report.json carries under "cooling" -> "film" (units in the key
// names: _mm, _mm2, _mm3, _deg, _s).
#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <vector>

#include "src/brep/boolean/boolean_retries.hpp"

namespace cg::features {

struct HoleMeasure {
  std::string name, row, chamber, shape;  ///< shape: "cylindrical" | "fan_shaped"
  double span = 0, chord = 0;             ///< blade coordinates of the exit point
  double exit[3] = {0, 0, 0}, axis[3] = {0, 0, 0};  ///< exit point (mm) and unit axis into the wall
  double diameter = 0, inclination_deg = 0;
  double length = 0, length_d = 0;                    ///< L and L/D through the wall along the axis
  double metering_length = 0, metering_length_d = 0;  ///< cavity wall to diffuser start (cylinder: L)
  double diffuser_length = 0;
  double metering_area = 0, exit_area = 0, area_ratio = 1;  ///< exit: fan cross-section at L*
  double footprint_area = 0;   ///< exit footprint on the outer surface
  double breakout_width = 0;   ///< along the row
  double expected_volume = 0;  ///< our quadrature
  double measured_volume = std::numeric_limits<double>::quiet_NaN();  ///< on the cut blade (BRepGProp)
  bool volume_passed = false;
  double ligament = std::numeric_limits<double>::infinity();  ///< to the nearest hole (lower bound)
  std::string ligament_to;
  double obstacle_ligament = std::numeric_limits<double>::infinity();  ///< to the nearest rib / end wall
  std::string nearest_obstacle;
};

struct RowMeasure {
  std::string name;
  int holes = 0;
  double pitch = 0;            ///< mm along the row
  double breakout_width = 0;   ///< mean over the row
  double coverage = 0;         ///< breakout width / pitch
  double min_ligament = std::numeric_limits<double>::infinity();
  double metering_area = 0;    ///< total of the row
};

struct ChamberFeed {
  std::string chamber;
  int holes = 0;
  double metering_area = 0;  ///< total metering area of the holes it feeds, mm^2
};

struct InsertMeasure {
  std::string name, chamber;
  double gap = 0, sheet_thickness = 0;             ///< configured
  double measured_gap = 0;                         ///< least distance insert - blade, on the solids
  double measured_sheet_min = 0, measured_sheet_max = 0;  ///< sampled through-thickness distance
  double volume = 0, expected_volume = 0;          ///< mm^3 (expected: shell before jet holes minus jet quadrature)
  int jet_holes = 0;
  double jet_area = 0;                             ///< total jet hole area, mm^2
  bool hub_open = true, tip_open = true;
};

struct FilmReport {
  std::vector<HoleMeasure> holes;
  std::vector<RowMeasure> rows;
  std::vector<ChamberFeed> chambers;
  std::vector<InsertMeasure> inserts;
  double min_ligament = std::numeric_limits<double>::infinity();  ///< between holes, mm
  double configured_min_ligament = 0;
  int tool_clusters = 0, boolean_runs = 0;  ///< of the verified boolean step(s)
  std::vector<PerturbedTool> perturbed;  ///< tools (holes, insert shells) that went in after a perturbed retry
  int drilled_holes = 0;  ///< holes cut by direct drilling (drill_holes.hpp); the rest went through booleans
  std::vector<std::pair<std::string, double>> seconds;  ///< stage times
  nlohmann::json to_json() const;
};

/// Fills rows and chambers from the holes (pitch per row from `row_pitch`, in the order rows appear).
void summarise_film_report(FilmReport& report, const std::vector<std::pair<std::string, double>>& row_pitch);

}  // namespace cg::features
