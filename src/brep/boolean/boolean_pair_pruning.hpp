#pragma once
// A BOPAlgo_PaveFiller that intersects only the face pairs that can meet.
//
// OCCT intersects every pair of faces whose bounding boxes overlap. On a cooled blade most of those
// pairs are a small feature tool against a large wall face that merely encloses it (for one turbulator
// 4 of 54 candidate pairs meet; the others cost ~30 ms each in IntTools_FaceFace). Two faces that cut
// each other along a curve which reaches a boundary of either face have an edge of one face crossing
// (or touching, or lying on) the other, or two of their edges/vertices meeting: OCCT finds those
// interferences first (vertex/edge/face pairs, before the face/face phase). This filler runs that
// phase as usual and then keeps only the face pairs linked by such an interference.
//
// Not covered: a section curve closed inside both faces without touching an edge of either (one
// surface bulging through the interior of the other). Such a miss leaves a wrong solid, which the
// verified boolean path detects (per-tool volumes, verify_solid); it then repeats the boolean with
// every pair (BooleanOptions::prune_face_pairs).
#include <BOPAlgo_PaveFiller.hxx>

namespace cg::features {

class PrunedPaveFiller : public BOPAlgo_PaveFiller {
 public:
  /// `prune` false: behaves exactly as BOPAlgo_PaveFiller.
  explicit PrunedPaveFiller(bool prune) : prune_(prune) {}
  int candidate_face_pairs() const { return candidates_; }  ///< face pairs with overlapping boxes
  int kept_face_pairs() const { return kept_; }             ///< of those, intersected

 protected:
  void PerformFF(const Message_ProgressRange& range) override;

 private:
  void prune_face_pairs();
  bool prune_;
  int candidates_ = 0, kept_ = 0;
};

}  // namespace cg::features
