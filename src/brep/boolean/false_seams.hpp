#pragma once
// False seams: an edge E where two different faces F1, F2 on ONE periodic surface meet at the
// surface's seam (e.g. the inner wall's crease, u = 0 = 1, after the core was split into chambers: the
// last chamber's wall came out as a suction face and a pressure face on the same surface).
//
// Why it matters: OCCT stores an edge's pcurves per (surface, location), so E carries the closed-surface
// pair (u = 0 and u = 1) and BRep_Tool::IsClosed(E, F) is true on BOTH faces, although each uses E
// once. A boolean that splits E (a trailing-edge slot through the crease) then treats its pieces as
// seams on both faces, and the face builder drops them (BOPAlgo_AlertFaceBuilderUnusedEdges; measured
// on every centreline slot of the built-in example, with the volume off by ~1e-4 relative).
//
// Repair (exact, no geometry changes): F1 gets its own copy of the surface and every one of its edges a
// pcurve on that copy (the same 2D curves), and E keeps a single pcurve on the shared surface, the one
// that meets F2's other edges at E's vertices. E is then an ordinary edge between two faces.
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct FalseSeamRepair {
  brep::NamedShape shape;  ///< the repaired part (a copy; the input is not modified), names carried over
  int repaired_edges = 0;  ///< false seams found and repaired (0: `shape` is the input itself)
};

/// Finds and repairs every false seam of `part` (see the header comment). Checks the repaired faces
/// (BRepCheck valid, their share of the volume integral unchanged within 1e-9 relative, no
/// repaired edge closed on either face);
/// throws FeatureFailure when a repair cannot be made or checked.
FalseSeamRepair repair_false_seams(const brep::NamedShape& part);

}  // namespace cg::features
