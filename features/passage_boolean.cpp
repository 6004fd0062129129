#include "features/passage_boolean.hpp"

#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <chrono>
#include <memory>
#include <cmath>

#include "features/face_names.hpp"

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
                                     bool verify_result) {
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
    BRepClass3d_SolidClassifier in_part;
    in_part.Load(solids.front());
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
    for (const FeatureTool& t : interior) {
      const std::vector<TopoDS_Shape> ts = solids_of(t.shape.shape);
      if (ts.size() != 1) throw FeatureFailure(t.feature + ": an interior tool must be one solid");
      TopExp_Explorer tool_shell(ts.front(), TopAbs_SHELL);
      const auto pdw = distance(wall, tool_shell.Current()), pde = distance(ends, tool_shell.Current());
      const BRepExtrema_DistShapeShape &dw = *pdw, &de = *pde;
      if (!dw.IsDone() || !de.IsDone())
        throw FeatureFailure(t.feature + ": cannot measure its distance to the blade's boundary");
      const double d = std::min(dw.Value(), de.Value());
      TopExp_Explorer v(ts.front(), TopAbs_VERTEX);
      in_part.Perform(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())), 1e-7);
      if (d <= 1e-6 || in_part.State() != TopAbs_IN)
        throw FeatureFailure(t.feature + ": not strictly inside the blade (distance to its boundary " +
                             std::to_string(d) + " mm)");
      report.min_clearance = std::min(report.min_clearance, d);
      report.wall_clearance = std::min(report.wall_clearance, dw.Value());
      for (TopExp_Explorer e(ts.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(result, e.Current().Reversed());
      // The removed volume is the integral over the inserted (reversed) faces: with the tool's own volume
      // this checks the void's orientation.
      TopoDS_Compound inserted;
      bb.MakeCompound(inserted);
      for (TopExp_Explorer e(ts.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(inserted, e.Current().Reversed());
      const double removed = -volume_of(inserted);
      const BooleanOptions opt;
      const bool ok = std::abs(removed - t.expected_volume) <= opt.volume_rel_tolerance * t.expected_volume + opt.volume_abs_tolerance;
      ToolReport tr;
      tr.feature = t.feature;
      tr.expected_volume = t.expected_volume;
      tr.measured_volume = removed;
      tr.expected_source = "given";
      tr.passed = ok;
      report.voids.push_back(tr);
      if (!ok)
        throw FeatureFailure(t.feature + ": as a void it removes " + std::to_string(removed) + " mm^3, expected " +
                             std::to_string(t.expected_volume) + " mm^3");
    }
    current.shape = result;
    for (const FeatureTool& t : interior)
      current.faces.insert(current.faces.end(), t.shape.faces.begin(), t.shape.faces.end());
    FaceNames names(current.faces);
    current.faces = names.list(result, "blade with chambers");
    report.void_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (cuts.empty()) {
    if (!verify_result) return current;
    // No boolean follows: check the blade with its voids here (otherwise the cut checks the result).
    report.cut.check = brep::verify_solid(current.shape);
    if (!report.cut.check.all_passed())
      throw FeatureFailure("the blade with its chambers fails " + report.cut.check.failed_names());
    return current;
  }
  BooleanOptions options;
  options.verify_result = verify_result;
  return cut_passage_tools(current, cuts, report.cut, options);
}

}  // namespace cg::features
