#include "features/passages.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "features/core_passages.hpp"
#include "features/passage_boolean.hpp"
#include "features/passage_checks.hpp"
#include "features/radial_passages.hpp"
#include "features/wall_features.hpp"

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

PassagesResult build_passages(const blade::BladeModel& model, const brep::NamedShape& blade,
                              const PassagesDefinition& def, bool verify_solid_after_steps) {
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
    core = build_core_tools(model, *def.core);
    for (const auto& [stage, s] : core->seconds) out.report.seconds.emplace_back("core_" + stage, s);
    interior = core->interior_tools;
    cuts = core->cut_tools;
    // Turbulator, pin and slot tools now: their input errors come before the expensive booleans.
    out.wall_features = build_wall_feature_tools(model, *def.core, *core, out.report);
    t0 = std::chrono::steady_clock::now();
  }
  if (!def.radial_passages.empty()) {
    radial = build_radial_passages(model, def.radial_passages);
    cuts.insert(cuts.end(), radial->tools.begin(), radial->tools.end());
    lap("radial_passages");
  }
  PassageBooleanReport br;
  out.blade = apply_passage_tools(blade, interior, cuts, br, verify_solid_after_steps);
  lap("boolean");
  out.check = br.cut.check;
  out.checked = verify_solid_after_steps;
  out.report.min_clearance = br.min_clearance;
  out.report.wall_clearance = br.wall_clearance;
  for (const auto& v : br.voids) out.report.tools.push_back({v.feature, v.expected_volume, v.measured_volume, v.passed, "void"});
  for (const auto& t : br.cut.tools) out.report.tools.push_back({t.feature, t.expected_volume, t.measured_volume, t.passed, "cut"});
  measure_passages(model, out.blade, def, core ? &*core : nullptr, radial ? &*radial : nullptr, out.report);
  lap("checks");
  std::string failed;
  for (const auto& t : out.report.thickness)
    if (!t.passed)
      failed += (failed.empty() ? "" : "; ") + t.feature + " measures " + std::to_string(t.min) + " mm, configured " +
                std::to_string(t.configured) + " mm";
  if (!out.report.all_chambers_fed)
    failed += (failed.empty() ? "" : "; ") + std::to_string(out.report.closed_cavities) + " closed cavities (no inlet)";
  if (!failed.empty()) throw FeatureFailure("design checks of the cooling passages failed: " + failed);
  // Turbulators, pin fins and TE slots after the passage checks (those measure the smooth chambers; a
  // failed design check stops the build before these booleans).
  if (core) {
    out.blade = apply_wall_feature_tools(out.blade, out.wall_features, out.report, verify_solid_after_steps);
    // The last step verified the final solid.
    if (!out.wall_features.steps.empty()) out.check = out.wall_features.steps.back().check;
  }
  if (core) out.core = std::make_shared<const CoreBuild>(std::move(*core));
  return out;
}

}  // namespace cg::features
