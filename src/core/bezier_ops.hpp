#pragma once
// The Bézier kernels of the library, on flat arrays of poles (`width` doubles per pole, poles stored
// consecutively; homogeneous poles (w x, w y, [w z,] w) for rational geometry). Every algorithm that
// needs a knot span in Bézier form, a point by de Casteljau or a subdivided piece calls these (as
// OCCT's BSplCLib / PLib serve all of its algorithms); nothing allocates.
//
//  - span_bezier_poles: the Bézier poles of one knot span of a B-spline, each the blossom
//    f(a^(p-j), b^j) of the span [a, b] evaluated by de Boor's recursion with a different argument on
//    each level (Ramshaw's polar form; The NURBS Book 5.6). Exact up to rounding and independent of
//    the other spans, so a periodic curve's unwrapped spans convert directly.
//  - de_casteljau_point, split_bezier, restrict_bezier: evaluation and subdivision of a Bézier curve
//    (The NURBS Book A1.5), split_bezier_patch the same along one direction of a tensor patch.
namespace cg {

/// Bézier poles of knot span `span` (U[span] < U[span+1]) of a degree-p B-spline whose p+1 relevant
/// poles (span-p .. span) are stored consecutively, `width` doubles each (any width), in `poles`.
/// Writes p+1 poles to `out` (which may not alias `poles`).
void span_bezier_poles(int p, const double* U, int span, const double* poles, int width, double* out);

/// The point at t of the degree-p Bézier with poles `poles` (width doubles each) into out[0..width).
void de_casteljau_point(int p, int width, const double* poles, double t, double* out);

/// de Casteljau subdivision at t: `left` receives the poles of [0, t], `right` those of [t, 1], p+1
/// poles each; neither may alias `in`. The split point is left's last and right's first pole exactly.
void split_bezier(int p, int width, const double* in, double t, double* left, double* right);

/// Replaces the poles in place by those of the sub-range [a, b] of [0, 1] (0 <= a < b <= 1).
void restrict_bezier(int p, int width, double* poles, double a, double b);

/// Splits a tensor Bézier patch of degrees (pu, pv), pole (k, l) at offset (k * (pv+1) + l) * width
/// (width <= 8), at parameter t along u (along_u) or v, into two patches of the same layout.
void split_bezier_patch(int pu, int pv, int width, const double* in, bool along_u, double t, double* left,
                        double* right);

}  // namespace cg
