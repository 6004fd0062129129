#include "features/passage_boolean.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>
#include <Message_Alert.hxx>
#include <Message_Report.hxx>
#include <TopTools_ListOfShape.hxx>

#include <chrono>
#include <cmath>
#include <numeric>

#include "features/face_names.hpp"

namespace cg::features {
namespace {

std::string alerts(const BRepAlgoAPI_BooleanOperation& op, Message_Gravity g) {
  std::string s;
  for (const Handle(Message_Alert)& a : op.GetReport()->GetAlerts(g)) s += (s.empty() ? "" : ", ") + std::string(a->GetMessageKey());
  return s;
}

Bnd_Box box_of(const TopoDS_Shape& s) {
  Bnd_Box b;
  BRepBndLib::Add(s, b);
  return b;
}

}  // namespace

double volume_difference(const TopoDS_Shape& before, const TopoDS_Shape& after) {
  TopTools_IndexedMapOfShape fb, fa;
  TopExp::MapShapes(before, TopAbs_FACE, fb);
  TopExp::MapShapes(after, TopAbs_FACE, fa);
  // One compound, one integration: BRepGProp integrates every face of a call towards the same apex
  // (near the compound's centre), so the before-only faces and the reversed after-only faces sum to
  // the difference; separate calls would use different apexes.
  BRep_Builder bb;
  TopoDS_Compound c;
  bb.MakeCompound(c);
  for (TopExp_Explorer e(before, TopAbs_FACE); e.More(); e.Next())
    if (!fa.Contains(e.Current())) bb.Add(c, e.Current());
  for (TopExp_Explorer e(after, TopAbs_FACE); e.More(); e.Next())
    if (!fb.Contains(e.Current())) bb.Add(c, e.Current().Reversed());
  GProp_GProps p;
  BRepGProp::VolumeProperties(c, p, 1e-9);
  return p.Mass();
}

std::vector<FeatureTool> fuse_overlapping_tools(const std::vector<FeatureTool>& tools) {
  const int n = static_cast<int>(tools.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)];
    return a;
  };
  std::vector<Bnd_Box> boxes;
  for (const auto& t : tools) boxes.push_back(box_of(t.shape.shape));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (boxes[static_cast<std::size_t>(i)].IsOut(boxes[static_cast<std::size_t>(j)])) continue;
      BRepExtrema_DistShapeShape d(tools[static_cast<std::size_t>(i)].shape.shape, tools[static_cast<std::size_t>(j)].shape.shape);
      if (d.IsDone() && d.Value() <= 1e-7) parent[static_cast<std::size_t>(find(i))] = find(j);
    }
  std::vector<FeatureTool> out;
  std::vector<std::vector<int>> groups(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) groups[static_cast<std::size_t>(find(i))].push_back(i);
  for (const auto& g : groups) {
    if (g.empty()) continue;
    if (g.size() == 1) {
      out.push_back(tools[static_cast<std::size_t>(g[0])]);
      continue;
    }
    FeatureTool cluster = tools[static_cast<std::size_t>(g[0])];
    FaceNames names(cluster.shape.faces);
    for (std::size_t k = 1; k < g.size(); ++k) {
      const FeatureTool& t = tools[static_cast<std::size_t>(g[k])];
      names.add(t.shape.faces);
      BRepAlgoAPI_Fuse fuse(cluster.shape.shape, t.shape.shape);
      if (!fuse.IsDone() || fuse.HasErrors() || fuse.HasWarnings())
        throw FeatureFailure("fusing the overlapping tools " + cluster.feature + " and " + t.feature + " failed: " +
                             alerts(fuse, Message_Fail) + " " + alerts(fuse, Message_Warning));
      const TopoDS_Shape r = fuse.Shape();
      if (solids_of(r).size() != 1) throw FeatureFailure("fusing " + cluster.feature + " and " + t.feature + " gave " + std::to_string(solids_of(r).size()) + " solids");
      names = names.carried(fuse, r);
      cluster.feature += "+" + t.feature;
      cluster.shape.shape = r;
      cluster.expected_volume = std::numeric_limits<double>::quiet_NaN();
    }
    cluster.shape.faces = names.list(cluster.shape.shape, cluster.feature);
    out.push_back(cluster);
  }
  return out;
}

