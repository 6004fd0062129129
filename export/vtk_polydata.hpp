#pragma once
// vtkPolyData of the triangles of one body of a triangulated part (shared by the .vtp writer and the
// preview renderer): points, point normals "Normals", cell data "feature_id", "face_name_id",
// "face_id", field data "feature_kinds", "face_names", "body_name".
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

#include "export/triangulation.hpp"

namespace cg::io {

/// Polydata of the triangles of body `body` (all bodies when body < 0), only of feature kind id `kind`
/// when kind >= 0.
vtkSmartPointer<vtkPolyData> body_polydata(const PartTriangles& t, int body, const std::string& body_name, int kind = -1);

}  // namespace cg::io
