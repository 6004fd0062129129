#include "src/brep/boolean/verified_boolean.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <OSD_Parallel.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <sstream>

#include "src/brep/boolean/boolean_disjoint.hpp"
#include "src/brep/boolean/boolean_expected.hpp"
#include "src/brep/boolean/boolean_naming.hpp"
#include "src/brep/face_patches.hpp"
#include "src/brep/boolean/boolean_perturb.hpp"
#include "src/brep/boolean/boolean_run.hpp"
#include "src/brep/boolean/boolean_volume.hpp"
#include "src/brep/occt_progress.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int count_solids(const TopoDS_Shape& s) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(s, TopAbs_SOLID, m);
  return m.Extent();
}

// Test hook, read here only: COOLINGGEN_TEST_FAIL_VOLUME=<feature> fails that feature's volume check on
// every attempt, so the path of a boolean the tool cannot verify (retries, then exit 3 naming the
// feature) stays tested end to end while no real design takes it (tests/cli/test_cli_sections.cpp).
bool injected_volume_failure(const std::string& label) {
  static const std::string feature = [] {
    const char* v = std::getenv("COOLINGGEN_TEST_FAIL_VOLUME");
    return std::string(v ? v : "");
  }();
  return !feature.empty() && label == feature;
}

// A tool of the step after overlapping tools were fused: pairwise disjoint from the others.
struct Unit {
  std::vector<int> members;  // indices into the step's tools
  std::string label;         // member features, " + " separated
  brep::NamedShape shape;
  std::optional<gp_Ax1> axis;
  double expected = std::numeric_limits<double>::quiet_NaN();
  double expected_before_retries = std::numeric_limits<double>::quiet_NaN();
  std::string expected_source;
  // Outcome.
  double measured = 0, closure = 0, uncertainty = 0;
  int retries = 0;
  std::string perturbation;
  bool perturbation_changed_geometry = false;
  bool passed = false;
};

// One boolean of a part with some units and its cheap checks (and verify_solid when asked).
struct Attempt {
  brep::NamedShape result;
  std::string failure;        // a failure not attributable to one tool ("" = none)
  std::string warning;        // BOPAlgo warnings located at the suspects
  std::vector<int> suspects;  // units whose measured volume is wrong
  std::vector<ToolVolume> volumes;
  brep::SolidCheck check;
  bool verified = false;
  bool ok() const { return failure.empty() && suspects.empty(); }
};

class Engine {
 public:
  Engine(BooleanOperation op, const BooleanOptions& o, BooleanStepReport& report)
      : op_(op), opt_(o), report_(report), prune_(o.prune_face_pairs) {}

  void stop_pruning() { prune_ = false; }

  std::vector<Unit> units;
  std::vector<std::string> failures;  // features that could not be applied, with the reason

  // Applies units `ids` to `part`: one boolean; on failure, guilty units are isolated (by their volume,
  // by the shapes OCCT's warnings name, or by bisection) and retried perturbed. A unit that cannot be
  // applied is recorded in `failures` and left out. `verify`: run verify_solid on every accepted
  // boolean (otherwise the caller verifies the final result once).
  brep::NamedShape apply_group(const brep::NamedShape& part, std::vector<int> ids, bool verify) {
    if (ids.empty()) return part;
    Attempt a = attempt(part, ids, units_shapes(ids), ids, verify);
    if (a.ok()) return accept(a, ids);
    note(a, ids);
    if (ids.size() == 1) return retry(part, ids.front(), a, verify);
    if (a.failure.empty()) {
      // Only some tools are to blame: the others first (in one boolean), then each suspect alone.
      std::vector<int> rest;
      for (int id : ids)
        if (std::find(a.suspects.begin(), a.suspects.end(), id) == a.suspects.end()) rest.push_back(id);
      brep::NamedShape r = apply_group(part, rest, verify);
      for (int id : a.suspects) r = apply_group(r, {id}, verify);
      return r;
    }
    // Not attributable: bisect (spatially coherent halves).
    sort_spatially(ids);
    const std::vector<int> low(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(ids.size() / 2));
    const std::vector<int> high(ids.begin() + static_cast<std::ptrdiff_t>(ids.size() / 2), ids.end());
    return apply_group(apply_group(part, low, verify), high, verify);
  }

