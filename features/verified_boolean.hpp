#pragma once
// The one verified boolean path every cooling feature goes through (see features/README.md).
//
// CONTRACT (interface agreed for the feature helpers; the implementation lands in
// features/verified_boolean.cpp on the boolean-engine branch and may refine details, not the shape).
//
//   features::BooleanStep step(features::BooleanOperation::Cut, options);
//   step.add(tool) ...                              // tools with named faces and expected volumes
//   brep::NamedShape result = step.apply(part);     // throws FeatureFailure naming the feature
//   const BooleanStepReport& r = step.report();     // per-tool expected/measured volumes, checks, timings
//
// What apply() guarantees when it returns: the result passed every check of brep::verify_solid plus the
// per-tool volume check, carries no BOPAlgo warning, and every face is named from boolean history.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"
#include "src/core/error.hpp"

namespace cg::features {

/// A feature could not be applied correctly (after retries); the message names the feature(s).
class FeatureFailure : public AlgorithmFailure {
 public:
  using AlgorithmFailure::AlgorithmFailure;
};

enum class BooleanOperation { Cut, Fuse };

/// One tool of a step.
struct FeatureTool {
  /// Feature name for messages and the report, e.g. "chamber_2", "film_row_2_hole_014".
  std::string feature;
  /// The tool solid. Its faces carry the names the result's faces get where they come from this tool.
  brep::NamedShape shape;
  /// Independent expectation of the volume this tool removes (Cut: V(tool & part)) or adds
  /// (Fuse: V(tool - part)), mm^3. NaN: the step computes it with OCCT (Common / Cut of the tool
  /// against the part before the step).
  double expected_volume = std::numeric_limits<double>::quiet_NaN();
};

struct BooleanOptions {
  /// Per-tool |measured - expected| <= volume_rel_tolerance * expected + volume_abs_tolerance.
  double volume_rel_tolerance = 1e-6;
  double volume_abs_tolerance = 1e-6;  ///< mm^3
  int expected_solids = 1;             ///< solids the result must have
  int max_retries = 2;                 ///< perturbed retries of a guilty tool
  double perturbation = 0.01;          ///< mm, shift (and seam rotation) applied on retry
  bool parallel = true;
};

struct ToolReport {
  std::string feature;
  double expected_volume = 0;  ///< mm^3
  double measured_volume = 0;  ///< mm^3, measured on the result
  int retries = 0;
  bool passed = false;
};

struct BooleanStepReport {
  BooleanOperation operation = BooleanOperation::Cut;
  int tool_count = 0;
  int cluster_count = 0;  ///< clusters of overlapping tools fused before the step
  std::vector<ToolReport> tools;
  std::vector<std::string> warnings;  ///< BOPAlgo alerts met on the way (a retry cured them)
  brep::SolidCheck check;             ///< of the result
  double seconds = 0;
};

/// Algorithm object: collect tools, apply them to a part once, read the report.
class BooleanStep {
 public:
  explicit BooleanStep(BooleanOperation operation, BooleanOptions options = {});
  void add(FeatureTool tool);
  /// Applies every tool to `part` (made disjoint, one boolean with history, checked, guilty tools
  /// retried). Returns the named result; throws FeatureFailure naming the feature(s) that failed.
  brep::NamedShape apply(const brep::NamedShape& part);
  bool done() const { return done_; }
  const BooleanStepReport& report() const { return report_; }

 private:
  BooleanOperation operation_;
  BooleanOptions options_;
  std::vector<FeatureTool> tools_;
  BooleanStepReport report_;
  bool done_ = false;
};

}  // namespace cg::features
