#pragma once
// Volume flux of a trimmed face, 1/3 * integral over the face of (x - c) . n dA (n the normal of the
// face in its orientation): summed over the faces of a closed shell it is the enclosed volume
// (divergence theorem), for any reference point c.
//
// The face integral over the trimmed parameter domain D is turned into a boundary integral (Green's
// theorem, as BRepGProp does): with g(u, v) = (S - c) . (S_u x S_v) and the strip integral
// G(u, v) = integral of g(s, v) ds from u0 to u,  integral over D of g du dv = closed integral of G dv
// over the boundary of D (counter-clockwise: an OCCT face in FORWARD orientation has its material on
// the left of its pcurves). What differs from BRepGProp_Vinert, and makes it several times faster on
// our B-spline walls:
//  - the strip integral follows the surface's knot spans with the Gauss rule that is exact there
//    (g is a polynomial of degree 3p - 1 in the strip direction on a polynomial B-spline of degree p:
//    ceil(3p / 2) points), where BRepGProp spreads 2 (p + 1) * spans points over the whole strip;
//  - patches are evaluated from their cached polynomial form (SurfaceEvaluator), not by OCCT's span
//    cache, which is rebuilt at every knot line a strip crosses;
//  - the strips run in the direction with fewer spans (then the boundary integral is -closed integral
//    of H du, H the strip integral in v), and start from the middle of their loop: every wire closed in
//    the parameter plane takes its own start u0 (a closed loop's integral does not depend on it), so a
//    small hole costs as little as a small face.
// Surfaces other than polynomial B-splines (rational B-splines, analytic and swept surfaces) get a
// 10-point rule on pieces refined until halving them changes sample strips by less than the accuracy.
// The boundary integral is adaptive per edge (10-point Gauss on a panel against its two halves).
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

namespace cg::brep {

struct FaceFlux {
  double value = 0;  ///< mm^3
  double error = 0;  ///< estimate (sum over panels of |halves - whole|), mm^3
  bool ours = true;  ///< false: the face needed BRepGProp_Vinert (no wires, or an edge without pcurve)
};

/// Which parameter the strip integrals run along: the cheaper one (fewer spans times rule points), or
/// one fixed (the two are independent computations of the same integral; tests compare them).
enum class StripDirection { Cheaper, U, V };

/// 1/3 * integral over `face` of (x - c) . n dA to `relative_accuracy` of the integral's scale (the
/// integral of |G dv| over the boundary: a face whose flux cancels to ~0 still gets a finite target).
FaceFlux face_volume_flux(const TopoDS_Face& face, const gp_Pnt& c, double relative_accuracy,
                          StripDirection direction = StripDirection::Cheaper);

}  // namespace cg::brep