  void reset_outcomes() {
    for (Unit& u : units) {
      u.passed = false, u.measured = 0, u.closure = 0, u.uncertainty = 0, u.retries = 0;
      u.perturbation.clear();
      u.perturbation_changed_geometry = false;
      u.expected = u.expected_before_retries;
    }
  }

  // verify_solid on a result; true when every check passed (the report keeps the check).
  bool verify_final(const brep::NamedShape& result) {
    const auto t = Clock::now();
    brep::VerifyOptions vo = opt_.verify;
    vo.progress = opt_.progress;
    report_.check = brep::verify_solid(result.shape, vo);
    report_.check.one_solid.passed = count_solids(result.shape) == opt_.expected_solids;
    report_.seconds_verify += since(t);
    return report_.check.all_passed();
  }

 private:
  std::vector<TopoDS_Shape> units_shapes(const std::vector<int>& ids) const {
    std::vector<TopoDS_Shape> s;
    for (int id : ids) s.push_back(units[static_cast<std::size_t>(id)].shape.shape);
    return s;
  }

  // The B-rep defines each volume only to within its edge tolerances (ToolVolume::uncertainty).
  bool volume_ok(double measured, double expected, const ToolVolume& tv) const {
    const double tol = opt_.volume_rel_tolerance * std::abs(expected) + opt_.volume_abs_tolerance + tv.uncertainty;
    return std::abs(measured - expected) <= tol && tv.closure <= tol;
  }

  // `shapes[k]` is the (possibly perturbed) shape of unit ids[k]; `expected` from units unless given.
  Attempt attempt(const brep::NamedShape& part, const std::vector<int>& ids, const std::vector<TopoDS_Shape>& shapes,
                  const std::vector<int>& for_names, bool verify, const std::vector<double>* expected = nullptr,
                  const std::vector<const brep::NamedShape*>* named = nullptr) {
    ++report_.boolean_runs;
    check_cancel(opt_.progress, "verified boolean");
    auto t = Clock::now();
    const Handle(brep::OcctProgress) progress = new brep::OcctProgress(opt_.progress, "verified boolean");
    const bool pruned = prune_;
    const BooleanRun run = run_boolean(part.shape, shapes, op_, opt_.parallel, pruned, progress->Start());
    progress->throw_if_stopped();
    report_.seconds_boolean += since(t);
    report_.seconds_intersect += run.seconds_intersect;
    report_.candidate_face_pairs += run.candidate_face_pairs;
    report_.intersected_face_pairs += run.intersected_face_pairs;
    if (pruned) {
      // A failed pruned boolean proves nothing against the tools: repeat it with every face pair.
      Attempt a = checked(run, part, ids, shapes, for_names, verify, expected, named);
      if (a.ok()) return a;
      prune_ = false;
      ++report_.unpruned_repeats;
      report_.warnings.push_back("boolean with pruned face pairs rejected (" + (a.failure.empty() ? a.warning : a.failure) +
                                 "): repeated with every face pair");
      return attempt(part, ids, shapes, for_names, verify, expected, named);
    }
    return checked(run, part, ids, shapes, for_names, verify, expected, named);
  }

