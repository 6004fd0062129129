#include "features/wall_features.hpp"

#include <chrono>

#include "features/false_seams.hpp"

namespace cg::features {
namespace {

class Lap {
 public:
  explicit Lap(PassageReport& report) : report_(report) {}
  void operator()(const std::string& stage) {
    const auto t = std::chrono::steady_clock::now();
    report_.seconds.emplace_back(stage, std::chrono::duration<double>(t - t0_).count());
    t0_ = t;
  }

 private:
  PassageReport& report_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

}  // namespace

void check_wall_feature_definitions(const CoreDefinition& def) {
  check_turbulator_definitions(def);
  check_trailing_edge_definition(def);
}

WallFeatureBuild build_wall_feature_tools(const blade::BladeModel& model, const CoreDefinition& def,
                                          const CoreBuild& core, PassageReport& report) {
  WallFeatureBuild b;
  if (def.turbulators.empty() && !def.trailing_edge) return b;
  Lap lap(report);
  WallLines lines(model.surface, core.inner_wall.surface);
  b.turbulators = build_turbulators(model, def, core, lines);
  lap("turbulator_tools");
  b.trailing_edge = build_trailing_edge(model, def, core, lines);
  lap("trailing_edge_tools");
  return b;
}

brep::NamedShape apply_wall_feature_tools(const brep::NamedShape& blade, WallFeatureBuild& b, PassageReport& report) {
  Lap lap(report);
  brep::NamedShape current = blade;
  auto run = [&](const std::string& group, BooleanOperation op, const std::vector<FeatureTool>& tools) {
    if (tools.empty()) return;
    BooleanStep step(op);
    for (const FeatureTool& t : tools) step.add(t);
    current = step.apply(current);
    b.steps.push_back(step.report());
    b.step_names.push_back(group);
    for (const ToolReport& t : step.report().tools)
      report.tools.push_back({t.feature, t.expected_volume, t.measured_volume, t.passed,
                              op == BooleanOperation::Fuse ? "fuse" : "cut"});
    lap(group);
  };
  run("turbulators", BooleanOperation::Fuse, b.turbulators.tools);
  run("pin_fins", BooleanOperation::Fuse, b.trailing_edge.pin_tools);
  if (b.trailing_edge.through_crease && !b.trailing_edge.slot_tools.empty()) {
    current = repair_false_seams(current).shape;
    lap("te_crease_repair");
  }
  run("te_slots", BooleanOperation::Cut, b.trailing_edge.slot_tools);
  for (const auto& t : b.turbulators.turbulators) report.volumes.push_back({t.name, t.added_volume, "added"});
  for (const auto& p : b.trailing_edge.pins) report.volumes.push_back({p.name, p.added_volume, "added"});
  for (const auto& s : b.trailing_edge.slots) report.volumes.push_back({s.name, s.removed_volume, "removed"});
  return current;
}

}  // namespace cg::features
