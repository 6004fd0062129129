#include "src/cad_import/face_samples.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

#include "adaptors/occt_convert.hpp"

namespace cg::cad_import {
namespace {

double area_of(const TopoDS_Face& f) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(f, props);
  return std::abs(props.Mass());
}

// An n x n grid over the face's parameter box, cell centres, kept where they lie inside the face.
std::vector<Eigen::Vector3d> grid_points(const TopoDS_Face& face, int n) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const BRepAdaptor_Surface surface(face);
  BRepTopAdaptor_FClass2d inside(face, 1e-9);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / n, v = v0 + (v1 - v0) * (j + 0.5) / n;
      if (inside.Perform(gp_Pnt2d(u, v)) == TopAbs_IN) out.push_back(occt::to_eigen(surface.Value(u, v)));
    }
  return out;
}

bool on_span(const std::vector<Eigen::Vector3d>& points, blade_import::ChannelSide& side, double s, double tolerance) {
  return std::all_of(points.begin(), points.end(), [&](const Eigen::Vector3d& p) { return std::abs(side.offset(p, s)) <= tolerance; });
}

}  // namespace

std::vector<SampledFace> sample_faces(const TopoDS_Shape& shape, int total_points, blade_import::ChannelSide& side,
                                      double tolerance) {
  std::vector<SampledFace> faces;
  std::vector<double> areas;
  double total_area = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    faces.push_back({TopoDS::Face(e.Current()), static_cast<int>(faces.size()) + 1, {}, FaceRole::Wall});
    areas.push_back(area_of(faces.back().face));
    total_area += areas.back();
  }
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const double share = total_area > 0 ? areas[k] / total_area : 1.0 / static_cast<double>(faces.size());
    const int n = std::max(8, static_cast<int>(std::ceil(std::sqrt(share * total_points))));
    SampledFace& f = faces[k];
    f.points = grid_points(f.face, n);
    if (!f.points.empty() && (on_span(f.points, side, 0, tolerance) || on_span(f.points, side, 1, tolerance)))
      f.role = FaceRole::EndFace;
  }
  return faces;
}

}  // namespace cg::cad_import