  // The cheap checks (and verify_solid when asked) of one boolean run.
  Attempt checked(const BooleanRun& run, const brep::NamedShape& part, const std::vector<int>& ids,
                  const std::vector<TopoDS_Shape>& shapes, const std::vector<int>& for_names, bool verify,
                  const std::vector<double>* expected, const std::vector<const brep::NamedShape*>* named) {
    Attempt a;
    if (run.result.IsNull() || !run.errors.empty()) {
      a.failure = "OCCT boolean failed (" + join(run.errors) + ")";
      return a;
    }
    if (!run.warnings.empty()) {
      // Attributable when every warning names a shape inside the box of one of the tools.
      a.suspects = tools_near(run.warning_shapes, ids, shapes);
      if (a.suspects.empty()) a.failure = "OCCT boolean warned (" + join(run.warnings) + ")";
      else a.warning = "OCCT boolean warned (" + join(run.warnings) + ")";
      return a;
    }
    auto t = Clock::now();
    std::vector<const brep::NamedShape*> tool_names;
    if (named) tool_names = *named;
    else
      for (int id : for_names) tool_names.push_back(&units[static_cast<std::size_t>(id)].shape);
    NamingResult naming = name_result(run, part, tool_names);
    a.result = std::move(naming.shape);
    const int solids = count_solids(run.result);
    if (naming.unnamed > 0) a.failure = std::to_string(naming.unnamed) + " result faces without a history";
    else if (solids != opt_.expected_solids)
      a.failure = std::to_string(solids) + " solids instead of " + std::to_string(opt_.expected_solids);
    const VolumeMeasure vm = measure_tool_volumes(run, part.shape, shapes, op_, opt_.parallel);
    report_.seconds_measure += since(t);
    if (a.failure.empty() && vm.lost_pieces > 0)
      a.failure = std::to_string(vm.lost_pieces) + " pieces of the part (" + format_number(vm.lost_area) +
                  " mm^2) dropped outside every tool";
    if (a.failure.empty() && vm.ambiguous_pieces > 0)
      a.failure = std::to_string(vm.ambiguous_pieces) + " dropped pieces inside more than one tool";
    a.volumes = vm.tools;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const double e = expected ? (*expected)[k] : units[static_cast<std::size_t>(ids[k])].expected;
      if (!volume_ok(vm.tools[k].volume, e, vm.tools[k]) || injected_volume_failure(units[static_cast<std::size_t>(ids[k])].label))
        a.suspects.push_back(ids[k]);
    }
    if (!a.ok() || !verify) return a;
    t = Clock::now();
    brep::VerifyOptions vo = opt_.verify;
    vo.progress = opt_.progress;
    a.check = brep::verify_solid(run.result, vo);
    a.verified = true;
    report_.seconds_verify += since(t);
    // verify_solid asks for one solid; a step expecting several checks the count itself.
    a.check.one_solid.passed = solids == opt_.expected_solids;
    if (!a.check.all_passed()) a.failure = "checks failed: " + a.check.failed_names();
    return a;
  }

  brep::NamedShape accept(Attempt& a, const std::vector<int>& ids) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      Unit& u = units[static_cast<std::size_t>(ids[k])];
      u.measured = a.volumes[k].volume;
      u.closure = a.volumes[k].closure;
      u.uncertainty = a.volumes[k].uncertainty;
      u.passed = true;
    }
    if (a.verified) report_.check = a.check;
    return std::move(a.result);
  }

  void note(const Attempt& a, const std::vector<int>& ids) {
    std::string what = a.failure.empty() ? a.warning : a.failure;
    if (a.volumes.empty()) {
      for (int id : a.suspects) what += (what.empty() ? "" : "; ") + std::string("at ") + units[static_cast<std::size_t>(id)].label;
      report_.warnings.push_back("boolean of " + std::to_string(ids.size()) + " tool(s) rejected: " + what);
      return;
    }
    for (int id : a.suspects) {
      const Unit& u = units[static_cast<std::size_t>(id)];
      const auto k = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
      const ValueLimitText t = format_value_limit(a.volumes[k].volume, u.expected, Allowed::near);
      what += (what.empty() ? "" : "; ") + u.label + ": measured " + t.value + " mm^3, expected " + t.limit + " mm^3 (closure " + format_number(a.volumes[k].closure) + ", B-rep uncertainty " + format_number(a.volumes[k].uncertainty) + ")";
    }
    report_.warnings.push_back("boolean of " + std::to_string(ids.size()) + " tool(s) rejected: " + what);
  }

  // Unit `id` failed alone on `part`: perturbed retries; if none passes, the failure is recorded and
  // the part comes back unchanged (apply() throws FeatureFailure naming every failed feature).
  brep::NamedShape retry(const brep::NamedShape& part, int id, const Attempt& first, bool verify) {
    Unit& u = units[static_cast<std::size_t>(id)];
    const std::string first_failure = describe(first, u);
    std::string last = first_failure;
    bool shift_refused = false;
    for (int k = 1; k <= opt_.max_retries; ++k) {
      const Perturbed p = perturb_tool(u.shape, u.axis, k, opt_.perturbation);
      if (!p.same_geometry && opt_.perturbed_retries == PerturbedRetries::SameGeometry) {
        shift_refused = true;  // a shift would move the geometry the user asked for
        report_.warnings.push_back(u.label + ": retry " + std::to_string(k) + " (" + p.what + ") not tried: booleans.allow_perturbation is false");
        continue;
      }
      // A shift changes the volume a little: the independent expectation moves by the change OCCT
      // measures (Common before and after the shift), so a wrong expectation stays wrong.
      double expected = u.expected;
      if (!p.same_geometry) {
        try {
          expected += occt_expected_volume(p.shape.shape, part.shape, op_, u.label) -
                      occt_expected_volume(u.shape.shape, part.shape, op_, u.label);
        } catch (const FeatureFailure& e) {
          last = e.what();
          report_.warnings.push_back(u.label + ": retry " + std::to_string(k) + " (" + p.what + ") skipped: " + last);
          continue;
        }
      }
      const std::vector<double> e{expected};
      const std::vector<const brep::NamedShape*> named{&p.shape};
      Attempt a = attempt(part, {id}, {p.shape.shape}, {id}, verify, &e, &named);
      ++u.retries;
      if (a.ok()) {
        u.perturbation = p.what;
        u.perturbation_changed_geometry = !p.same_geometry;
        u.expected = expected;
        report_.warnings.push_back(u.label + ": accepted after retry " + std::to_string(k) + " (" + p.what + ")");
        return accept(a, {id});
      }
      last = describe(a, u, expected) + " after " + p.what;
      report_.warnings.push_back(u.label + ": retry " + std::to_string(k) + " (" + p.what + ") rejected: " + last);
    }
    failures.push_back("feature " + u.label + " could not be applied correctly (" + first_failure +
                       (last != first_failure ? "; last retry: " + last : std::string()) + "; " +
                       (shift_refused ? std::string("no shifted retry: booleans.allow_perturbation is false; set it true to let it be moved by ") +
                                            format_number(opt_.perturbation) + " mm"
                                      : std::to_string(opt_.max_retries) + " perturbed retries failed") +
                       ")");
    return part;
  }

  std::string describe(const Attempt& a, const Unit& u, double expected = std::numeric_limits<double>::quiet_NaN()) const {
    if (!a.failure.empty()) return a.failure;
    if (!a.warning.empty()) return a.warning;
    if (std::isnan(expected)) expected = u.expected;
    const std::string verb = op_ == BooleanOperation::Cut ? "removed " : "added ";
    const ValueLimitText t = format_value_limit(a.volumes.empty() ? 0 : a.volumes.front().volume, expected, Allowed::near);
    return verb + t.value + " mm^3 instead of " + t.limit + " mm^3 (closure " + format_number(a.volumes.empty() ? 0 : a.volumes.front().closure) + " mm^3)";
  }

  // Units among `ids` whose (slightly enlarged) box contains each shape; empty when some shape is null
  // or lies in no unit's box (then the warning cannot be pinned on a tool).
  static std::vector<int> tools_near(const std::vector<TopoDS_Shape>& found, const std::vector<int>& ids,
                                     const std::vector<TopoDS_Shape>& shapes) {
    std::vector<int> near;
    std::vector<Bnd_Box> boxes(shapes.size());
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      BRepBndLib::Add(shapes[k], boxes[k], false);
      boxes[k].Enlarge(1e-3);
    }
    for (const TopoDS_Shape& f : found) {
      if (f.IsNull()) return {};
      Bnd_Box fb;
      BRepBndLib::Add(f, fb, false);
      bool located = false;
      for (std::size_t k = 0; k < shapes.size(); ++k) {
        double c[6];
        fb.Get(c[0], c[1], c[2], c[3], c[4], c[5]);
        if (boxes[k].IsOut(gp_Pnt(c[0], c[1], c[2])) || boxes[k].IsOut(gp_Pnt(c[3], c[4], c[5]))) continue;
        located = true;
        if (std::find(near.begin(), near.end(), ids[k]) == near.end()) near.push_back(ids[k]);
      }
      if (!located) return {};
    }
    return near;
  }

  void sort_spatially(std::vector<int>& ids) const {
    std::vector<gp_Pnt> c(units.size());
    Bnd_Box all;
    for (int id : ids) {
      Bnd_Box b;
      BRepBndLib::Add(units[static_cast<std::size_t>(id)].shape.shape, b, false);
      double x[6];
      b.Get(x[0], x[1], x[2], x[3], x[4], x[5]);
      c[static_cast<std::size_t>(id)] = gp_Pnt(0.5 * (x[0] + x[3]), 0.5 * (x[1] + x[4]), 0.5 * (x[2] + x[5]));
      all.Add(b);
    }
    double x[6];
    all.Get(x[0], x[1], x[2], x[3], x[4], x[5]);
    const int axis = (x[3] - x[0] >= x[4] - x[1] && x[3] - x[0] >= x[5] - x[2]) ? 1 : (x[4] - x[1] >= x[5] - x[2] ? 2 : 3);
    std::sort(ids.begin(), ids.end(), [&](int a, int b) {
      return c[static_cast<std::size_t>(a)].Coord(axis) < c[static_cast<std::size_t>(b)].Coord(axis);
    });
  }

  static std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  }

  BooleanOperation op_;
  const BooleanOptions& opt_;
  BooleanStepReport& report_;
  bool prune_;
};

