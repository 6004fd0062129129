#define BOOST_TEST_MODULE probe
#include <boost/test/unit_test.hpp>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <map>
#include <chrono>
#include <cstdio>
#include "features/face_names.hpp"
#include "features/passage_boolean.hpp"
#include "features/turbulators.hpp"
#include "features/trailing_edge.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
using namespace cg;
BOOST_AUTO_TEST_CASE(probe) {
  const config::Config c = config::builtin_example_config();
  const blade::BladeModel model = config::build_model(c);
  const features::CoreDefinition& def = *c.cooling.passages.core;
  const features::CoreBuild core = features::build_core_tools(model, def);
  const brep::BladeSolid s = brep::build_blade_solid(model);
  features::PassageBooleanReport rep;
  const brep::NamedShape part = features::apply_passage_tools({s.solid, s.faces}, core.interior_tools, {}, rep);
  features::WallLines lines(model.surface, core.inner_wall.surface);
  const features::TrailingEdgeBuild tb = features::build_trailing_edge(model, def, core, lines);
  for (const auto& t : tb.slot_tools) {
    if (t.feature != "te_slot_07" && t.feature != "te_slot_03" && t.feature != "te_slot_09") continue;
    BRepAlgoAPI_Common com(t.shape.shape, part.shape);
    const double vt = features::volume_of(t.shape.shape), vc = features::volume_of(com.Shape());
    std::printf("%s tool %.9f common %.9f expected %.9f\n", t.feature.c_str(), vt, vc, t.expected_volume);
    std::map<std::string, double> dist;
    for (const auto& f : part.faces) {
      BRepExtrema_DistShapeShape d(f.face, t.shape.shape);
      auto it = dist.find(f.name);
      if (it == dist.end() || d.Value() < it->second) dist[f.name] = d.Value();
    }
    for (const auto& [n, d] : dist) if (d < 0.5) std::printf("   %s %.6f\n", n.c_str(), d);
  }
}
