#pragma once
// What a verified boolean step may change to get a tool through OCCT (src/brep/boolean/verified_boolean.hpp):
// a guilty tool is retried perturbed, either rotated about its own axis of symmetry (a hole, a pin: the
// same solid, only its seams move) or, for other tools, shifted by BooleanOptions::perturbation (0.01 mm:
// the geometry the user asked for moves). Config: "booleans": {"allow_perturbation": false} selects
// SameGeometry. No OCCT here: the feature definitions carry it.
#include <string>

namespace cg::features {

enum class PerturbedRetries {
  Any,           ///< rotations and shifts (default)
  SameGeometry,  ///< only rotations of a rotationally symmetric tool; a tool that needs a shift fails
};

/// A tool that went in only after a perturbed retry (report.json "booleans.perturbed_tools").
struct PerturbedTool {
  std::string feature;
  std::string change;             ///< e.g. "shifted 0.01 mm", "rotated 21.199438420002464 deg about its axis"
  bool geometry_changed = false;  ///< true for a shift
};

}  // namespace cg::features