// 1. Disjoint tools: fuse clusters of overlapping ones. The engine's units, one per cluster; the
// cluster of each tool (-1: alone).
std::vector<int> disjoint_units(const std::vector<FeatureTool>& tools, const BooleanOptions& options,
                                BooleanStepReport& report, Engine& engine) {
  ProgressSink* const progress = options.progress;
  std::vector<TopoDS_Shape> shapes;
  for (const FeatureTool& ft : tools) shapes.push_back(ft.shape.shape);
  const OverlapClusters oc = overlap_clusters(shapes, options.overlap_gap, options.parallel);
  std::vector<int> cluster_of(tools.size(), -1);
  for (const std::vector<int>& members : oc.clusters) {
    Unit u;
    u.members = members;
    std::vector<const brep::NamedShape*> named;
    for (int m : members) {
      u.label += (u.label.empty() ? "" : " + ") + tools[static_cast<std::size_t>(m)].feature;
      named.push_back(&tools[static_cast<std::size_t>(m)].shape);
    }
    if (members.size() == 1) {
      const FeatureTool& ft = tools[static_cast<std::size_t>(members.front())];
      u.shape = ft.shape;
      u.axis = ft.symmetry_axis ? ft.symmetry_axis : detect_symmetry_axis(ft.shape.shape);
      u.expected = ft.expected_volume;
      u.expected_source = "given";
    } else {
      check_cancel(progress, "fusing overlapping tools");
      u.shape = fuse_cluster(named, u.label, options.parallel);
      for (int m : members) cluster_of[static_cast<std::size_t>(m)] = report.cluster_count;
      ++report.cluster_count;
    }
    engine.units.push_back(std::move(u));
  }
  return cluster_of;
}

