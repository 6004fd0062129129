#pragma once
// The faces of a CAD blade sampled on a grid of their surface parameters (the points inside each face's
// boundary), and which of them are end faces: faces lying on the hub or casing stream surface (a
// solid's end caps, or the end planes of a cascade), which are neither cut nor measured.
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <Eigen/Core>
#include <vector>

#include "src/blade_import/channel_side.hpp"

namespace cg::cad_import {

enum class FaceRole { Wall, EndFace };

struct SampledFace {
  TopoDS_Face face;
  int index = 0;  // 1-based, in the shape's order of faces
  std::vector<Eigen::Vector3d> points;
  FaceRole role = FaceRole::Wall;
};

/// About `total_points` grid points over all faces, shared by surface area (at least 64 per face).
/// A face is an end face when all its points lie within `tolerance` (mm) of the hub (span 0) or of the
/// casing (span 1).
std::vector<SampledFace> sample_faces(const TopoDS_Shape& shape, int total_points, blade_import::ChannelSide& side,
                                      double tolerance);

}  // namespace cg::cad_import
