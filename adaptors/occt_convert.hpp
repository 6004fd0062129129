#pragma once
// Exact two-way conversion between CoolingGen B-splines and OCCT's Geom_BSplineCurve,
// Geom2d_BSplineCurve and Geom_BSplineSurface. Knots, multiplicities, poles and weights are copied
// bit for bit; periodic curves and surfaces map to OCCT's periodic form (one period of poles, knots
// continued by the period), so a round trip returns the identical representation. With a periodic
// seam multiplicity m > 1 OCCT's pole 1 is our pole m - 1 (its flat knots start p + 1 - m knots
// before the seam, ours p knots before it); the conversion rotates the poles accordingly.
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::occt {

Handle(Geom_BSplineCurve) to_occt(const BSplineCurve<3>& curve);
Handle(Geom2d_BSplineCurve) to_occt(const BSplineCurve<2>& curve);
Handle(Geom_BSplineSurface) to_occt(const BSplineSurface<3>& surface);

BSplineCurve<3> from_occt(const Geom_BSplineCurve& curve);
BSplineCurve<2> from_occt(const Geom2d_BSplineCurve& curve);
BSplineSurface<3> from_occt(const Geom_BSplineSurface& surface);

}  // namespace cg::occt
