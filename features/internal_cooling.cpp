#include "features/internal_cooling.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_boolean.hpp"
#include "features/passages/passage_checks.hpp"
#include "features/passages/radial_passages.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/wall_features.hpp"
#include "src/core/background.hpp"
#include "src/core/format.hpp"

namespace cg::features {

void validate_passages(const blade::BladeModel& model, const PassagesDefinition& def) {
  if (def.core && !def.radial_passages.empty())
    throw PassageInputError("radial_passages", "radial passages cannot be combined with a core (they would cut "
                                               "through its chambers); use one or the other");
  if (def.core) {
    check_core_definition(model, *def.core);
    check_wall_feature_definitions(*def.core);
  }
  if (!def.radial_passages.empty()) build_radial_passages(model, def.radial_passages);  // checks, cheap tools
}

PassagesResult build_passages(const blade::BladeModel& model, const brep::NamedShape& blade, const PassagesDefinition& def,
                              const std::optional<CoreBuild>& walls, const TrailingEdgePlan& trailing_edge,
                              Verification verification) {
  PassagesResult out;
  out.blade = blade;
  if (def.empty()) return out;
  if (def.core && !def.radial_passages.empty())
    throw PassageInputError("radial_passages", "radial passages cannot be combined with a core (they would cut "
                                               "through its chambers); use one or the other");
  auto t0 = std::chrono::steady_clock::now();
  auto lap = [&](const char* stage) {
    const auto t = std::chrono::steady_clock::now();
    out.report.seconds.emplace_back(stage, std::chrono::duration<double>(t - t0).count());
    t0 = t;
  };
  std::optional<CoreBuild> core;
  std::optional<RadialPassageBuild> radial;
  std::vector<FeatureTool> interior, cuts;
  if (def.core) {
    require(walls.has_value(), "build_passages: a core needs the walls of its plan");
    core = *walls;
    // The turbulator, pin and slot tools need only the walls: they are built in the background while
    // this thread builds the core's cells (the fillets and inlets there are single-threaded OCCT work),
    // on their own copy of the walls (end walls keep evaluation state). An error of the core comes
    // first, as when they ran one after the other; theirs still comes before the expensive booleans.
    PassageReport tool_report;
    auto wall_tools = start_in_background([&model, &def, &tool_report, &trailing_edge, walls = *core] {
      return build_wall_feature_tools(model, *def.core, walls, trailing_edge, tool_report);
    });
    build_core_cells(model, *def.core, *core);
    try {
      out.wall_features = wall_tools.get();
    } catch (...) {
      check_inlet_rims(*core);  // the inlets' input errors come before the wall features' (as in build order)
      throw;
    }
    for (const auto& [stage, s] : core->seconds) out.report.seconds.emplace_back("core_" + stage, s);
    for (const auto& [stage, s] : tool_report.seconds) out.report.seconds.emplace_back(stage, s);
    interior = core->interior_tools;
    cuts = core->cut_tools;
    t0 = std::chrono::steady_clock::now();
  }
  if (!def.radial_passages.empty()) {
    radial = build_radial_passages(model, def.radial_passages);
    cuts.insert(cuts.end(), radial->tools.begin(), radial->tools.end());
    lap("radial_passages");
  }
  // The inlets' rim test (point classification, ~0.3 s on a serpentine) beside the chambers' boolean:
  // its input error, when there is one, is the error reported.
  std::future<void> rims;
  if (core) rims = start_in_background([&core] { check_inlet_rims(*core); });
  PassageBooleanReport br;
  try {
    out.blade = apply_passage_tools(blade, interior, cuts, br, verification, def.retries);
  } catch (...) {
    if (rims.valid()) rims.get();
    throw;
  }
  if (rims.valid()) rims.get();
  lap("boolean");
  out.check = br.cut.check;
  out.checked = verification == Verification::EachStep;
  out.report.min_clearance = br.min_clearance;
  out.report.wall_clearance = br.wall_clearance;
  for (const auto& v : br.voids) out.report.tools.push_back({v.feature, v.expected_volume, v.measured_volume, v.passed, "void"});
  for (const auto& t : br.cut.tools) out.report.tools.push_back({t.feature, t.expected_volume, t.measured_volume, t.passed, "cut"});
  append_perturbed_tools(br.cut, out.report.perturbed);
  // The design checks measure the smooth chambers in the background while the turbulators, pins and
  // slots are booleaned in (both only read this solid: booleans here are non-destructive). The checks
  // still decide first: when one fails, that is the error, whatever the wall features did.
  auto checks = start_in_background([&] {
    measure_passages(model, out.blade, def, core ? &*core : nullptr, radial ? &*radial : nullptr, out.report);
    lap("checks");
  });
  brep::NamedShape cooled = out.blade;
  PassageReport wall_report;  // out.report belongs to the checks until they are done
  std::exception_ptr wall_error;
  if (core) {
    try {
      cooled = apply_wall_feature_tools(out.blade, out.wall_features, wall_report, verification, def.retries);
      // The last step verified the final solid.
      if (!out.wall_features.steps.empty()) out.check = out.wall_features.steps.back().check;
    } catch (...) {
      wall_error = std::current_exception();
    }
  }
  checks.get();
  std::string failed;
  for (const auto& t : out.report.thickness)
    if (!t.passed)
      failed += (failed.empty() ? "" : "; ") + t.feature + " measures " + format_value_limit(t.min, t.configured, Allowed::near).value +
                " mm, configured " + format_value_limit(t.min, t.configured, Allowed::near).limit + " mm";
  if (!out.report.all_chambers_fed)
    failed += (failed.empty() ? "" : "; ") + std::to_string(out.report.closed_cavities) + " closed cavities (no inlet)";
  if (!failed.empty()) throw FeatureFailure("design checks of the cooling passages failed: " + failed);
  if (wall_error) std::rethrow_exception(wall_error);
  out.blade = cooled;
  out.report.seconds.insert(out.report.seconds.end(), wall_report.seconds.begin(), wall_report.seconds.end());
  out.report.tools.insert(out.report.tools.end(), wall_report.tools.begin(), wall_report.tools.end());
  for (const BooleanStepReport& step : out.wall_features.steps) append_perturbed_tools(step, out.report.perturbed);
  out.report.volumes.insert(out.report.volumes.end(), wall_report.volumes.begin(), wall_report.volumes.end());
  if (core) out.core = std::make_shared<const CoreBuild>(std::move(*core));
  return out;
}

}  // namespace cg::features
