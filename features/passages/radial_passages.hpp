#pragma once
// Straight radial passages through the whole span, open at both ends (e.g. the NASA C3X vane's ten
// cooling passages, NASA CR-168015 Fig. 7): cylinders along z on a straight vane, from below the hub
// plane to above the casing plane. Each removes pi r^2 times the span exactly (planar ends normal to the
// axis), the analytic expected volume of the verified cut. Face names: radial_passage_<k>.
#include <vector>

#include "features/passages/passage_definition.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/blade/blade_surface.hpp"

namespace cg::features {

struct RadialPassageBuild {
  std::vector<FeatureTool> tools;
  /// Smallest wall between each passage and the outer wall, mm (the distance from the axis to the
  /// wall minus the radius, at the hub, mid-span and the casing).
  std::vector<double> min_wall;
};

/// Builds the passages. Throws PassageInputError ("radial_passages[k]...") for a passage that breaks
/// through the wall or lies outside the section, two passages that overlap, or a meridional blade
/// (not supported: radial passages need a straight vane).
RadialPassageBuild build_radial_passages(const blade::BladeModel& model,
                                         const std::vector<RadialPassageDefinition>& passages);

}  // namespace cg::features
