#include "src/mesh/mesh_sizes.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gmsh.h>

#include <algorithm>
#include <cmath>

#include "src/brep/named_shape.hpp"
#include "src/core/constants.hpp"
#include "src/core/parallel.hpp"

namespace cg::mesh {
namespace {

// Bounds of the sampling: 2^12 cells per side of a first-grid cell (a 5 mm cell split to 1.2 um), 20 000
// points along an edge (a 500 mm edge at 0.05 mm).
constexpr int kMaxCellDepth = 12, kMaxSamplesPerEdge = 20000;

bool is_outer_metal(const std::string& kind) {
  return kind == "blade_wall" || kind == "hub" || kind == "casing" || kind == "tip_cap" || kind == "hub_floor";
}

// The size a cooling-feature face needs at (u, v): 2 pi rho / N, rho the smaller principal radius of
// curvature there, clamped to [min_size, max_size]; max_size where the surface is flat.
double local_size(BRepLProp_SLProps& props, double u, double v, const MeshOptions& o) {
  props.SetParameters(u, v);
  if (!props.IsCurvatureDefined()) return o.max_size;
  const double k = std::max(std::abs(props.MaxCurvature()), std::abs(props.MinCurvature()));
  return k > 0 ? std::clamp(2 * kPi / (o.feature_curvature_elements * k), o.min_size, o.max_size) : o.max_size;
}

// Samples of one cooling-feature face, each with the size its own point needs; points that need
// max_size are left out (the field is capped there anyway). Wherever a face point needs size h, a sample
// lies within h / 2, so the field there is at most h (1 + size_growth / 2):
//  - each boundary edge at half its smallest size apart (17 points scanned along it);
//  - the interior by (u, v) cells from a 4 x 4 grid, split while a side is longer (in space) than the
//    size needed at the centre allows; a cell small enough gives its centre, when inside the face.
void sample_face(const TopoDS_Face& face, const MeshOptions& o, std::vector<GradedSizeField::Sample>& out) {
  const TopoDS_Face f = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const BRepAdaptor_Surface s(f);
  BRepLProp_SLProps props(s, 2, 1e-9);
  auto add = [&](double u, double v, double h) {
    const gp_Pnt p = s.Value(u, v);
    out.push_back({{p.X(), p.Y(), p.Z()}, h});
  };
  for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    double t0, t1;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, f, t0, t1);
    if (pcurve.IsNull() || BRep_Tool::Degenerated(edge)) continue;
    auto size_at = [&](double t) {
      const gp_Pnt2d uv = pcurve->Value(t);
      return local_size(props, uv.X(), uv.Y(), o);
    };
    double h_min = o.max_size;
    for (int i = 0; i <= 16; ++i) h_min = std::min(h_min, size_at(t0 + (t1 - t0) * i / 16));
    if (h_min >= o.max_size) continue;
    const double length = GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge));
    const int n = std::clamp(static_cast<int>(std::ceil(2 * length / h_min)), 2, kMaxSamplesPerEdge);
    for (int i = 0; i <= n; ++i) {
      const double t = t0 + (t1 - t0) * i / n;
      const double h = size_at(t);
      const gp_Pnt2d uv = pcurve->Value(t);
      if (h < o.max_size) add(uv.X(), uv.Y(), h);
    }
  }
  double u0, u1, v0, v1;
  BRepTools::UVBounds(f, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d inside(f, 1e-9);
  struct Cell {
    double u0, u1, v0, v1;
    int depth;
  };
  std::vector<Cell> cells;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      cells.push_back({u0 + (u1 - u0) * i / 4, u0 + (u1 - u0) * (i + 1) / 4, v0 + (v1 - v0) * j / 4, v0 + (v1 - v0) * (j + 1) / 4, 0});
  while (!cells.empty()) {
    const Cell c = cells.back();
    cells.pop_back();
    const double um = (c.u0 + c.u1) / 2, vm = (c.v0 + c.v1) / 2;
    const double h = local_size(props, um, vm, o);
    // Split across the sides longer than h / sqrt 2 (then the diagonal is at most h), each on its own:
    // a long thin cell is split along its length only.
    const double limit = h / std::sqrt(2.0);
    const bool split_u = s.Value(c.u0, vm).Distance(s.Value(c.u1, vm)) > limit && c.depth < kMaxCellDepth;
    const bool split_v = s.Value(um, c.v0).Distance(s.Value(um, c.v1)) > limit && c.depth < kMaxCellDepth;
    if (split_u || split_v) {
      const std::vector<std::pair<double, double>> us = split_u ? std::vector<std::pair<double, double>>{{c.u0, um}, {um, c.u1}}
                                                                : std::vector<std::pair<double, double>>{{c.u0, c.u1}};
      const std::vector<std::pair<double, double>> vs = split_v ? std::vector<std::pair<double, double>>{{c.v0, vm}, {vm, c.v1}}
                                                                : std::vector<std::pair<double, double>>{{c.v0, c.v1}};
      for (const auto& [a0, a1] : us)
        for (const auto& [b0, b1] : vs) cells.push_back({a0, a1, b0, b1, c.depth + 1});
    } else if (h < o.max_size && inside.Perform(gp_Pnt2d(um, vm)) == TopAbs_IN) {
      add(um, vm, h);
    }
  }
}

}  // namespace

std::unique_ptr<GradedSizeField> install_sizes(const std::vector<ModelSurface>& surfaces, const MeshOptions& o) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", o.max_size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", o.min_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", o.curvature_elements);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  for (const ModelSurface& s : surfaces) gmsh::model::mesh::setSizeFromBoundary(2, s.tag, 0);
  // The number of segments of a curve is the integral of 1 / size along it, rounded. gmsh's default
  // relative accuracy of that integral, 1e-9, took 120 s for the curves of the built-in example; 1e-3
  // takes 2.3 s and changes the number of curve nodes by 1 of 47 661.
  gmsh::option::setNumber("Mesh.LcIntegrationPrecision", 1e-3);

  // Faces sampled in parallel (o.threads), concatenated in face order: the same field for any thread count.
  std::vector<const ModelSurface*> features;
  if (o.feature_curvature_elements > 0)
    for (const ModelSurface& f : surfaces)
      if (!is_outer_metal(brep::feature_kind(f.name))) features.push_back(&f);
  std::vector<std::vector<GradedSizeField::Sample>> per_face(features.size());
  parallel_for(static_cast<int>(features.size()), o.threads,
               [&](int i, int) { sample_face(features[static_cast<std::size_t>(i)]->face, o, per_face[static_cast<std::size_t>(i)]); });
  std::vector<GradedSizeField::Sample> samples;
  for (const auto& v : per_face) samples.insert(samples.end(), v.begin(), v.end());
  auto field = std::make_unique<GradedSizeField>(std::move(samples), o.size_growth, o.max_size);
  const GradedSizeField* f = field.get();
  gmsh::model::mesh::setSizeCallback([f](int, int, double x, double y, double z) { return (*f)({x, y, z}); });
  return field;
}

}  // namespace cg::mesh
