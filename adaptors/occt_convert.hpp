#pragma once
// Exact two-way conversion between CoolingGen B-splines and OCCT's Geom_BSplineCurve,
// Geom2d_BSplineCurve and Geom_BSplineSurface. Knots, multiplicities, poles and weights are copied
// bit for bit; periodic curves and surfaces map to OCCT's periodic form (one period of poles, knots
// continued by the period), so a round trip returns the identical representation. With a periodic
// seam multiplicity m > 1 OCCT's pole 1 is our pole m - 1 (its flat knots start p + 1 - m knots
// before the seam, ours p knots before it); the conversion rotates the poles accordingly.
// Points and vectors: to_pnt / to_vec / to_dir (Eigen -> OCCT) and to_eigen (OCCT -> Eigen), coordinate
// by coordinate (exact; to_dir normalises, as gp_Dir does).
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>
#include <gp_Vec2d.hxx>
#include <gp_XYZ.hxx>

#include <Eigen/Core>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::occt {

Handle(Geom_BSplineCurve) to_occt(const BSplineCurve<3>& curve);
Handle(Geom2d_BSplineCurve) to_occt(const BSplineCurve<2>& curve);
Handle(Geom_BSplineSurface) to_occt(const BSplineSurface<3>& surface);

BSplineCurve<3> from_occt(const Geom_BSplineCurve& curve);
BSplineCurve<2> from_occt(const Geom2d_BSplineCurve& curve);
BSplineSurface<3> from_occt(const Geom_BSplineSurface& surface);

inline gp_Pnt to_pnt(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }
inline gp_Vec to_vec(const Eigen::Vector3d& v) { return gp_Vec(v.x(), v.y(), v.z()); }
/// Throws Standard_ConstructionError for a zero vector (gp_Dir).
inline gp_Dir to_dir(const Eigen::Vector3d& v) { return gp_Dir(v.x(), v.y(), v.z()); }

inline Eigen::Vector3d to_eigen(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }
inline Eigen::Vector3d to_eigen(const gp_Pnt& p) { return to_eigen(p.XYZ()); }
inline Eigen::Vector3d to_eigen(const gp_Vec& v) { return to_eigen(v.XYZ()); }
inline Eigen::Vector2d to_eigen(const gp_Pnt2d& p) { return {p.X(), p.Y()}; }
inline Eigen::Vector2d to_eigen(const gp_Vec2d& v) { return {v.X(), v.Y()}; }

}  // namespace cg::occt
