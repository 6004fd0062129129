#pragma once
// One OCCT boolean of a part with a list of (pairwise disjoint) tools, keeping everything the
// verification needs: the result, the split images of every input face (also the pieces that did
// not make it into the result) and the alerts.
//
// OCCT: BOPAlgo_PaveFiller (intersections, run once) + BOPAlgo_BOP (split faces, classify, build the
// result). Non-destructive (the inputs are never modified, so a retry starts from the same shapes),
// OBB pre-filter on, parallel as asked, face pairs pruned when asked.
#include <Message_ProgressRange.hxx>
#include <TopTools_DataMapOfShapeListOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace cg::features {

enum class BooleanOperation;

struct BooleanRun {
  TopoDS_Shape result;                     ///< null when OCCT reported an error
  TopTools_DataMapOfShapeListOfShape images;  ///< input sub-shape -> its split pieces (absent: unchanged)
  std::vector<std::string> errors, warnings;  ///< BOPAlgo alert names
  /// The shapes the warnings name (e.g. the too small edge), where OCCT gives one: they locate the
  /// tool that caused a warning without bisecting.
  std::vector<TopoDS_Shape> warning_shapes;
  bool cancelled = false;
  double seconds_intersect = 0, seconds_build = 0;
  int candidate_face_pairs = 0, intersected_face_pairs = 0;  ///< when pruned (else both 0)
};

/// Runs `part` op `tools`. Never throws for a bad boolean: errors come back in the run.
/// `prune_face_pairs`: intersect only the face pairs that can meet (src/brep/boolean/boolean_pair_pruning.hpp).
BooleanRun run_boolean(const TopoDS_Shape& part, const std::vector<TopoDS_Shape>& tools, BooleanOperation op,
                       bool parallel, bool prune_face_pairs = false,
                       const Message_ProgressRange& range = Message_ProgressRange());

/// The pieces of an input sub-shape: its images, or the shape itself when it was not split.
TopTools_ListOfShape pieces_of(const BooleanRun& run, const TopoDS_Shape& s);

}  // namespace cg::features
