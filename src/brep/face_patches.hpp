#pragma once
// Splitting the faces of a part into patches, so that no face receives hundreds of tools.
//
// Why (measured, see features/README.md "Verified boolean path"): OCCT's per-tool work on a face
// grows with the face's parameter domain (edge/face and face/face intersections sample the whole face,
// ~10 ms per pair on a blade wall against ~3-7 ms on a patch), and a face with n inner wires is split,
// classified and checked in worse than linear time, so one blade wall pierced by 1 000 holes makes the
// cut superlinear.
//
// Method: for each face that more than `min_tools` tools reach, the tools' footprints are estimated
// in the face's parameter space (the tool's oriented box cut by the tangent plane at the foot of its
// centre) and the face is cut along a grid of iso-parametric lines placed in the gaps between the
// footprints near the quantiles of their distribution, so every cell holds about `tools_per_patch`
// tools and, where the layout leaves a gap, no tool crosses a patch edge. The iso-lines are exact
// (Geom_Surface::UIso/VIso, with their pcurves, straight lines, attached), and the faces are split by
// one general fuse (BOPAlgo_Builder) of the part's shells with those edges, which lie on the faces.
// The shells are rebuilt from the images of their faces (they share the split edges); every piece
// keeps its face's name.
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "src/brep/named_shape.hpp"

namespace cg::features {

struct PatchOptions {
  int min_tools = 24;       ///< faces reached by fewer tools are left whole
  int tools_per_patch = 6;  ///< target tools per patch
  bool parallel = true;
};

struct PatchedPart {
  brep::NamedShape part;              ///< same solid(s), faces split, names kept
  std::vector<std::string> warnings;  ///< BOPAlgo warnings of the split
  int faces_before = 0, faces_after = 0, cut_lines = 0;
};

/// Splits the faces of `part` that many of `tools` reach into patches (see above). Returns the part
/// unchanged when no face needs it. Throws AlgorithmFailure when the general fuse fails.
PatchedPart patch_faces(const brep::NamedShape& part, const std::vector<TopoDS_Shape>& tools,
                        const PatchOptions& options = {});

}  // namespace cg::features