brep::NamedShape cut_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& tools_in,
                                   BooleanStepReport& report, const BooleanOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  report = BooleanStepReport{};
  report.operation = BooleanOperation::Cut;
  report.tool_count = static_cast<int>(tools_in.size());
  const std::vector<FeatureTool> tools = fuse_overlapping_tools(tools_in);
  report.cluster_count = static_cast<int>(tools_in.size() - tools.size());

  FaceNames names(part.faces);
  TopTools_ListOfShape args, tool_shapes;
  args.Append(part.shape);
  double expected_total = 0;
  for (const auto& t : tools) {
    names.add(t.shape.faces);
    tool_shapes.Append(t.shape.shape);
    ToolReport tr;
    tr.feature = t.feature;
    if (std::isnan(t.expected_volume)) {
      BRepAlgoAPI_Common c(t.shape.shape, part.shape);
      if (!c.IsDone() || c.HasErrors()) throw FeatureFailure(t.feature + ": cannot compute its expected volume (Common failed)");
      tr.expected_volume = volume_of(c.Shape());
    } else {
      tr.expected_volume = t.expected_volume;
    }
    expected_total += tr.expected_volume;
    report.tools.push_back(tr);
  }
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tool_shapes);
  cut.SetRunParallel(options.parallel);
  cut.Build();
  std::string feats;
  for (const auto& t : tools) feats += (feats.empty() ? "" : ", ") + t.feature;
  if (!cut.IsDone() || cut.HasErrors())
    throw FeatureFailure("cutting " + feats + " from the blade failed: " + alerts(cut, Message_Fail));
  if (cut.HasWarnings())
    throw FeatureFailure("cutting " + feats + " from the blade raised BOPAlgo warnings (" + alerts(cut, Message_Warning) +
                         "), which came with wrong results in our measurements");
  brep::NamedShape out;
  out.shape = cut.Shape();
  out.faces = names.carried(cut, out.shape).list(out.shape, "cut of " + feats);
  report.check = brep::verify_solid(out.shape);
  if (!report.check.all_passed())
    throw FeatureFailure("after cutting " + feats + " the solid fails " + report.check.failed_names());
  const double removed = volume_difference(part.shape, out.shape);
  const double tol = options.volume_rel_tolerance * std::abs(expected_total) + options.volume_abs_tolerance * tools.size();
  // The interim path measures the total; per tool it records the share of the measured total.
  for (auto& tr : report.tools) {
    tr.measured_volume = expected_total > 0 ? removed * tr.expected_volume / expected_total : 0;
    tr.passed = std::abs(removed - expected_total) <= tol;
  }
  if (std::abs(removed - expected_total) > tol)
    throw FeatureFailure("cutting " + feats + " removed " + std::to_string(removed) + " mm^3, expected " +
                         std::to_string(expected_total) + " mm^3");
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

brep::NamedShape apply_passage_tools(const brep::NamedShape& part, const std::vector<FeatureTool>& interior,
                                     const std::vector<FeatureTool>& cuts, PassageBooleanReport& report) {
  const auto t0 = std::chrono::steady_clock::now();
  report = PassageBooleanReport{};
  brep::NamedShape current = part;
  if (!interior.empty()) {
    const std::vector<TopoDS_Shape> solids = solids_of(part.shape);
    if (solids.size() != 1) throw FeatureFailure("inserting chambers: the blade must be one solid");
    report.min_clearance = HUGE_VAL;
    BRep_Builder bb;
    TopoDS_Solid result;
    bb.MakeSolid(result);
    for (TopExp_Explorer e(solids.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(result, e.Current());
    BRepClass3d_SolidClassifier in_part;
    in_part.Load(solids.front());
    for (const FeatureTool& t : interior) {
      const std::vector<TopoDS_Shape> ts = solids_of(t.shape.shape);
      if (ts.size() != 1) throw FeatureFailure(t.feature + ": an interior tool must be one solid");
      // Between the boundaries (shells): between solids BRepExtrema reports 0 for a solid inside another.
      TopExp_Explorer part_shell(solids.front(), TopAbs_SHELL), tool_shell(ts.front(), TopAbs_SHELL);
      BRepExtrema_DistShapeShape d(part_shell.Current(), tool_shell.Current());
      if (!d.IsDone()) throw FeatureFailure(t.feature + ": cannot measure its distance to the blade's boundary");
      TopExp_Explorer v(ts.front(), TopAbs_VERTEX);
      in_part.Perform(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())), 1e-7);
      if (d.Value() <= 1e-6 || in_part.State() != TopAbs_IN)
        throw FeatureFailure(t.feature + ": not strictly inside the blade (distance to its boundary " +
                             std::to_string(d.Value()) + " mm)");
      report.min_clearance = std::min(report.min_clearance, d.Value());
      for (TopExp_Explorer e(ts.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(result, e.Current().Reversed());
      // The removed volume is the integral over the inserted (reversed) faces: with the tool's own volume
      // this checks the void's orientation.
      TopoDS_Compound inserted;
      bb.MakeCompound(inserted);
      for (TopExp_Explorer e(ts.front(), TopAbs_SHELL); e.More(); e.Next()) bb.Add(inserted, e.Current().Reversed());
      const double removed = -volume_of(inserted);
      const BooleanOptions opt;
      const bool ok = std::abs(removed - t.expected_volume) <= opt.volume_rel_tolerance * t.expected_volume + opt.volume_abs_tolerance;
      report.voids.push_back({t.feature, t.expected_volume, removed, 0, ok});
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
    // No boolean follows: check the blade with its voids here (otherwise the cut checks the result).
    report.cut.check = brep::verify_solid(current.shape);
    if (!report.cut.check.all_passed())
      throw FeatureFailure("the blade with its chambers fails " + report.cut.check.failed_names());
    return current;
  }
  return cut_passage_tools(current, cuts, report.cut);
}

}  // namespace cg::features
