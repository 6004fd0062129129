// Direct drilling (features/drill_holes.hpp) against the verified boolean path on the same holes.
#define BOOST_TEST_MODULE drill_holes
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cstdio>

#include "features/boolean_sample_part.hpp"
#include "features/drill_holes.hpp"
#include "features/drill_sample_holes.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

using namespace cg;

namespace {

struct Fixture {
  blade::BladeModel model;
  features::HollowBlade hb;
};

const Fixture& hollow() {
  static Fixture* f = [] {
    auto* x = new Fixture;
    x->model = config::build_model(config::builtin_example_config());
    features::HollowBladeOptions ho;
    ho.verify = false;
    x->hb = features::make_hollow_blade(x->model, ho);
    return x;
  }();
  return *f;
}

}  // namespace

BOOST_AUTO_TEST_CASE(drill_small_field) {
  const Fixture& f = hollow();
  features::HoleFieldOptions ho;
  ho.count = 12;
  const auto tools = features::make_hole_tools(f.model, f.hb, ho);
  const auto holes = features::holes_of_tools(tools);
  features::DrillOptions o;
  o.verify_solid = true;
  const auto r = features::drill_holes(f.hb.part, holes, o);
  for (const auto& h : r.holes)
    std::printf("%s drilled %d %s vol %.9f quad %.9f unc %.2e tol %.2e nodes %d\n", h.name.c_str(), h.drilled,
                h.fallback_reason.c_str(), h.volume, h.independent_volume, h.uncertainty, h.edge_tolerance, h.nodes);
  std::printf("balance %.3e, %.2f s (geometry %.2f topo %.2f checks %.2f verify %.2f) check %s vol %.6f (part %.6f)\n",
              r.face_balance, r.seconds, r.seconds_geometry, r.seconds_topology, r.seconds_checks, r.seconds_verify,
              r.check.failed_names().c_str(), r.check.volume, f.hb.volume);
  for (std::size_t i = 0; i < tools.size(); ++i) std::printf("tool expected %.9f\n", tools[i].expected_volume);
}
