#pragma once
// Making the tools of a step pairwise disjoint: one multi-tool boolean with overlapping tools returned
// a wrong solid that BRepCheck called valid, and overlapping tools inside a cavity made the cut run for
// minutes (see the booleans notes). Overlapping (or touching) tools are found and each cluster is fused
// into one tool first.
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"

namespace cg::features {

struct OverlapClusters {
  std::vector<std::vector<int>> clusters;  ///< every tool index exactly once; singletons included
  int candidate_pairs = 0;                 ///< pairs whose boxes overlap (exact test run on them)
  int overlapping_pairs = 0;
};

/// Tools closer than `gap` mm (or overlapping, or one inside the other) end up in one cluster:
/// axis-aligned boxes sorted along x (sweep), then oriented boxes, then BRepExtrema_DistShapeShape.
OverlapClusters overlap_clusters(const std::vector<TopoDS_Shape>& tools, double gap, bool parallel);

/// Fuses overlapping tools into one solid whose faces keep their names (from the fuse's history).
/// Throws FeatureFailure naming `label` when the fuse fails or does not give exactly one valid solid.
brep::NamedShape fuse_cluster(const std::vector<const brep::NamedShape*>& members, const std::string& label, bool parallel);

}  // namespace cg::features
