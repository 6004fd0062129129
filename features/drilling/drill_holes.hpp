#pragma once
// Direct drilling: many straight cylindrical holes, each through one thin wall, cut into a part
// without a general boolean, with local verification (issue 10, "Speed").
//
//   features::DrillResult r = features::drill_holes(part, holes, options);
//   r.part                      // the drilled solid, every face named (hole faces get hole.name)
//   r.holes[i]                  // per hole: drilled or fallen back (and why), volumes, tolerances
//
// Method (features/README.md, "Direct drilling"): a hole is the tool cylinder (origin, axis, radius,
// length). Where it crosses exactly one wall -- it enters one face A (outer wall) and leaves through one
// face B (chamber wall), both B-spline faces, its loops strictly inside them, no other face of the part
// within reach -- the hole is built directly:
//  1. Loops (drill_hole_geometry.hpp): each ruling line of the cylinder meets A and B once; Newton on
//     line(t) = S(u, v) from the axis hit found by our ray caster (src/algo/ray_surface.hpp), continued
//     around the circle, gives t(theta), (u, v)(theta) on both walls. 3D curve, pcurve on the wall and
//     pcurve on the cylinder are periodic cubic interpolants (src/fit, The NURBS Book A9.1 periodic form)
//     at the same parameters; the number of nodes doubles until all three lie within
//     `fit_tolerance` of the exact intersection (checked between the nodes), and the edge tolerance is
//     that measured deviation.
//  2. Topology (drill_hole_topology.hpp): the hole face is the cylinder between the two loops (one seam
//     edge); each loop edge is shared by the hole face and its wall face by construction; the wall face
//     is rebuilt on the same surface with its own wires plus one inner wire per hole; the shells are
//     rebuilt from the faces (no sewing).
//  3. Wall faces that many holes reach are first split into patches along iso-lines between the holes
//     (src/brep/face_patches.hpp), so each rebuilt face holds a bounded number of holes and every
//     local check costs O(holes on the face): the whole step stays linear in the number of holes.
// Holes that fail a precondition fall back to the verified boolean path (verified_boolean.hpp,
// BooleanStep), with the reason counted: first, on the part before drilling (a boolean's cost grows
// with the part's faces); the others are then planned again on its result and drilled.
//
// Verification (local; each failure throws FeatureFailure naming the hole(s)):
//  - per hole: removed volume by the divergence theorem over its own faces (hole face + the two wall
//    caps, BRepGProp) against an independent ray quadrature (Gauss-Legendre in radius x trapezoid in
//    angle of the wall chord of axis-parallel lines, our kernel): |a - b| <= volume_rel_tolerance * b
//    + the uncertainty the edge tolerances leave;
//  - every hole face: BRepCheck_Analyzer (its edges with all their pcurves, vertices, wire, face);
//  - every loop as an inner wire of its rebuilt wall: BRepCheck's wire checks in the face's context
//    (2D closure, orientation, self-intersection) and edge checks (pcurve on the wall). What
//    BRepCheck_Face adds -- wires of one face crossing each other or the outer wire -- is what the
//    margin checks exclude (rings of radius r + margin inside the face, axis distances >= r1 + r2 +
//    margin); whole_face_checks runs it anyway;
//  - the whole result: every edge used exactly twice with opposite orientations (closed, oriented
//    shells), one solid;
//  - optional (`verify_solid`): brep::verify_solid on the result (BRepCheck, free edges, closed mesh,
//    volume: global, costs about as much as the drilling itself).
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

#include "src/brep/boolean/verified_boolean.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"

