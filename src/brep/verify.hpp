#pragma once
// Independent checks of a solid before it is written. Each check alone has missed a failure in
// our measurements (see the booleans notes), so all are run and reported by name.
#include <TopoDS_Shape.hxx>

#include <array>
#include <string>
#include <vector>

namespace cg::brep {

struct Check {
  std::string name;     ///< stable identifier, e.g. "one_solid" (used as key in report.json)
  bool passed = false;
  std::string message;  ///< what was measured
  double seconds = 0;   ///< wall time the check took
};

struct SolidCheck {
  Check one_solid;        ///< exactly one TopAbs_SOLID
  Check brep_valid;       ///< BRepCheck_Analyzer (with geometric controls)
  Check no_free_edges;    ///< ShapeAnalysis_FreeBounds finds no free boundary
  Check oriented_shells;  ///< ShapeAnalysis_Shell: faces of each shell consistently oriented
  Check closed_mesh;      ///< after BRepMesh, every oriented mesh edge has exactly one opposite
  Check positive_volume;  ///< volume > 0 (outward normals)

  double volume = 0;        ///< mm^3, BRepGProp::VolumeProperties with relative accuracy 1e-7
  double volume_error = 0;  ///< error estimate returned by BRepGProp
  double area = 0;          ///< mm^2, BRepGProp::SurfaceProperties with relative accuracy 1e-7
  std::array<double, 3> bbox_min{}, bbox_max{};  ///< tight box (BRepBndLib::AddOptimal), mm
  int face_count = 0;
  int solid_count = 0;
  int mesh_triangles = 0;

  std::vector<const Check*> checks() const {
    return {&one_solid, &brep_valid, &no_free_edges, &oriented_shells, &closed_mesh, &positive_volume};
  }
  bool all_passed() const;
  /// Names of the failed checks, comma separated (empty when all passed).
  std::string failed_names() const;
};

struct VerifyOptions {
  /// BRepMesh linear deflection as a fraction of the shape's bounding-box diagonal, and angular
  /// deflection (rad). The closed-mesh check tests topology (every mesh edge shared by exactly two
  /// triangles, opposite directions), which any mesh of every face shows; tying the deflection to the
  /// shape's size keeps the mesh small however many poles or faces the shape has. The mesh is made on a
  /// copy, so the checked shape is left untouched.
  double mesh_deflection_fraction = 1e-3;
  double mesh_angular_deflection = 0.5;
  /// Requested relative accuracy of BRepGProp's adaptive volume and area integration.
  double gprop_relative_accuracy = 1e-7;
};

/// Runs every check on `shape` (expected: one closed solid) and measures it. Never throws for a
/// bad shape: a bad shape gives failed checks. BRepCheck_Analyzer runs in parallel, and the mesh check
/// runs alongside the volume and area integrations (which only read the shape).
SolidCheck verify_solid(const TopoDS_Shape& shape, const VerifyOptions& options = {});

}  // namespace cg::brep
