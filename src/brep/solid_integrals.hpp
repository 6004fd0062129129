#pragma once
// Volume and area of a solid, face by face on all cores: the volume by our face flux (face_flux.hpp,
// ~10x BRepGProp_Vinert's speed on the cooled blades), the area by BRepGProp's adaptive Gauss
// integration with faces holding many holes integrated hole by hole.
//
// Why hole by hole (the area): BRepGProp integrates a face through its boundary (Green's theorem): at every Gauss
// point of every boundary edge it integrates the surface's integrand in u from the face's lowest u
// parameter to the point, across every knot span on the way. A small hole's loop in a large wall thus
// costs as much as a strip across the whole wall (measured: 3 s each for the volume and the area of a
// blade wall with 170 film-hole loops, 100 ms for the same wall without them). A closed loop's
// contribution does not depend on where the strips start (the difference is the loop integral of a
// function of v alone, zero for a closed loop), so each inner wire that is closed in the face's
// parameter plane is integrated as a face of its own (same surface, same orientation, only that wire:
// strips start at the loop), and the rest of the face (its outer wire and any other wires) as another.
// The sum is the same integral over the same edges and pcurves; each piece meets the requested
// relative accuracy on its own.
#include <TopoDS_Shape.hxx>

#include <vector>

namespace cg::brep {

struct SolidIntegrals {
  double volume = 0;        ///< mm^3, faces of the closed shells (BRepGProp::VolumeProperties, OnlyClosed)
  double volume_error = 0;  ///< mm^3, estimate of the volume's integration error (sum over faces)
  double area = 0;          ///< mm^2, every face (BRepGProp::SurfaceProperties)
  int pieces = 0;           ///< faces integrated (faces plus the inner wires split off)
};

/// Which integrals integrate_solid computes (the others stay 0).
enum class Integrals { VolumeAndArea, Volume, Area };

/// Volume of the closed shells and area of all faces of `shape` at relative accuracy `eps` (per piece).
/// `parallel`: pieces on all cores. Throws Standard_Failure where BRepGProp does.
SolidIntegrals integrate_solid(const TopoDS_Shape& shape, double eps, bool parallel = true,
                               Integrals which = Integrals::VolumeAndArea);

/// Volume bounded by every face of `shape` (as BRepGProp::VolumeProperties with OnlyClosed = false:
/// one reference point, the mean of the vertices), at relative accuracy `eps` per face. Shapes of 64
/// faces or more have their faces integrated on all cores; the fluxes are summed in face order, so the
/// result is the same on any number of threads.
double shape_volume(const TopoDS_Shape& shape, double eps);

/// THE volume of a shape for the checks (tool volumes, removed volumes, void orientation, coolant and
/// insert volumes of the mesher): the divergence theorem over every face of `shape` (faces of open
/// shells and loose faces count too: a compound of faces gives their share of the volume integral),
/// each face's flux by our adaptive Gauss quadrature (face_flux.hpp) to relative accuracy 1e-7 per
/// face, ten times below the 1e-6 volume checks; shape_volume(shape, 1e-7). OCCT's
/// BRepGProp::VolumeProperties agrees to ~1e-9 relative on the test solids (tests/brep/test_face_flux.cpp).
double volume_of(const TopoDS_Shape& shape);
/// volume_of of every shape, the shapes in parallel.
std::vector<double> volumes_of(const std::vector<TopoDS_Shape>& shapes);

}  // namespace cg::brep
