#define BOOST_TEST_MODULE probe
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cstdio>
#include "features/turbulators.hpp"
#include "features/trailing_edge.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
using namespace cg;
BOOST_AUTO_TEST_CASE(probe) {
  const config::Config c = config::builtin_example_config();
  const blade::BladeModel model = config::build_model(c);
  auto t0 = std::chrono::steady_clock::now();
  const features::CoreDefinition& def = *c.cooling.passages.core;
  const features::CoreBuild core = features::build_core_tools(model, def);
  auto lap = [&](const char* w) { auto t = std::chrono::steady_clock::now(); std::printf("%s %.3f s\n", w, std::chrono::duration<double>(t - t0).count()); t0 = t; };
  lap("core");
  features::WallLines lines(model.surface, core.inner_wall.surface);
  const features::TurbulatorBuild tb = features::build_turbulators(model, def, core, lines);
  lap("turbulators");
  for (const auto& t : tb.turbulators) std::printf("%s span %.4f suction %d len %.3f vol %.6f\n", t.name.c_str(), t.span, t.suction, t.length, t.added_volume);
  const features::TrailingEdgeBuild te = features::build_trailing_edge(model, def, core, lines);
  lap("te");
  for (const auto& s : te.slots) std::printf("%s span %.4f inlet %.3f lip %.3f end %.3f floor %.3f vol %.6f\n", s.name.c_str(), s.span, s.x_inlet, s.x_lip, s.x_end, s.floor_y, s.removed_volume);
  for (const auto& p : te.pins) std::printf("%s span %.4f row %d len %.3f chamber %.3f vol %.6f\n", p.name.c_str(), p.span, p.row, p.length, p.chamber_length, p.added_volume);
}
#include "src/blade/inner_wall.hpp"
BOOST_AUTO_TEST_CASE(te_numbers) {
  const config::Config c = config::builtin_example_config();
  const blade::BladeModel model = config::build_model(c);
  const blade::BladeCoordinates coords(model);
  for (double s : {0.05, 0.5, 0.95}) {
    for (double t : {1.0, 1.5, 2.0}) {
      const auto cr = blade::inner_wall_crease(coords, blade::ThicknessField::constant(t), s);
      const Eigen::Vector3d P = coords.frame(s, 1.0).point;
      std::printf("span %.2f t %.1f crease chords %.4f %.4f dist to TE %.3f  SS len %.2f\n", s, t, cr.suction_chord, cr.pressure_chord, (cr.crease - P).norm(), coords.section(s).suction_length());
    }
    for (double ch : {0.8, 0.85, 0.9, 0.95, 0.98})
      std::printf("   chord %.2f thickness %.3f\n", ch, (coords.frame(s, ch).point - coords.frame(s, -ch).point).norm());
  }
}
