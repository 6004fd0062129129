#pragma once
// The one place where the passage features meet the blade through a boolean. It follows the contract
// of verified_boolean.hpp (BooleanStep add/apply/report); until that implementation is on main this
// file carries an interim implementation with the same checks the contract lists that matter here
// (overlapping tools fused first, one cut with history, face names from history, verify_solid, no
// BOPAlgo warning, removed volume against the tools' expected volumes).
#include <vector>

#include "features/verified_boolean.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

/// Cuts `tools` from `part`; returns the named result and fills `report`. Throws FeatureFailure naming
/// the feature(s) when a check fails.
brep::NamedShape cut_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& tools,
                                   BooleanStepReport& report, const BooleanOptions& options = {});

/// Fuses overlapping tools (any two whose solids intersect) so the list becomes pairwise disjoint;
/// face names are carried, the feature name of a cluster joins its members' names with '+'.
std::vector<FeatureTool> fuse_overlapping_tools(const std::vector<FeatureTool>& tools);

}  // namespace cg::features
