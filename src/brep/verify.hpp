#pragma once
// Independent checks of a solid before it is written. Each check alone has missed a failure in
// our measurements (see the booleans notes), so all are run and reported by name.
#include <TopoDS_Shape.hxx>

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "src/core/progress.hpp"

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

  double volume = 0;        ///< mm^3, integrate_solid (our face flux) at gprop_relative_accuracy per face
  double volume_error = 0;  ///< mm^3, the integration's error estimate (sum over the faces)
  /// mm^2, every face's area (BRepGProp's adaptive rule at gprop_relative_accuracy; NaN if it raised or
  /// the volume integration did), integrated alongside the volume; verify_solid returns with it done.
  double area() const { return area_; }
  double area_ = std::numeric_limits<double>::quiet_NaN();
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
  /// BRepMesh linear deflection relative to each edge's size, and angular deflection (rad); no interior
  /// refinement of the faces. The closed-mesh check tests topology (every mesh edge shared by exactly two
  /// triangles, opposite directions), which any conforming mesh of every face shows; a deflection tied
  /// to the size of each edge (not to the poles of the surfaces) keeps the mesh small, and a face of any
  /// size gets triangles (a deflection tied to the whole shape left the 3.8 mm end faces of a 100 m
  /// span untriangulated). The mesh is made on a copy, so the checked shape is left untouched.
  double mesh_relative_deflection = 0.01;
  double mesh_angular_deflection = 0.3;
  /// Requested relative accuracy of the volume (our face flux) and area (BRepGProp) integration.
  double gprop_relative_accuracy = 1e-7;
  /// Optional: sees the checks' progress; a stop request ends verify_solid with Cancelled.
  ProgressSink* progress = nullptr;
};

/// Runs every check on `shape` (expected: one closed solid) and measures it. Never throws for a
/// bad shape: a bad shape gives failed checks. Throws Cancelled when options.progress asks to stop.
/// BRepCheck_Analyzer runs in parallel, and the mesh check and the volume integration (which only read
/// the shape) run alongside the topology checks; the area is integrated in the background (see area()).
SolidCheck verify_solid(const TopoDS_Shape& shape, const VerifyOptions& options = {});

}  // namespace cg::brep
