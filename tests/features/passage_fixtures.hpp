#pragma once
// Shared fixtures of the passage tests: the configured examples built once per test program, and
// measurements on named faces of the built solid (independent of the library's own checks).
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomLProp_SLProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "brep/temp_files.hpp"
#include "export/step_writer.hpp"
#include "brep/step_read_back.hpp"
#include "features/internal_cooling.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/cooling.hpp"

namespace cg::test {

struct CooledBlade {
  config::Config config;
  blade::BladeModel model;
  brep::NamedShape blade;  ///< uncooled
  features::PassagesResult cooled;
};

inline std::unique_ptr<CooledBlade> build_cooled(config::Config c) {
  auto out = std::make_unique<CooledBlade>();
  out->config = std::move(c);
  out->model = config::build_model(out->config);
  const brep::BladeSolid s = brep::build_blade_solid(out->model);
  out->blade = {s.solid, s.faces};
  out->cooled = pipeline::apply_cooling(out->model, pipeline::plan_cooling(out->config.cooling, out->model), out->blade);
  return out;
}

/// Builds a config's blade and its cooling (once per process and file; "" = the built-in example).
inline const CooledBlade& cooled_example(const std::string& file) {
  static std::map<std::string, std::unique_ptr<CooledBlade>> cache;
  auto& slot = cache[file];
  if (!slot) slot = build_cooled(file.empty() ? config::builtin_example_config() : config::load_config_file(file));
  return *slot;
}

/// The built-in example with its JSON edited (once per process and name), e.g. fewer features so a
/// test stays cheap.
inline const CooledBlade& cooled_builtin_variant(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  static std::map<std::string, std::unique_ptr<CooledBlade>> cache;
  auto& slot = cache[name];
  if (!slot) {
    nlohmann::json doc = nlohmann::json::parse(config::builtin_example_json());
    edit(doc);
    slot = build_cooled(config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "hpt_rotor"));
  }
  return *slot;
}

inline bool name_matches(const std::string& name, const std::string& pattern) {
  if (!pattern.empty() && pattern.back() == '*') return name.compare(0, pattern.size() - 1, pattern, 0, pattern.size() - 1) == 0;
  return name == pattern;
}

inline std::vector<TopoDS_Face> named_faces(const brep::NamedShape& s, const std::vector<std::string>& patterns) {
  std::vector<TopoDS_Face> out;
  for (const auto& f : s.faces)
    for (const auto& p : patterns)
      if (name_matches(f.name, p)) {
        out.push_back(f.face);
        break;
      }
  return out;
}

inline TopoDS_Compound compound(const std::vector<TopoDS_Face>& faces) {
  BRep_Builder bb;
  TopoDS_Compound c;
  bb.MakeCompound(c);
  for (const auto& f : faces) bb.Add(c, f);
  return c;
}

/// Smallest distance between two face groups (BRepExtrema_DistShapeShape).
inline double min_distance(const std::vector<TopoDS_Face>& a, const std::vector<TopoDS_Face>& b) {
  BRepExtrema_DistShapeShape d(compound(a), compound(b));
  return d.IsDone() ? d.Value() : -1;
}

/// Points of a face on an n x n parameter grid, inside its boundary.
inline std::vector<gp_Pnt> face_points(const TopoDS_Face& f, int n) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(f, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d cls(f, 1e-9);
  BRepAdaptor_Surface s(f);
  std::vector<gp_Pnt> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / n, v = v0 + (v1 - v0) * (j + 0.5) / n;
      if (cls.Perform(gp_Pnt2d(u, v)) == TopAbs_IN) out.push_back(s.Value(u, v));
    }
  return out;
}

/// Largest principal curvature magnitude at interior grid points of a face, min and max over the points.
inline std::pair<double, double> max_curvature_range(const TopoDS_Face& f, int n) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(f, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d cls(f, 1e-9);
  const Handle(Geom_Surface) s = BRep_Tool::Surface(f);
  double lo = HUGE_VAL, hi = 0;
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      const double u = u0 + (u1 - u0) * i / n, v = v0 + (v1 - v0) * j / n;
      if (cls.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      GeomLProp_SLProps p(s, u, v, 2, 1e-9);
      if (!p.IsCurvatureDefined()) continue;
      const double k = std::max(std::abs(p.MaxCurvature()), std::abs(p.MinCurvature()));
      lo = std::min(lo, k);
      hi = std::max(hi, k);
    }
  return {lo, hi};
}

/// Rolling-ball check of a concave fillet face of `part`: at interior grid points p the ball centre
/// c = p + r n (n the outward normal of the solid, i.e. into the cavity) must lie at distance r from the
/// faces around the fillet other than fillets (the supports the ball rolls on). Returns the min and max
/// of that distance over the points ({inf, 0} when no grid point lies inside the face).
inline std::pair<double, double> rolling_ball_distance_range(const brep::NamedShape& part, const TopoDS_Face& fillet,
                                                             double r, int n) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(part.shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<TopoDS_Face> supports;
  for (TopExp_Explorer e(fillet, TopAbs_EDGE); e.More(); e.Next())
    for (const TopoDS_Shape& f : edge_faces.FindFromKey(e.Current())) {
      if (f.IsSame(fillet)) continue;
      for (const auto& nf : part.faces)
        if (nf.face.IsSame(f) && (nf.name.size() < 7 || nf.name.compare(nf.name.size() - 7, 7, "_fillet") != 0))
          supports.push_back(TopoDS::Face(f));
    }
  const TopoDS_Compound around = compound(supports);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(fillet, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d cls(fillet, 1e-9);
  const Handle(Geom_Surface) s = BRep_Tool::Surface(fillet);
  const double sign = fillet.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
  double lo = HUGE_VAL, hi = 0;
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      const double u = u0 + (u1 - u0) * i / n, v = v0 + (v1 - v0) * j / n;
      if (cls.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      GeomLProp_SLProps p(s, u, v, 1, 1e-9);
      if (!p.IsNormalDefined()) continue;
      const gp_Pnt c = p.Value().Translated(gp_Vec(p.Normal()) * (sign * r));
      BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(c).Vertex(), around);
      if (!d.IsDone()) continue;
      lo = std::min(lo, d.Value());
      hi = std::max(hi, d.Value());
    }
  return {lo, hi};
}

inline double volume(const TopoDS_Shape& s) {
  GProp_GProps p;
  BRepGProp::VolumeProperties(s, p, 1e-9);
  return p.Mass();
}

/// Writes `s` as STEP (AP214, its face names) into a temporary directory and reads it back.
inline StepReadBack step_round_trip(const brep::NamedShape& s, const std::string& tag) {
  TempDir dir(tag);
  const auto file = dir.path / "blade.step";
  io::write_step(file, s.shape, s.faces, {io::StepSchema::AP214, "hpt_rotor"});
  return read_step_back(file);
}

/// Allowed deviation of a measured thickness: 1 % or 0.01 mm, whichever is larger (issue 9).
inline double thickness_tolerance(double value) { return std::max(0.01, 0.01 * value); }

}  // namespace cg::test
