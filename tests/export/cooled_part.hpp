#pragma once
// Cooled test parts made here, independent of the feature library. Kept (issue 20) where a test needs
// what the features cannot give: straight cylindrical chambers whose plane sections are exact ellipses
// and whose removed volume is known (test_visual_outputs), and a cheap part with an insert tube for the
// output-directory and mesh tests. The hand-off files of real feature-built blades are checked in
// tests/acceptance.
// The parts:
// a blade from a config (the built-in example or the C3X vane) with straight cylindrical chambers
// along the camber line (open at the hub), a row of film holes from the pressure side into the first
// chamber, and a separate insert tube inside the second chamber. Faces are named from the history of
// one BRepAlgoAPI_Cut ("blade_wall", "hub", "casing", "chamber_1_wall", "chamber_1_end",
// "film_row_1_hole_001", ...; the insert's faces "insert_1").
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GProp_GProps.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <stdexcept>

#include "adaptors/occt_convert.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/core/constants.hpp"

namespace cg::test {

struct CooledPart {
  brep::Part part;             ///< bodies[0] "blade" (cut), optional "insert_1"
  TopoDS_Shape uncooled;       ///< the blade solid before the cut
  std::vector<brep::NamedFace> uncooled_faces;
  double uncooled_volume = 0;  ///< mm^3
  double removed_volume = 0;   ///< V(uncooled) - V(blade), mm^3
  int chambers = 0, holes = 0;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> chamber_axes;  ///< end points of each chamber's axis
  std::vector<double> chamber_radii;                                      ///< mm
  blade::BladeModel model;
};

struct CooledPartOptions {
  int chambers = 2;         ///< straight chambers at chordwise positions spread over the thick part
  int holes = 4;            ///< film holes into chamber 1 (pressure side)
  bool insert = true;       ///< an insert tube in the last chamber (a second body)
  double hole_radius = 0.3; ///< mm
  double chamber_top = 0.85;///< span fraction where the chambers end (they open at the hub)
};

using cg::kPi;

inline double occt_volume(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::VolumeProperties(s, g, 1e-7, /*OnlyClosed=*/true);  // relative accuracy 1e-7 (as brep::verify_solid)
  return g.Mass();
}

using occt::to_pnt;

/// Solid cylinder from a to b with every face named `side` (lateral) / `ends` (caps).
inline brep::NamedShape named_cylinder(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                                       const std::string& side, const std::string& ends) {
  const Eigen::Vector3d d = b - a;
  BRepPrimAPI_MakeCylinder mk(gp_Ax2(to_pnt(a), gp_Dir(d.x(), d.y(), d.z())), radius, d.norm());
  brep::NamedShape s{mk.Shape(), {}};
  for (TopExp_Explorer e(s.shape, TopAbs_FACE); e.More(); e.Next())
    s.faces.push_back({TopoDS::Face(e.Current()),
                       BRepAdaptor_Surface(TopoDS::Face(e.Current())).GetType() == GeomAbs_Cylinder ? side : ends});
  return s;
}

/// Cuts `tools` from `part`, naming every result face from the cut's history. Throws when the result
/// is not one solid or a face gets no name.
inline brep::NamedShape cut_named(const brep::NamedShape& part, const std::vector<brep::NamedShape>& tools) {
  TopTools_ListOfShape args, tls;
  args.Append(part.shape);
  for (const auto& t : tools) tls.Append(t.shape);
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tls);
  cut.SetRunParallel(true);
  cut.Build();
  if (!cut.IsDone() || cut.HasErrors()) throw std::runtime_error("test part: cut failed");
  NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher> name_of;  // IsSame: orientation ignored
  auto record = [&](const brep::NamedFace& f) {
    if (cut.IsDeleted(f.face)) return;
    const TopTools_ListOfShape& mod = cut.Modified(f.face);
    if (mod.IsEmpty()) name_of.Bind(f.face, f.name);
    for (const TopoDS_Shape& m : mod) name_of.Bind(m, f.name);
  };
  for (const auto& f : part.faces) record(f);
  for (const auto& t : tools)
    for (const auto& f : t.faces) record(f);
  brep::NamedShape out{cut.Shape(), {}};
  int solids = 0;
  for (TopExp_Explorer e(out.shape, TopAbs_SOLID); e.More(); e.Next()) {
    ++solids;
    out.shape = e.Current();
  }
  if (solids != 1) throw std::runtime_error("test part: cut gave " + std::to_string(solids) + " solids");
  for (TopExp_Explorer e(out.shape, TopAbs_FACE); e.More(); e.Next()) {
    const std::string* name = name_of.Seek(e.Current());
    if (!name) throw std::runtime_error("test part: a face of the cut has no name");
    out.faces.push_back({TopoDS::Face(e.Current()), *name});
  }
  return out;
}

inline std::string numbered(const std::string& prefix, int k, int width) {
  std::string n = std::to_string(k);
  while (static_cast<int>(n.size()) < width) n = "0" + n;
  return prefix + n;
}

