#pragma once
// Element sizes of `coolinggen mesh` on the gmsh model being meshed (a gmsh session must be open and the
// compound imported):
//  - max_size / min_size bound every element; curvature_elements per 2 pi of curvature on every
//    surface (gmsh Mesh.MeshSizeFromCurvature: the leading and trailing edges of the outer wall);
//  - every point of a cooling-feature face (every face that is not outer metal) needs 2 pi rho / N
//    (rho the local smaller radius of curvature, N = feature_curvature_elements): the faces are sampled
//    (sample_face in the .cpp) and the sizes graded into the part at size_growth by a GradedSizeField
//    (size_field.hpp), installed as gmsh's size callback for curves, surfaces and volumes;
//  - sizes are not extended from a surface's boundary into its interior (setSizeFromBoundary 0 on every
//    surface): on a wall pierced by 150 film holes that interpolation meshed the whole wall at the holes'
//    size (2.3 M triangles on the built-in example's outer wall). The volume mesh still grows from the
//    surface mesh (Mesh.MeshSizeExtendFromBoundary 1, which gmsh 4.8 applies to 3D only once every
//    surface has its own setting).
#include <TopoDS_Face.hxx>

#include <memory>
#include <string>
#include <vector>

#include "src/mesh/mesh_options.hpp"
#include "src/mesh/size_field.hpp"

namespace cg::mesh {

/// A gmsh surface of the model and the named B-rep face it was matched to.
struct ModelSurface {
  int tag = 0;
  TopoDS_Face face;
  std::string name;
};

/// Sets the size options and the size callback on the current gmsh model. The returned field is what
/// the callback reads: keep it alive until meshing is done.
std::unique_ptr<GradedSizeField> install_sizes(const std::vector<ModelSurface>& surfaces, const MeshOptions& options);

}  // namespace cg::mesh
