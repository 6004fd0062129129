#include "src/brep/boolean/boolean_disjoint.hpp"

#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_OBB.hxx>
#include <OSD_Parallel.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <numeric>

#include "src/brep/boolean/boolean_naming.hpp"
#include "src/brep/boolean/boolean_run.hpp"
#include "src/brep/boolean/verified_boolean.hpp"

namespace cg::features {
namespace {

int find_root(std::vector<int>& parent, int a) {
  while (parent[static_cast<std::size_t>(a)] != a)
    a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
  return a;
}

}  // namespace

OverlapClusters overlap_clusters(const std::vector<TopoDS_Shape>& tools, double gap, bool parallel) {
  OverlapClusters r;
  const int n = static_cast<int>(tools.size());
  std::vector<Bnd_Box> boxes(tools.size());
  std::vector<Bnd_OBB> obbs(tools.size());
  std::vector<double> xmin(tools.size());
  for (int i = 0; i < n; ++i) {
    BRepBndLib::Add(tools[static_cast<std::size_t>(i)], boxes[static_cast<std::size_t>(i)], false);
    boxes[static_cast<std::size_t>(i)].Enlarge(gap);
    BRepBndLib::AddOBB(tools[static_cast<std::size_t>(i)], obbs[static_cast<std::size_t>(i)], false, false, false);
    obbs[static_cast<std::size_t>(i)].Enlarge(gap);
    double c[6];
    boxes[static_cast<std::size_t>(i)].Get(c[0], c[1], c[2], c[3], c[4], c[5]);
    xmin[static_cast<std::size_t>(i)] = c[0];
  }
  std::vector<int> order(tools.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return xmin[static_cast<std::size_t>(a)] < xmin[static_cast<std::size_t>(b)]; });
  std::vector<std::pair<int, int>> candidates;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int a = order[k];
    double ca[6];
    boxes[static_cast<std::size_t>(a)].Get(ca[0], ca[1], ca[2], ca[3], ca[4], ca[5]);
    for (std::size_t l = k + 1; l < order.size() && xmin[static_cast<std::size_t>(order[l])] <= ca[3]; ++l) {
      const int b = order[l];
      if (boxes[static_cast<std::size_t>(a)].IsOut(boxes[static_cast<std::size_t>(b)])) continue;
      if (obbs[static_cast<std::size_t>(a)].IsOut(obbs[static_cast<std::size_t>(b)])) continue;
      candidates.emplace_back(a, b);
    }
  }
  r.candidate_pairs = static_cast<int>(candidates.size());
  std::vector<char> close(candidates.size(), 0);
  OSD_Parallel::For(0, static_cast<int>(candidates.size()), [&](int k) {
    const auto [a, b] = candidates[static_cast<std::size_t>(k)];
    try {
      BRepExtrema_DistShapeShape d(tools[static_cast<std::size_t>(a)], tools[static_cast<std::size_t>(b)], Extrema_ExtFlag_MIN);
      close[static_cast<std::size_t>(k)] = !d.IsDone() || d.Value() <= gap || d.InnerSolution();
    } catch (const Standard_Failure&) {
      close[static_cast<std::size_t>(k)] = 1;  // undecided: fuse them, the fuse is checked
    }
  }, !parallel);
  std::vector<int> parent(tools.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (close[k]) {
      ++r.overlapping_pairs;
      parent[static_cast<std::size_t>(find_root(parent, candidates[k].first))] = find_root(parent, candidates[k].second);
    }
  std::vector<int> slot(tools.size(), -1);
  for (int i = 0; i < n; ++i) {
    const int root = find_root(parent, i);
    if (slot[static_cast<std::size_t>(root)] < 0) {
      slot[static_cast<std::size_t>(root)] = static_cast<int>(r.clusters.size());
      r.clusters.emplace_back();
    }
    r.clusters[static_cast<std::size_t>(slot[static_cast<std::size_t>(root)])].push_back(i);
  }
  return r;
}

brep::NamedShape fuse_cluster(const std::vector<const brep::NamedShape*>& members, const std::string& label, bool parallel) {
  if (members.size() == 1) return *members.front();
  std::vector<TopoDS_Shape> rest;
  std::vector<const brep::NamedShape*> rest_named;
  for (std::size_t i = 1; i < members.size(); ++i) {
    rest.push_back(members[i]->shape);
    rest_named.push_back(members[i]);
  }
  const BooleanRun run = run_boolean(members.front()->shape, rest, BooleanOperation::Fuse, parallel);
  std::string why;
  if (run.result.IsNull() || !run.errors.empty()) why = "the fuse failed";
  else if (!run.warnings.empty()) why = "the fuse reported " + run.warnings.front();
  TopTools_IndexedMapOfShape solids;
  if (why.empty()) {
    TopExp::MapShapes(run.result, TopAbs_SOLID, solids);
    if (solids.Extent() != 1)
      why = "the fuse gave " + std::to_string(solids.Extent()) + " solids (tools that touch without overlapping)";
  }
  if (!why.empty()) throw FeatureFailure("overlapping tools " + label + " could not be fused into one tool: " + why);
  NamingResult named = name_result(run, *members.front(), rest_named);
  if (named.unnamed > 0) throw FeatureFailure("overlapping tools " + label + ": the fuse's history does not name every face");
  // Merge the coplanar / co-cylindrical pieces the fuse leaves (e.g. the two halves of a common end
  // cap): OCCT's later booleans with such a tool warn about unused edges. A merged face takes the
  // name of its first piece; the others keep theirs.
  ShapeUpgrade_UnifySameDomain unify(solids(1), /*UnifyEdges=*/true, /*UnifyFaces=*/true, /*ConcatBSplines=*/false);
  unify.Build();
  brep::NamedShape r{unify.Shape(), {}};
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(r.shape, TopAbs_FACE, faces);
  std::vector<const std::string*> names(static_cast<std::size_t>(faces.Extent()), nullptr);
  const Handle(BRepTools_History) h = unify.History();
  for (const brep::NamedFace& f : named.shape.faces) {
    TopTools_ListOfShape now = h->Modified(f.face);
    if (now.IsEmpty() && !h->IsRemoved(f.face)) now.Append(f.face);
    for (const TopoDS_Shape& g : now) {
      const int i = faces.FindIndex(g);
      if (i > 0 && !names[static_cast<std::size_t>(i - 1)]) names[static_cast<std::size_t>(i - 1)] = &f.name;
    }
  }
  for (int i = 1; i <= faces.Extent(); ++i) {
    if (!names[static_cast<std::size_t>(i - 1)])
      throw FeatureFailure("overlapping tools " + label + ": a merged face of the fused tool has no name");
    r.faces.push_back({TopoDS::Face(faces(i)), *names[static_cast<std::size_t>(i - 1)]});
  }
  return r;
}

}  // namespace cg::features