// 2. Independent expectations where the features gave none (and of every fused cluster).
void expect_volumes(Engine& engine, const brep::NamedShape& part, BooleanOperation operation, const BooleanOptions& options) {
  std::vector<int> missing;
  for (std::size_t k = 0; k < engine.units.size(); ++k)
    if (std::isnan(engine.units[k].expected) || engine.units[k].members.size() > 1) missing.push_back(static_cast<int>(k));
  std::vector<std::string> errors(missing.size());
  OSD_Parallel::For(0, static_cast<int>(missing.size()), [&](int k) {
    Unit& u = engine.units[static_cast<std::size_t>(missing[static_cast<std::size_t>(k)])];
    try {
      u.expected = occt_expected_volume(u.shape.shape, part.shape, operation, u.label);
      u.expected_source = "occt";
    } catch (const FeatureFailure& e) {
      errors[static_cast<std::size_t>(k)] = e.what();
    }
  }, !options.parallel);
  for (const std::string& e : errors)
    if (!e.empty()) throw FeatureFailure(e);
}

// 3. Patches, when many tools reach one face: the part the booleans work on.
brep::NamedShape patched_part(const brep::NamedShape& part, const Engine& engine, const BooleanOptions& options,
                              BooleanStepReport& report) {
  ProgressSink* const progress = options.progress;
  brep::NamedShape base = part;
  if (options.patch_min_tools > 0 && static_cast<int>(engine.units.size()) >= options.patch_min_tools) {
    report_progress(progress, 0.15, "patches");
    check_cancel(progress, "patches");
    std::vector<TopoDS_Shape> us;
    for (const Unit& u : engine.units) us.push_back(u.shape.shape);
    PatchOptions po;
    po.min_tools = options.patch_min_tools;
    po.tools_per_patch = options.patch_tools_per_patch;
    po.parallel = options.parallel;
    PatchedPart pp = patch_faces(part, us, po);
    for (const std::string& w : pp.warnings) report.warnings.push_back("patches: " + w);
    if (pp.cut_lines > 0) {
      // A patch split is kept only when clean: otherwise the step works on the part as it is.
      const bool clean = pp.warnings.empty() && count_solids(pp.part.shape) == count_solids(part.shape);
      if (clean) {
        base = std::move(pp.part);
        report.patched_faces = pp.faces_after - pp.faces_before;
      } else {
        report.warnings.push_back("patches: the split was not clean, the part is used unsplit");
      }
    }
  }
  return base;
}

