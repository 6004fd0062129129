#include "src/brep/boolean/boolean_run.hpp"

#include <BOPAlgo_BOP.hxx>
#include <BOPAlgo_PaveFiller.hxx>
#include <Message_ProgressScope.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_AlertWithShape.hxx>

#include <chrono>

#include "src/brep/boolean/boolean_alerts.hpp"
#include "src/brep/boolean/boolean_pair_pruning.hpp"
#include "src/brep/boolean/verified_boolean.hpp"

namespace cg::features {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void collect(const Handle(Message_Report) & report, BooleanRun& run) {
  for (const std::string& e : alert_names(report, Message_Fail)) run.errors.push_back(e);
  for (const std::string& w : alert_names(report, Message_Warning)) run.warnings.push_back(w);
  if (report.IsNull()) return;
  for (const Handle(Message_Alert)& a : report->GetAlerts(Message_Warning)) {
    const Handle(TopoDS_AlertWithShape) s = Handle(TopoDS_AlertWithShape)::DownCast(a);
    run.warning_shapes.push_back(s.IsNull() ? TopoDS_Shape() : s->GetShape());
  }
}

}  // namespace

BooleanRun run_boolean(const TopoDS_Shape& part, const std::vector<TopoDS_Shape>& tools, BooleanOperation op,
                       bool parallel, bool prune_face_pairs, const Message_ProgressRange& range) {
  BooleanRun run;
  Message_ProgressScope scope(range, "boolean", 10);
  try {
    auto t0 = std::chrono::steady_clock::now();
    TopTools_ListOfShape args;
    args.Append(part);
    for (const TopoDS_Shape& t : tools) args.Append(t);
    PrunedPaveFiller filler(prune_face_pairs);
    filler.SetArguments(args);
    filler.SetRunParallel(parallel);
    filler.SetNonDestructive(true);
    filler.SetUseOBB(true);
    filler.Perform(scope.Next(7));
    run.seconds_intersect = seconds_since(t0);
    run.candidate_face_pairs = filler.candidate_face_pairs();
    run.intersected_face_pairs = filler.kept_face_pairs();
    collect(filler.GetReport(), run);
    if (!scope.More()) {
      run.cancelled = true;
      return run;
    }
    if (filler.HasErrors()) return run;

    t0 = std::chrono::steady_clock::now();
    BOPAlgo_BOP bop;
    bop.AddArgument(part);
    for (const TopoDS_Shape& t : tools) bop.AddTool(t);
    bop.SetOperation(op == BooleanOperation::Cut ? BOPAlgo_CUT : BOPAlgo_FUSE);
    bop.SetRunParallel(parallel);
    bop.SetNonDestructive(true);
    bop.SetCheckInverted(false);  // tools are closed solids with outward normals (checked by the step)
    bop.PerformWithFiller(filler, scope.Next(3));
    run.seconds_build = seconds_since(t0);
    collect(bop.GetReport(), run);
    if (!scope.More()) {
      run.cancelled = true;
      return run;
    }
    if (bop.HasErrors()) return run;
    run.result = bop.Shape();
    run.images = bop.Images();
  } catch (const Standard_Failure& e) {
    run.errors.push_back(std::string("exception: ") + e.GetMessageString());
    run.result.Nullify();
  }
  return run;
}

TopTools_ListOfShape pieces_of(const BooleanRun& run, const TopoDS_Shape& s) {
  if (const TopTools_ListOfShape* im = run.images.Seek(s)) return *im;
  TopTools_ListOfShape self;
  self.Append(s);
  return self;
}

}  // namespace cg::features
