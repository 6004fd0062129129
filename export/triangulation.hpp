#pragma once
// Triangle mesh of a brep::Part for visualisation (VTK files, preview): BRepMesh on a copy of every
// body, face triangulations joined with their locations applied and REVERSED faces flipped (so every
// triangle is oriented outward), each triangle tagged with its body, face, face name and kind.
#include <Eigen/Core>
#include <vector>

#include "export/feature_style.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::io {

struct PartTriangles {
  std::vector<Eigen::Vector3d> points;       ///< mm; nodes are not shared between faces
  std::vector<Eigen::Vector3d> normals;      ///< outward unit normal at each point (from the surface)
  std::vector<std::array<int, 3>> triangles; ///< indices into points, outward orientation
  std::vector<int> body;                     ///< per triangle: body index in the part
  std::vector<int> face;                     ///< per triangle: face index within its body (NamedShape::faces order)
  std::vector<int> kind_id;                  ///< per triangle: FeatureTable kind id
  std::vector<int> name_id;                  ///< per triangle: FeatureTable name id
  FeatureTable table;
};

struct TriangulationOptions {
  double linear_deflection = 0.01;   ///< mm, > 0; at least 2e-5 of the part's diagonal is used
  double angular_deflection = 0.35;  ///< rad, > 0
};

/// Triangulates every named face of every body. Throws ExportError when a face gets no triangulation.
PartTriangles triangulate_part(const brep::Part& part, const TriangulationOptions& options = {});

}  // namespace cg::io