namespace cg::features {

/// A straight cylindrical hole, given as its tool: the cylinder of `diameter` from `origin` along
/// `axis` for `length` mm. The tool starts outside the part and ends in the cavity behind the wall.
struct CylindricalHole {
  std::string name;  ///< feature and face name, e.g. "film_row_2_hole_014"
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< into the part (normalized by drill_holes)
  double diameter = 0;  ///< mm
  double length = 0;    ///< mm
};

struct DrillOptions {
  /// Target for the fitted loop curves: 3D curve, wall pcurve and cylinder pcurve within this of the
  /// exact intersection (mm). Reached by doubling the interpolation nodes (32 .. 512).
  double fit_tolerance = 1e-7;
  /// A loop must stay this far inside its face (mm, measured on a ring of radius r + margin) and
  /// two holes this far apart (axis distance >= r1 + r2 + margin); otherwise the hole falls back.
  double margin = 0.02;
  /// Smallest angle (deg) between the hole axis and a wall surface along the loop; below: falls back.
  double min_incidence_deg = 8;
  /// Per-hole |divergence volume - quadrature volume| <= rel * quadrature + uncertainty.
  double volume_rel_tolerance = 1e-6;
  /// Split faces reached by >= patch_min_holes holes into patches of about patch_holes_per_patch
  /// (src/brep/face_patches.hpp) first; 0: never. Off by default: every check here is per hole, so a wall
  /// with 1 000 holes costs no more per hole than one with 10 (measured, bench_holes), and the split
  /// (a general fuse, ~1-5 s) warns and is rejected on the cooled blade's trimmed chamber walls.
  int patch_min_holes = 0;
  int patch_holes_per_patch = 8;
  bool parallel = true;
  /// Also check every rebuilt wall face as a whole: BRepCheck_Analyzer of the face (all its wires) and
  /// its divergence integral (BRepGProp, 1e-9) after = before - its caps. Off by default: the per-hole
  /// checks cover the same ground locally (see above) and these cost O(holes on the face) each, on
  /// one thread per face (~10 ms per hole on the blade wall).
  bool whole_face_checks = false;
  /// brep::verify_solid on the final result (global; see above). Off: local checks only.
  bool verify_solid = false;
  brep::VerifyOptions verify;
  /// Options of the BooleanStep that takes the holes falling back.
  BooleanOptions fallback;
};

struct DrilledHole {
  std::string name;
  bool drilled = false;          ///< built directly; false: went through the BooleanStep fallback
  std::string fallback_reason;   ///< why not drilled (empty when drilled)
  std::string entry_face, exit_face;  ///< names of the faces the hole crosses (drilled holes)
  double volume = 0;             ///< mm^3 removed: divergence theorem over the hole's faces (drilled)
                                 ///< or measured by BooleanStep (fallback)
  double independent_volume = std::numeric_limits<double>::quiet_NaN();  ///< mm^3, ray quadrature
  double closure = 0;            ///< mm^3, |volume about two points| (0 for a closed boundary)
  double uncertainty = 0;        ///< mm^3 the edge tolerances leave in `volume`
  double edge_tolerance = 0;     ///< mm, largest tolerance of the hole's loop edges
  int nodes = 0;                 ///< interpolation nodes per loop
};

struct DrillResult {
  brep::NamedShape part;
  std::vector<DrilledHole> holes;  ///< in input order
  int drilled = 0, fallen_back = 0;
  int patched_faces = 0;           ///< faces added by splitting walls into patches
  int rebuilt_faces = 0;           ///< wall faces rebuilt with inner wires
  double volume_change = 0;        ///< mm^3, sum of the drilled holes' volumes (divergence theorem)
  /// mm^3, |sum over rebuilt faces of (integral after - before) + sum of the caps|: 0 up to the
  /// integration accuracy when every inner wire is where and how it should be.
  double face_balance = 0;
  /// Report of the fallback step(s) (tool_count 0 when none; tools in the order they were cut; check
  /// of the last step).
  BooleanStepReport fallback;
  brep::SolidCheck check;          ///< when options.verify_solid
  /// Wall-clock seconds per stage.
  double seconds = 0, seconds_patches = 0, seconds_geometry = 0, seconds_topology = 0, seconds_checks = 0,
         seconds_fallback = 0, seconds_verify = 0;
};

/// The tool of a hole for the verified boolean path: the cylinder (the frame drill_holes uses, so the
/// seam lies on the same ruling), every face named after the hole, symmetry axis set, expected volume
/// NaN (the step measures OCCT's Common).
FeatureTool hole_tool(const CylindricalHole& hole);

/// The preconditions alone, on `part` as it is (no patches, nothing built): per hole, why it would fall
/// back ("" when it would be drilled directly). Same errors as drill_holes for bad holes.
std::vector<std::string> drill_fallback_reasons(const brep::NamedShape& part, const std::vector<CylindricalHole>& holes,
                                                const DrillOptions& options = {});

/// Drills `holes` into `part` (one solid, named faces). Throws InvalidGeometry for a bad hole (zero or
/// non-finite axis, diameter or length <= 0, duplicate name), FeatureFailure when a check fails (naming
/// the hole) or the fallback step fails.
DrillResult drill_holes(const brep::NamedShape& part, const std::vector<CylindricalHole>& holes,
                        const DrillOptions& options = {});

}  // namespace cg::features
