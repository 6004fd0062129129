#pragma once
// Where an imported blade came from and how closely the built blade follows it (plain data, filled
// by src/blade_import, carried by the BladeModel into report.json).
#include <string>
#include <vector>

namespace cg::blade {

/// Distances (mm) from input points to the built wall: largest, root mean square and how many.
struct DeviationFigures {
  double max = 0, rms = 0;
  long points = 0;
};

struct ImportedSectionFidelity {
  int section = 0;   // 1-based, in file order (hub -> tip)
  int line = 0;      // file line where it starts
  DeviationFigures at_points;       // the given points inside the flow path
  DeviationFigures between_points;  // the section's interpolant half-way between consecutive points
  DeviationFigures to_next;         // the input surface half-way to the next section (empty for the last)
  DeviationFigures on_faces;        // STEP / IGES: points of the input faces between this cut and the next
};

struct ImportRecord {
  std::string format;  // "geomturbo" | "sections" | "step" | "iges"
  std::string file;
  std::string row;     // "annular" | "cascade"
  int number_of_blades = 0;  // 0 = not given
  double tip_gap_le = 0, tip_gap_te = 0;  // mm
  double tolerance = 0;                   // mm
  int cuts = 0;                           // stream-surface cuts the blade model was built from
  int samples_per_side = 0;
  std::vector<ImportedSectionFidelity> sections;
  DeviationFigures overall;
};

}  // namespace cg::blade
