#include "features/wall/wall_features.hpp"

#include <chrono>

#include "src/brep/boolean/false_seams.hpp"

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
                                          const CoreBuild& core, const TrailingEdgePlan& trailing_edge,
                                          PassageReport& report) {
  WallFeatureBuild b;
  if (def.turbulators.empty() && !def.trailing_edge) return b;
  Lap lap(report);
  WallLines lines(model.surface, core.inner_wall.surface);
  b.turbulators = build_turbulators(model, def, core, lines);
  lap("turbulator_tools");
  b.trailing_edge = build_trailing_edge(def, trailing_edge, lines);
  lap("trailing_edge_tools");
  return b;
}

brep::NamedShape apply_wall_feature_tools(const brep::NamedShape& blade, WallFeatureBuild& b, PassageReport& report,
                                          Verification verification, PerturbedRetries retries) {
  const struct Group {
    const char* name;
    BooleanOperation op;
    const std::vector<FeatureTool>* tools;
  } groups[] = {{"turbulators", BooleanOperation::Fuse, &b.turbulators.tools},
                {"pin_fins", BooleanOperation::Fuse, &b.trailing_edge.pin_tools},
                {"te_slots", BooleanOperation::Cut, &b.trailing_edge.slot_tools}};
  // The groups' booleans in a chain. Every boolean gets its cheap checks and the per-tool volume check
  // (BooleanStep); verify_solid (BRepCheck, free edges, shells, closed mesh, ~1 s on the blade) runs on
  // the chain's result only when `steps` is not EachStep: the steps touch disjoint regions and a defect a
  // step leaves is still in the final solid, where the check finds it. Only if it does is the chain
  // redone with verify_solid after every step, which names the group (and the tools) to blame.
  std::vector<ToolVolumeCheck> tools;
  auto chain = [&](Verification steps, std::vector<std::pair<std::string, double>>& seconds) {
    b.steps.clear();
    b.step_names.clear();
    tools.clear();
    brep::NamedShape current = blade;
    auto t0 = std::chrono::steady_clock::now();
    for (const Group& g : groups) {
      if (g.tools->empty()) continue;
      if (g.tools == &b.trailing_edge.slot_tools && b.trailing_edge.through_crease) {
        current = repair_false_seams(current).shape;  // centreline slots cut through the crease
        const auto t = std::chrono::steady_clock::now();
        seconds.emplace_back("te_crease_repair", std::chrono::duration<double>(t - t0).count());
        t0 = t;
      }
      BooleanOptions options;
      options.verification = steps;
      options.prune_face_pairs = steps != Verification::EachStep;  // the redo that locates a defect takes no shortcut
      options.perturbed_retries = retries;
      BooleanStep step(g.op, options);
      for (const FeatureTool& t : *g.tools) step.add(t);
      current = step.apply(current);
      b.steps.push_back(step.report());
      b.step_names.push_back(g.name);
      for (const ToolReport& t : step.report().tools)
        tools.push_back({t.feature, t.expected_volume, t.measured_volume, t.passed,
                         g.op == BooleanOperation::Fuse ? "fuse" : "cut"});
      const auto t = std::chrono::steady_clock::now();
      seconds.emplace_back(g.name, std::chrono::duration<double>(t - t0).count());
      t0 = t;
    }
    return current;
  };
  std::vector<std::pair<std::string, double>> seconds;
  brep::NamedShape current = chain(Verification::FinalOnly, seconds);
  if (!b.steps.empty() && verification == Verification::EachStep) {
    const auto t0 = std::chrono::steady_clock::now();
    BooleanStepReport& last = b.steps.back();
    last.check = brep::verify_solid(current.shape);
    last.seconds_verify = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    seconds.emplace_back("wall_features_verify", last.seconds_verify);
    // Throws FeatureFailure naming the group and tools, or passes (every step's result then verified).
    if (!last.check.all_passed()) current = chain(Verification::EachStep, seconds);
  }
  report.seconds.insert(report.seconds.end(), seconds.begin(), seconds.end());
  report.tools.insert(report.tools.end(), tools.begin(), tools.end());
  for (const auto& t : b.turbulators.turbulators) report.volumes.push_back({t.name, t.added_volume, "added"});
  for (const auto& p : b.trailing_edge.pins) report.volumes.push_back({p.name, p.added_volume, "added"});
  for (const auto& s : b.trailing_edge.slots) report.volumes.push_back({s.name, s.removed_volume, "removed"});
  return current;
}

}  // namespace cg::features