/// The cooled part of a config (see the file comment).
inline CooledPart make_cooled_part(const config::Config& c, const CooledPartOptions& o = {}) {
  CooledPart cp;
  cp.model = config::build_model(c);
  const brep::BladeSolid solid = brep::build_blade_solid(cp.model);
  const auto& s = cp.model.surface;
  // u at a fraction c of the way LE -> TE: increasing u runs LE (u_le) -> suction side -> TE (u_te) ->
  // pressure side -> LE, period 1. Not the arc-length chordwise coordinate, close enough for test tools.
  const double ule = cp.model.u_le, ute = cp.model.u_te <= ule ? cp.model.u_te + 1 : cp.model.u_te;
  auto surface_u = [&](double c) {  // c > 0 suction side, c < 0 pressure side
    const double u = c >= 0 ? ule + c * (ute - ule) : ule + c * (1 - (ute - ule));
    return u - std::floor(u);
  };
  auto camber = [&](double chordwise, double v, double* thickness) {
    const Eigen::Vector3d a = s.point(surface_u(chordwise), v);
    const Eigen::Vector3d b = s.point(surface_u(-chordwise), v);
    if (thickness) *thickness = (a - b).norm();
    return Eigen::Vector3d(0.5 * (a + b));
  };
  const double v0 = -0.04, v1 = o.chamber_top;  // from below the hub (open there) to chamber_top
  std::vector<brep::NamedShape> tools;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> axes;
  std::vector<double> radii;
  for (int k = 0; k < o.chambers; ++k) {
    const double chordwise = 0.2 + 0.3 * k / std::max(1, o.chambers - 1);
    const Eigen::Vector3d a = camber(chordwise, v0, nullptr), b = camber(chordwise, v1, nullptr);
    // Largest radius that keeps 30 % of the local half thickness as wall, along the straight axis.
    double r = 1e9;
    for (int i = 0; i <= 20; ++i) {
      const double v = 0.0 + (v1 - 0.0) * i / 20;
      double t = 0;
      const Eigen::Vector3d p = camber(chordwise, v, &t);
      const Eigen::Vector3d d = (b - a).normalized();
      const double off = ((p - a) - (p - a).dot(d) * d).norm();
      r = std::min(r, 0.7 * (0.5 * t - off) * 0.85);
    }
    if (!(r > 0.5)) throw std::runtime_error("test part: blade too thin for a chamber at chordwise " + std::to_string(chordwise));
    const std::string name = "chamber_" + std::to_string(k + 1);
    tools.push_back(named_cylinder(a, b, r, name + "_wall", name + "_end"));
    axes.emplace_back(a, b);
    radii.push_back(r);
  }
  const double c1 = 0.2;
  for (int j = 0; j < o.holes && o.chambers > 0; ++j) {
    const double v = 0.2 + (v1 - 0.35) * j / std::max(1, o.holes - 1);  // 0.2 .. 0.5 at the default top
    const Eigen::Vector3d p = s.point(surface_u(-c1), v);
    // Into the chamber axis point nearest the wall point: the hole ends inside the chamber.
    const auto& [a, b] = axes[0];
    const Eigen::Vector3d d = (b - a).normalized();
    const Eigen::Vector3d q = a + (p - a).dot(d) * d;
    const Eigen::Vector3d dir = (q - p).normalized();
    tools.push_back(named_cylinder(p - 1.5 * dir, q, o.hole_radius, numbered("film_row_1_hole_", j + 1, 3),
                                   numbered("film_row_1_hole_", j + 1, 3)));
  }
  cp.chambers = o.chambers;
  cp.chamber_axes = axes;
  cp.chamber_radii = radii;
  cp.holes = o.chambers > 0 ? o.holes : 0;
  brep::NamedShape blade{solid.solid, solid.faces};
  cp.uncooled = solid.solid;
  cp.uncooled_faces = solid.faces;
  cp.uncooled_volume = occt_volume(solid.solid);
  cp.part.push_back({"blade", tools.empty() ? blade : cut_named(blade, tools)});
  cp.removed_volume = cp.uncooled_volume - occt_volume(cp.part[0].geometry.shape);
  if (o.insert && o.chambers > 0) {
    // A tube in the last chamber, clear of its wall, from 25 % to 70 % of the chamber's length (inside
    // the blade: the chamber starts below the hub).
    const auto& [a, b] = axes.back();
    const double r = radii.back();
    const Eigen::Vector3d p0 = a + 0.25 * (b - a), p1 = a + 0.7 * (b - a);
    const brep::NamedShape outer = named_cylinder(p0, p1, 0.7 * r, "insert_1", "insert_1");
    const brep::NamedShape inner = named_cylinder(p0 - 0.1 * (b - a), p1 + 0.1 * (b - a), 0.5 * r, "insert_1", "insert_1");
    cp.part.push_back({"insert_1", cut_named(outer, {inner})});
  }
  return cp;
}

inline CooledPart cooled_example(const CooledPartOptions& o = {}) { return make_cooled_part(config::builtin_example_config(), o); }

inline CooledPart cooled_c3x(const CooledPartOptions& o = {}) {
  return make_cooled_part(config::load_config_file(std::string(COOLINGGEN_SOURCE_DIR) + "/data/examples/c3x_vane.json"), o);
}

}  // namespace cg::test