// 5. Report (also when the step fails), one entry per tool in the order they were added.
void report_tools(const Engine& engine, const std::vector<FeatureTool>& tools, const std::vector<int>& cluster_of,
                  BooleanStepReport& report) {
  report.tools.assign(tools.size(), ToolReport{});
  for (const Unit& u : engine.units)
    for (int m : u.members) {
      ToolReport tr;
      tr.feature = tools[static_cast<std::size_t>(m)].feature;
      tr.expected_volume = u.expected;
      tr.measured_volume = u.measured;
      tr.closure = u.closure;
      tr.uncertainty = u.uncertainty;
      tr.expected_source = u.expected_source;
      tr.cluster = cluster_of[static_cast<std::size_t>(m)];
      tr.retries = u.retries;
      tr.perturbation = u.perturbation;
      tr.perturbation_changed_geometry = u.perturbation_changed_geometry;
      tr.passed = u.passed;
      report.tools[static_cast<std::size_t>(m)] = tr;
    }
}

}  // namespace

BooleanStep::BooleanStep(BooleanOperation operation, BooleanOptions options)
    : operation_(operation), options_(std::move(options)) {
  require(options_.volume_rel_tolerance >= 0 && options_.volume_abs_tolerance >= 0,
          "boolean step: volume tolerances must be >= 0");
  require(options_.expected_solids >= 1, "boolean step: expected_solids must be >= 1");
  require(options_.max_retries >= 0 && options_.perturbation > 0, "boolean step: max_retries >= 0, perturbation > 0");
  require(options_.overlap_gap >= 0, "boolean step: overlap_gap must be >= 0");
}

