#pragma once
// Shared fixtures of the film-cooling tests: a short straight vane (the HPT rotor's mid-span section,
// 12 mm span, so booleans and checks stay cheap) hollowed by the inner wall (1 mm wall, 1 mm end walls),
// and helpers to measure holes on the built solid.
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <gp_Cylinder.hxx>

#include <string>
#include <vector>

#include "blade/blade_fixtures.hpp"
#include "features/film/film_definition.hpp"
#include "tests/support/film_hollow_blade.hpp"
#include "features/film/hole_target.hpp"
#include "src/blade/blade_surface.hpp"

namespace cg::test {

inline blade::BladeModel short_vane(double span = 12, double max_thickness = 7.5) {
  blade::BladeDefinition d;
  d.flow_path = blade::StraightFlowPath{span};
  blade::BladeSectionDefinition s;
  s.shape = blade::test::rotor_section(max_thickness, 38, -64, -26);
  d.sections = {s};
  return blade::build_blade(d);
}

struct FilmVane {
  blade::BladeModel model;
  features::FilmHollowBlade hollow;
  features::HoleTarget target;
  explicit FilmVane(bool solid, double span = 12, double max_thickness = 7.5)
      : model(short_vane(span, max_thickness)), hollow(features::make_film_hollow_blade(model, 1.0, 1.0, solid)),
        target(features::film_hollow_target(model, hollow)) {}
};

/// A cylindrical row at a chordwise coordinate over spans 0.25 .. 0.75.
inline features::FilmRowDefinition film_row(double chord, double d = 0.4, double pitch_d = 4, double inclination = 30,
                                            double compound = 0) {
  features::FilmRowDefinition r;
  r.shape.diameter = d;
  r.position = {features::RowPosition::Kind::Chord, chord};
  r.span_start = 0.25;
  r.span_end = 0.75;
  r.pitch_d = pitch_d;
  r.inclination_deg = inclination;
  r.compound_deg = compound;
  return r;
}

/// Cylinder axes and radii of the faces named `name`.
inline std::vector<gp_Cylinder> named_cylinders(const brep::NamedShape& s, const std::string& name) {
  std::vector<gp_Cylinder> out;
  for (const brep::NamedFace& f : s.faces) {
    if (f.name != name) continue;
    BRepAdaptor_Surface a(f.face);
    if (a.GetType() == GeomAbs_Cylinder) out.push_back(a.Cylinder());
  }
  return out;
}

/// Total area of the faces named `name`.
inline double named_area(const brep::NamedShape& s, const std::string& name) {
  double area = 0;
  for (const brep::NamedFace& f : s.faces) {
    if (f.name != name) continue;
    GProp_GProps p;
    BRepGProp::SurfaceProperties(f.face, p, 1e-9);
    area += p.Mass();
  }
  return area;
}

}  // namespace cg::test
