#pragma once
// The one place where the passage features meet the blade: chambers strictly inside the blade are
// inserted as voids (checked, see apply_passage_tools), every other tool is cut through the verified
// boolean path (verified_boolean.hpp: BooleanStep).
#include <limits>
#include <vector>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

/// Report of apply_passage_tools.
struct PassageBooleanReport {
  std::vector<ToolReport> voids;  ///< interior tools inserted as voids (expected vs measured volume)
  double min_clearance = 0;       ///< mm, smallest distance between a void and the part's boundary
  /// mm, smallest distance between a void and the part's faces named blade_wall (NaN: no voids)
  double wall_clearance = std::numeric_limits<double>::quiet_NaN();
  double void_seconds = 0;
  BooleanStepReport cut;          ///< the cut of the other tools (tool_count 0 when none)
};

/// Applies the passage tools to the blade. `interior` tools lie strictly inside `part` by construction
/// (chambers inside the inner wall, between the end walls): subtracting such a tool changes no face of
/// the part, it only adds the tool's boundary as an inner shell (a void), so they are inserted that way
/// (exact, no face intersections to compute) after checking the precondition: the tool's distance to the
/// part's boundary (BRepExtrema_DistShapeShape) is positive and a point of it lies inside the part. The
/// result is checked like a boolean result (verify_solid, removed volume = the tools' volume). The
/// `cuts` then go through the verified boolean path. Throws FeatureFailure naming the feature.
/// `verification` FinalOnly, None: verify_solid of the result is left to the caller (every other check still runs).
brep::NamedShape apply_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& interior,
                                     const std::vector<FeatureTool>& cuts, PassageBooleanReport& report,
                                     Verification verification = Verification::EachStep,
                                     PerturbedRetries retries = PerturbedRetries::Any);

/// Cuts `tools` from `part` through one verified BooleanStep; returns the named result and fills
/// `report`. Throws FeatureFailure naming the feature(s) when a check fails.
brep::NamedShape cut_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& tools,
                                   BooleanStepReport& report, const BooleanOptions& options = {});

}  // namespace cg::features
