#include "features/passages/passage_boolean.hpp"

#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "src/brep/naming/face_names.hpp"
#include "src/core/parallel.hpp"
#include "src/core/format.hpp"

namespace cg::features {
brep::NamedShape cut_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& tools,
                                   BooleanStepReport& report, const BooleanOptions& options) {
  BooleanStep step(BooleanOperation::Cut, options);
  for (const FeatureTool& t : tools) step.add(t);
  brep::NamedShape out = step.apply(part);
  report = step.report();
  return out;
}

brep::NamedShape apply_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& interior,
                                     const std::vector<FeatureTool>& cuts, PassageBooleanReport& report,
                                     Verification verification, PerturbedRetries retries) {
  const auto t0 = std::chrono::steady_clock::now();
  report = PassageBooleanReport{};
  brep::NamedShape current = part;
  if (!interior.empty()) {
    const std::vector<TopoDS_Shape> solids = solids_of(part.shape);
    if (solids.size() != 1) throw FeatureFailure("inserting chambers: the blade must be one solid");
    report.min_clearance = report.wall_clearance = HUGE_VAL;
    BRep_Builder bb;
    TopoDS_Solid result;
    bb.MakeSolid(result);
    for (TopExp_Explorer e(solids.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(result, e.Current());
    // Distance between the boundaries (faces: between solids BRepExtrema reports 0 for a solid inside
    // another), from the outer wall and from the other faces of the part separately: the first is the
    // outer wall's minimum thickness the design checks report. (BRepExtrema's multi-threaded mode: the
    // face pairs on both cores.)
    TopoDS_Compound wall, ends;
    bb.MakeCompound(wall);
    bb.MakeCompound(ends);
    for (const brep::NamedFace& f : part.faces) bb.Add(f.name == "blade_wall" ? wall : ends, f.face);
    auto distance = [](const TopoDS_Shape& a, const TopoDS_Shape& b) {
      auto d = std::make_unique<BRepExtrema_DistShapeShape>();
      d->SetMultiThread(true);
      d->LoadS1(a);
      d->LoadS2(b);
      d->Perform();
      return d;
    };
    // The tools' measurements are independent: side by side (each worker its own classifier), then
    // judged in the tools' order so the error named does not depend on the scheduling.
    struct Measured {
      TopoDS_Shape solid;
      double wall = 0, ends = 0, removed = 0;  // written by different work items
      bool wall_done = false, ends_done = false, inside = false;
    };
    std::vector<Measured> m(interior.size());
    for (std::size_t i = 0; i < interior.size(); ++i) {
      const std::vector<TopoDS_Shape> ts = solids_of(interior[i].shape.shape);
      if (ts.size() != 1) throw FeatureFailure(interior[i].feature + ": an interior tool must be one solid");
      m[i].solid = ts.front();
    }
    const int items = 3 * static_cast<int>(interior.size());
    const int workers = std::min(parallel_workers(), items);
    std::vector<BRepClass3d_SolidClassifier> in_part(static_cast<std::size_t>(workers));
    for (BRepClass3d_SolidClassifier& c : in_part) c.Load(solids.front());
    // Three items per tool (its distance to the outer wall, to the other faces, its void's volume and
    // inside test): the big chamber system's distances would otherwise keep one core busy alone.
    parallel_for(items, workers, [&](int k, int w) {
      Measured& r = m[static_cast<std::size_t>(k / 3)];
      TopExp_Explorer tool_shell(r.solid, TopAbs_SHELL);
      if (k % 3 < 2) {
        const auto d = distance(k % 3 == 0 ? wall : ends, tool_shell.Current());
        (k % 3 == 0 ? r.wall_done : r.ends_done) = d->IsDone();
        if (d->IsDone()) (k % 3 == 0 ? r.wall : r.ends) = d->Value();
        return;
      }
      TopExp_Explorer v(r.solid, TopAbs_VERTEX);
      BRepClass3d_SolidClassifier& c = in_part[static_cast<std::size_t>(w)];
      c.Perform(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())), 1e-7);
      r.inside = c.State() == TopAbs_IN;
      // The removed volume is the integral over the inserted (reversed) faces: with the tool's own volume
      // this checks the void's orientation.
      BRep_Builder lb;
      TopoDS_Compound inserted;
      lb.MakeCompound(inserted);
      for (TopExp_Explorer e(r.solid, TopAbs_SHELL); e.More(); e.Next()) lb.Add(inserted, e.Current().Reversed());
      r.removed = -volume_of(inserted);
    });
    for (std::size_t i = 0; i < interior.size(); ++i) {
      const FeatureTool& t = interior[i];
      const Measured& r = m[i];
      if (!r.wall_done || !r.ends_done) throw FeatureFailure(t.feature + ": cannot measure its distance to the blade's boundary");
      const double d = std::min(r.wall, r.ends);
      if (d <= 1e-6 || !r.inside)
        throw FeatureFailure(t.feature + ": not strictly inside the blade (distance to its boundary " +
                             format_number(d) + " mm)");
      report.min_clearance = std::min(report.min_clearance, d);
      report.wall_clearance = std::min(report.wall_clearance, r.wall);
      for (TopExp_Explorer e(r.solid, TopAbs_SHELL); e.More(); e.Next()) bb.Add(result, e.Current().Reversed());
      const BooleanOptions opt;
      const bool ok =
          std::abs(r.removed - t.expected_volume) <= opt.volume_rel_tolerance * t.expected_volume + opt.volume_abs_tolerance;
      ToolReport tr;
      tr.feature = t.feature;
      tr.expected_volume = t.expected_volume;
      tr.measured_volume = r.removed;
      tr.expected_source = "given";
      tr.passed = ok;
      report.voids.push_back(tr);
      if (!ok)
        throw FeatureFailure(t.feature + ": as a void it removes " + format_value_limit(r.removed, t.expected_volume, Allowed::near).value +
                             " mm^3, expected " + format_value_limit(r.removed, t.expected_volume, Allowed::near).limit + " mm^3");
    }
    current.shape = result;
    for (const FeatureTool& t : interior)
      current.faces.insert(current.faces.end(), t.shape.faces.begin(), t.shape.faces.end());
    FaceNames names(current.faces);
    current.faces = names.list(result, "blade with chambers");
    report.void_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (cuts.empty()) {
    if (verification != Verification::EachStep) return current;
    // No boolean follows: check the blade with its voids here (otherwise the cut checks the result).
    report.cut.check = brep::verify_solid(current.shape);
    if (!report.cut.check.all_passed())
      throw FeatureFailure("the blade with its chambers fails " + report.cut.check.failed_names());
    return current;
  }
  BooleanOptions options;
  options.verification = verification;
  options.perturbed_retries = retries;
  return cut_passage_tools(current, cuts, report.cut, options);
}

}  // namespace cg::features
