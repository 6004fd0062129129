#pragma once
// One cut of a CAD blade's wall faces by a stream surface (a face on the surface of revolution of a
// streamline, or on a plane of a cascade): the section edges (OCCT's BRepAlgoAPI_Section), each sampled within a chord
// error (GCPnts_QuasiUniformDeflection), chained end to end into outlines. Faces need not share their
// edges (an IGES file's surfaces, a shell that was never sewn): pieces whose ends lie within `gap` are
// joined.
#include <TopoDS_Shape.hxx>

#include <Eigen/Core>
#include <vector>

namespace cg::cad_import {

struct StreamCut {
  int edges = 0;                                      // section edges found
  std::vector<std::vector<Eigen::Vector3d>> closed;   // closed outlines (the first point not repeated)
  std::vector<std::vector<Eigen::Vector3d>> open;     // chains whose ends meet nothing within the gap
};

/// Throws AlgorithmFailure when OCCT's section fails.
StreamCut cut_faces(const TopoDS_Shape& faces, const TopoDS_Shape& surface, double gap, double chord_error);

}  // namespace cg::cad_import
