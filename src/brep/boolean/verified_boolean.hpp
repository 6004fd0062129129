#pragma once
// The one verified boolean path every cooling feature goes through (see features/README.md,
// "Verified boolean path", for the method, the measured costs and what each check catches).
//
//   features::BooleanStep step(features::BooleanOperation::Cut, options);
//   step.add(tool) ...                              // tools with named faces and expected volumes
//   brep::NamedShape result = step.apply(part);     // throws FeatureFailure naming the feature
//   const BooleanStepReport& r = step.report();     // per-tool expected/measured volumes, checks, timings
//
// What apply() guarantees when it returns: the result passed every check of brep::verify_solid (unless
// options.verification is not EachStep), has options.expected_solids solids, came from booleans without any
// BOPAlgo error or warning, every face is named from boolean history, no piece of the part was dropped
// outside the tools, and every tool removed (added) its expected volume within the tolerance, measured
// on the result.
#include <gp_Ax1.hxx>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/brep/boolean/boolean_retries.hpp"
#include "src/brep/boolean/feature_options.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"
#include "src/core/error.hpp"
#include "src/core/progress.hpp"

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
  /// Axis about which the tool is rotationally symmetric (a hole, a pin). A retry rotates the tool
  /// about it, which moves its seams but keeps its geometry (and expected_volume). When absent it is
  /// detected for tools bounded by coaxial cylinders/cones and planes across the axis; other tools
  /// are retried by a small shift (and their expectation recomputed with OCCT).
  std::optional<gp_Ax1> symmetry_axis;
};

struct BooleanOptions : FeatureOptions {
  /// Per-tool |measured - expected| <= volume_rel_tolerance * expected + volume_abs_tolerance
  /// + the uncertainty the result's edge tolerances leave in the measured volume (ToolReport).
  double volume_rel_tolerance = 1e-6;
  double volume_abs_tolerance = 1e-6;  ///< mm^3
  int expected_solids = 1;             ///< solids the result must have
  int max_retries = 2;                 ///< perturbed retries of a guilty tool
  double perturbation = 0.01;          ///< mm, shift applied on a retry (rotations: 0.37 rad, 1.2 rad)
  PerturbedRetries perturbed_retries = PerturbedRetries::Any;  ///< src/brep/boolean/boolean_retries.hpp
  bool parallel = true;
  /// Intersect only the face pairs that can meet (src/brep/boolean/boolean_pair_pruning.hpp). A boolean that
  /// fails any check is repeated with every pair before a tool is blamed, and the step then stays
  /// unpruned (as do the booleans redone to locate a verify_solid failure).
  bool prune_face_pairs = true;
  /// Tools closer than this (mm), overlapping or nested, are fused into one tool first.
  double overlap_gap = 1e-4;
  /// Faces reached by at least `patch_min_tools` tools are split into patches of about
  /// `patch_tools_per_patch` tools first (src/brep/face_patches.hpp); 0 disables.
  int patch_min_tools = 64;
  int patch_tools_per_patch = 32;
  /// Inherited from FeatureOptions: `verification` EachStep runs brep::verify_solid on the result
  /// (BRepCheck, free edges, shells, closed mesh, volume), FinalOnly and None leave it to the caller;
  /// `progress`: progress and cancellation.
  brep::VerifyOptions verify;
};

struct ToolReport {
  std::string feature;
  double expected_volume = 0;  ///< mm^3 (of the fused cluster when `cluster` >= 0)
  double measured_volume = 0;  ///< mm^3, measured on the result
  double closure = 0;          ///< mm^3, |V(c1) - V(c2)| of the measurement (0 for a closed boundary)
  /// mm^3, how far the result's edge tolerances leave the measured volume undefined (lever / 3 times
  /// 2 tol x length summed over the edges of the tool's pieces); added to the volume tolerance.
  double uncertainty = 0;
  std::string expected_source; ///< "given" or "occt" (Common / Cut with the part before the step)
  int cluster = -1;            ///< index of the fused cluster of overlapping tools, -1: none
  int retries = 0;
  std::string perturbation;    ///< what the accepted retry changed, e.g. "rotated 21.2 deg about its axis"
  bool perturbation_changed_geometry = false;  ///< the accepted retry shifted the tool
  bool passed = false;
};

struct BooleanStepReport {
  BooleanOperation operation = BooleanOperation::Cut;
  int tool_count = 0;
  int cluster_count = 0;  ///< clusters of overlapping tools fused before the step
  int boolean_runs = 0;   ///< OCCT booleans run (1 when nothing failed)
  int patched_faces = 0;  ///< faces of the part split into patches before the step (0: none)
  std::vector<ToolReport> tools;
  std::vector<std::string> warnings;  ///< BOPAlgo alerts and failed checks met on the way (a retry cured them)
  brep::SolidCheck check;             ///< of the result (when verified)
  double seconds = 0;
  /// Wall-clock seconds per stage: disjoint, expected, patches, boolean, measure, verify.
  double seconds_disjoint = 0, seconds_expected = 0, seconds_patches = 0, seconds_boolean = 0,
         seconds_measure = 0, seconds_verify = 0;
  double seconds_intersect = 0;  ///< of seconds_boolean: OCCT's intersection phase (BOPAlgo_PaveFiller)
  /// Face pairs with overlapping boxes and, of those, intersected (pruned booleans, summed over runs).
  int candidate_face_pairs = 0, intersected_face_pairs = 0;
  int unpruned_repeats = 0;  ///< pruned booleans that failed a check and were repeated with every pair
};

/// The tools of `report` that went in after a perturbed retry, appended to `out`.
void append_perturbed_tools(const BooleanStepReport& report, std::vector<PerturbedTool>& out);

/// Algorithm object: collect tools, apply them to a part once, read the report.
class BooleanStep {
 public:
  explicit BooleanStep(BooleanOperation operation, BooleanOptions options = {});
  void add(FeatureTool tool);
  /// Applies every tool to `part` (made disjoint, one boolean with history, checked, guilty tools
  /// found by bisection and retried). Returns the named result; throws FeatureFailure naming the
  /// feature(s) that failed (every one of them; report() then still lists each tool's outcome),
  /// InvalidGeometry for a null part or tool, Cancelled when stopped.
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
