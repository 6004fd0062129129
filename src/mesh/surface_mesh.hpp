#pragma once
// The surface mesh of `coolinggen mesh` (gmsh 2D) with the algorithm chosen per surface and our own
// check of every triangle.
//
// Algorithm: Frontal-Delaunay (gmsh 6: the best-shaped triangles) except on surfaces gmsh meshes with its
// periodic mesher (a periodic surface, or a face with a seam edge) that are bounded by more than
// kFrontalCurveLimit curves: those get Delaunay (5). Measured on the built-in example (gmsh 4.8.4): on
// periodic surfaces gmsh's Frontal-Delaunay tests every point it inserts against the face's whole
// boundary, sampled at 299 segments per curve (meshGeneratorPeriodic -> bowyerWatsonFrontal ->
// pointInsideParametricDomain), so its cost is points x curves. The outer wall is one periodic B-spline
// face with 390 boundary curves (172 loops: the film-hole exits): 116 000 segments per point, 206 s for
// 168 000 triangles, against 10.7 s with Delaunay (5), which tests no point against the boundary.
// MeshAdapt (1) refines with the same test and is slower still.
//
// Check: gmsh's own check after a Delaunay-type algorithm (normals at the triangle's three nodes) takes
// the wrong side of a seam where two faces of one periodic surface meet at a crease (the built-in
// example's trailing-edge chamber: C0 knot at the seam, the normals 120 deg apart), calls the mesh
// folded and re-meshes the face with MeshAdapt (51-72 s for that face alone). Here gmsh's switch is off;
// each triangle is checked against the surface normal at one of its own interior nodes (or, when it has
// none, at its centroid's projection), which stays on the face's side. Only a surface with a triangle
// against the normal is re-meshed with MeshAdapt; one that is still folded is an error.
#include <string>
#include <vector>

#include "src/mesh/mesh_sizes.hpp"

namespace cg::mesh {

/// Periodic surfaces with more boundary curves than this are meshed with Delaunay instead of
/// Frontal-Delaunay: 16 curves are 4 800 boundary segments, ~0.07 ms per inserted point.
constexpr int kFrontalCurveLimit = 16;

struct SurfaceMeshStats {
  int frontal_delaunay = 0, delaunay = 0;
  std::vector<std::string> remeshed;  ///< faces re-meshed with MeshAdapt after the check
};

/// Generates the 2D mesh of the current gmsh model (1D included) as described above. Throws MeshError
/// naming the face when a surface is still folded after MeshAdapt.
SurfaceMeshStats mesh_surfaces(const std::vector<ModelSurface>& surfaces);

}  // namespace cg::mesh
