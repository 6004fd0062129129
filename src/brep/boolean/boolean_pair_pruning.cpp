#include "src/brep/boolean/boolean_pair_pruning.hpp"

#include <BOPDS_DS.hxx>
#include <BOPDS_Iterator.hxx>
#include <BOPDS_Tools.hxx>

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace cg::features {
namespace {

// BOPDS_Iterator keeps its candidate pairs protected; a pointer to that member, formed in a derived
// class, reads them through the filler's iterator without casting the object.
struct IteratorLists : BOPDS_Iterator {
  static constexpr BOPDS_VectorOfVectorOfPair BOPDS_Iterator::*lists = &IteratorLists::myLists;
};

std::uint64_t key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Faces (DS indices) each source sub-shape belongs to; a face belongs to itself.
std::vector<std::vector<int>> faces_of_subshapes(const BOPDS_DS& ds) {
  const int n = ds.NbSourceShapes();
  std::vector<std::vector<int>> faces(static_cast<std::size_t>(n));
  std::vector<int> stack, seen_by(static_cast<std::size_t>(n), -1);
  for (int f = 0; f < n; ++f) {
    if (ds.ShapeInfo(f).ShapeType() != TopAbs_FACE) continue;
    stack.assign(1, f);
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      if (seen_by[static_cast<std::size_t>(s)] == f) continue;
      seen_by[static_cast<std::size_t>(s)] = f;
      faces[static_cast<std::size_t>(s)].push_back(f);
      for (TColStd_ListOfInteger::Iterator it(ds.ShapeInfo(s).SubShapes()); it.More(); it.Next()) stack.push_back(it.Value());
    }
  }
  return faces;
}

template <class Interferences>
void link_faces(const Interferences& v, const std::vector<std::vector<int>>& faces, std::unordered_set<std::uint64_t>& linked) {
  const int n = static_cast<int>(faces.size());
  for (int i = 0; i < v.Length(); ++i) {
    int a = -1, b = -1;
    v(i).Indices(a, b);
    if (a < 0 || b < 0 || a >= n || b >= n) continue;  // new shapes (not from the arguments) link nothing
    for (int fa : faces[static_cast<std::size_t>(a)])
      for (int fb : faces[static_cast<std::size_t>(b)]) linked.insert(key(fa, fb));
  }
}

}  // namespace

void PrunedPaveFiller::PerformFF(const Message_ProgressRange& range) {
  if (prune_ && !HasErrors()) prune_face_pairs();
  BOPAlgo_PaveFiller::PerformFF(range);
}

void PrunedPaveFiller::prune_face_pairs() {
  BOPDS_DS& ds = *myDS;
  const std::vector<std::vector<int>> faces = faces_of_subshapes(ds);
  std::unordered_set<std::uint64_t> linked;
  link_faces(ds.InterfVV(), faces, linked);
  link_faces(ds.InterfVE(), faces, linked);
  link_faces(ds.InterfVF(), faces, linked);
  link_faces(ds.InterfEE(), faces, linked);
  link_faces(ds.InterfEF(), faces, linked);

  BOPDS_VectorOfPair& pairs = (myIterator->*IteratorLists::lists)(BOPDS_Tools::TypeToInteger(TopAbs_FACE, TopAbs_FACE));
  BOPDS_VectorOfPair kept;
  for (int i = 0; i < pairs.Length(); ++i) {
    int a = -1, b = -1;
    pairs(i).Indices(a, b);
    if (linked.count(key(a, b))) kept.Append(pairs(i));
  }
  candidates_ = pairs.Length();
  kept_ = kept.Length();
  pairs = kept;
}

}  // namespace cg::features
