#pragma once
// Volume removed (Cut) or added (Fuse) by each tool, measured on the result of one boolean with many
// disjoint tools, without one boolean per tool.
//
// Divergence theorem: V(D) = 1/3 * closed integral over dD of (x - c) . n dA, for any point c. For a
// tool T and the part P, the boundary of T & P consists of
//  - T's face pieces inside P: they are faces of the Cut result, oriented there with n pointing into T;
//  - P's face pieces inside T: the pieces of P's faces that the boolean dropped; since the tools are
//    disjoint each lies inside exactly one tool, found by classifying a point of the piece against the
//    tools whose boxes reach it (BRepClass3d_SolidClassifier on the small tool, independent of the
//    boolean's own classification).
// so V(T & P) = -sum flux(T pieces in the result) + sum flux(dropped P pieces, oriented as in P). For
// Fuse, V(T - P) = sum flux(T pieces in the result) - sum flux(dropped P pieces inside T). The face
// integrals are src/brep/face_flux's (relative accuracy 1e-9) on small faces.
//
// What this catches: a piece of the part dropped outside every tool (lost part, 'lost_pieces'), a
// tool piece missing or kept where it should not be (the boundary is no longer closed: the volume
// depends on c, 'closure' = |V(c1) - V(c2)| for two reference points a tool size apart), wrong
// removed volumes (compared by the caller with an independent expectation).
#include <TopoDS_Shape.hxx>

#include <vector>

#include "src/brep/boolean/boolean_run.hpp"

namespace cg::features {

struct ToolVolume {
  double volume = 0;   ///< mm^3 removed (Cut) or added (Fuse), reference point c1
  double closure = 0;  ///< mm^3, |V(c1) - V(c2)|: 0 up to integration error for a closed boundary
  /// mm^3: how far the volume of the pieces' boundary is defined by the B-rep itself. An edge of
  /// tolerance t lets each of its two faces end anywhere within t, so the boundary may leave gaps or
  /// overlaps of area up to 2 t L per edge of length L; their flux is at most lever / 3 per unit area,
  /// lever = the largest distance from c1 to the tool's box. (OCCT's cylinder / rational B-spline
  /// intersection edges carry t up to ~4e-4 mm: the measured volume of a 0.5 mm^3 hole is then known
  /// to ~1e-4 mm^3, not to 1e-6 relative.)
  double uncertainty = 0;
  int tool_pieces = 0, part_pieces = 0;
};

struct VolumeMeasure {
  std::vector<ToolVolume> tools;  ///< one per tool, in order
  int lost_pieces = 0;            ///< dropped part pieces inside no tool
  double lost_area = 0;           ///< mm^2, their area
  int ambiguous_pieces = 0;       ///< dropped part pieces inside more than one tool (tools not disjoint)
};

VolumeMeasure measure_tool_volumes(const BooleanRun& run, const TopoDS_Shape& part, const std::vector<TopoDS_Shape>& tools,
                                   BooleanOperation op, bool parallel);


}  // namespace cg::features