void BooleanStep::add(FeatureTool tool) {
  require(!tool.shape.shape.IsNull() && count_solids(tool.shape.shape) >= 1,
          "boolean step: tool '" + tool.feature + "' is not a solid");
  tools_.push_back(std::move(tool));
}

brep::NamedShape BooleanStep::apply(const brep::NamedShape& part) {
  require(!part.shape.IsNull() && count_solids(part.shape) >= 1, "boolean step: the part is not a solid");
  require(!done_, "boolean step: apply() runs once");
  const auto t0 = Clock::now();
  report_ = BooleanStepReport{};
  report_.operation = operation_;
  report_.tool_count = static_cast<int>(tools_.size());
  Engine engine(operation_, options_, report_);
  ProgressSink* const progress = options_.progress;

  // 1. Disjoint tools: fuse clusters of overlapping ones.
  auto t = Clock::now();
  report_progress(progress, 0.0, "disjoint tools");
  const std::vector<int> cluster_of = disjoint_units(tools_, options_, report_, engine);
  report_.seconds_disjoint = since(t);

  // 2. Independent expectations where the features gave none (and of every fused cluster).
  t = Clock::now();
  report_progress(progress, 0.1, "expected volumes");
  check_cancel(progress, "expected volumes");
  expect_volumes(engine, part, operation_, options_);
  report_.seconds_expected = since(t);

  for (Unit& u : engine.units) u.expected_before_retries = u.expected;

  // 3. Patches, when many tools reach one face.
  t = Clock::now();
  const brep::NamedShape base = patched_part(part, engine, options_, report_);
  report_.seconds_patches = since(t);

  // 4. The boolean(s), checked; guilty tools isolated and retried.
  report_progress(progress, 0.2, "boolean");
  std::vector<int> all(engine.units.size());
  std::iota(all.begin(), all.end(), 0);
  // Cheap checks on every boolean, verify_solid once on the final result; only if that fails are the
  // booleans redone with verify_solid on each of them, to find the tool to blame.
  brep::NamedShape result = engine.apply_group(base, all, /*verify=*/false);
  std::string failure;
  if (options_.verification == Verification::EachStep && engine.failures.empty()) {
    report_progress(progress, 0.9, "verify");
    if (!engine.verify_final(result)) {
      report_.warnings.push_back("the result failed " + report_.check.failed_names() +
                                 ": booleans redone with verify_solid on each");
      engine.reset_outcomes();
      engine.stop_pruning();
      result = engine.apply_group(base, all, /*verify=*/true);
      if (engine.failures.empty() && !engine.verify_final(result))
        failure = "the result of the step failed " + report_.check.failed_names() + " although every tool passed alone";
    }
  }
  for (const std::string& f : engine.failures) failure += (failure.empty() ? "" : "; ") + f;

  // 5. Report (also when the step fails), one entry per tool in the order they were added.
  report_tools(engine, tools_, cluster_of, report_);
  report_.seconds = since(t0);
  if (!failure.empty()) throw FeatureFailure(failure);
  report_progress(progress, 1.0, "done");
  done_ = true;
  return result;
}

void append_perturbed_tools(const BooleanStepReport& report, std::vector<PerturbedTool>& out) {
  for (const ToolReport& t : report.tools)
    if (!t.perturbation.empty()) out.push_back({t.feature, t.perturbation, t.perturbation_changed_geometry});
}

}  // namespace cg::features
