#include "features/drilling/drill_holes.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_Edge.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Wire.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>

#include "adaptors/occt_convert.hpp"
#include "src/brep/face_flux.hpp"
#include "src/brep/face_patches.hpp"
#include "features/drilling/drill_hole_geometry.hpp"
#include "features/drilling/drill_hole_plan.hpp"
#include "features/drilling/drill_hole_topology.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::features {

using namespace drill_detail;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }


// 1/3 * integral over the face of (x - c) . n dA with BRepGProp's fixed Gauss rule (orders from the
// surface's and the edges' degrees and spans; no adaptive refinement: the faces here are small and
// smooth, and the result is compared with the quadrature at 1e-6, which would expose a coarse rule).
double hole_face_flux(const TopoDS_Face& f, const gp_Pnt& c) {
  BRepGProp_Face bf(f);
  BRepGProp_Domain bd(f);
  BRepGProp_Vinert g;
  g.SetLocation(c);
  g.Perform(bf, bd);
  return g.Mass();
}

// The same integral by our adaptive face flux (src/brep/face_flux.hpp) at 1e-9 of its scale.
double face_flux(const TopoDS_Shape& f, const gp_Pnt& c) { return brep::face_volume_flux(TopoDS::Face(f), c, 1e-9).value; }

bool no_error(const BRepCheck_ListOfStatus& l) {
  for (const BRepCheck_Status st : l)
    if (st != BRepCheck_NoError) return false;
  return true;
}

// BRepCheck's checks of one inner wire and its edge in the context of its wall: 2D closure,
// orientation, self-intersection, the edge's pcurve on the wall. They run on a face of the wall's
// surface that holds only this wire: in the rebuilt wall each of them would first walk every edge of
// the face (BRepTools_WireExplorer's parameter bounds), O(holes) per hole. What BRepCheck_Face adds --
// wires of one face crossing each other or the outer wire -- is what plan_hole's margin checks exclude.
bool inner_wire_valid(const TopoDS_Wire& w, const TopoDS_Edge& e, const TopoDS_Face& wall) {
  BRep_Builder b;
  TopLoc_Location loc;
  const Handle(Geom_Surface) s = BRep_Tool::Surface(wall, loc);
  TopoDS_Face face;
  b.MakeFace(face, s, loc, BRep_Tool::Tolerance(wall));
  b.Add(face, w);
  BRepCheck_Wire bw(w);
  TopoDS_Edge e1, e2;
  if (bw.Closed2d(face) != BRepCheck_NoError) return false;
  if (bw.Orientation(face) != BRepCheck_NoError) return false;
  if (bw.SelfIntersect(face, e1, e2) != BRepCheck_NoError) return false;
  BRepCheck_Edge be(e);
  be.InContext(face);
  return no_error(be.StatusOnShape(face));
}

int count_solids(const TopoDS_Shape& s) {
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_SOLID); e.More(); e.Next()) ++n;
  return n;
}

// Every edge of the solid used exactly twice, once in each direction (closed, consistently oriented
// shells). Returns a description of the first offence, "" when none.
std::string edge_use_failure(const TopoDS_Shape& solid) {
  NCollection_DataMap<TopoDS_Shape, std::pair<int, int>, TopTools_ShapeMapHasher> use;
  for (TopExp_Explorer f(solid, TopAbs_FACE); f.More(); f.Next())
    for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& ed = TopoDS::Edge(e.Current());
      if (BRep_Tool::Degenerated(ed)) continue;
      const TopoDS_Shape key = ed.Oriented(TopAbs_FORWARD);
      if (!use.IsBound(key)) use.Bind(key, {0, 0});
      auto& c = use.ChangeFind(key);
      (ed.Orientation() == TopAbs_FORWARD ? c.first : c.second) += 1;
    }
  int bad = 0;
  for (NCollection_DataMap<TopoDS_Shape, std::pair<int, int>, TopTools_ShapeMapHasher>::Iterator it(use); it.More(); it.Next())
    if (it.Value().first != 1 || it.Value().second != 1) ++bad;
  return bad ? std::to_string(bad) + " edge(s) not used exactly once in each direction" : std::string();
}

// Cuts holes `ids` into `part` through the verified boolean path; their volumes are the step's
// measurements, its report is merged into r.fallback.
brep::NamedShape apply_fallback(const brep::NamedShape& part, const std::vector<std::size_t>& ids,
                                const std::vector<CylindricalHole>& holes, const DrillOptions& o, DrillResult& r);

}  // namespace

std::vector<std::string> drill_fallback_reasons(const brep::NamedShape& part, const std::vector<CylindricalHole>& holes,
                                                const DrillOptions& options) {
  std::vector<HolePlan> plans = initial_plans(holes, options);
  const Part p = index_part(part);
  plan_holes(p, plans, holes, options);
  std::vector<std::string> reasons;
  for (const HolePlan& h : plans) reasons.push_back(h.reason);
  return reasons;
}

namespace {

brep::NamedShape apply_fallback(const brep::NamedShape& part, const std::vector<std::size_t>& ids,
                                const std::vector<CylindricalHole>& holes, const DrillOptions& o, DrillResult& r) {
  BooleanStep step(BooleanOperation::Cut, o.fallback);
  for (std::size_t i : ids) step.add(hole_tool(holes[i]));
  brep::NamedShape result = step.apply(part);
  const BooleanStepReport& s = step.report();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    r.holes[ids[k]].volume = s.tools[k].measured_volume;
    r.holes[ids[k]].uncertainty = s.tools[k].uncertainty;
  }
  BooleanStepReport& f = r.fallback;
  f.tool_count += s.tool_count;
  f.cluster_count += s.cluster_count;
  f.boolean_runs += s.boolean_runs;
  f.tools.insert(f.tools.end(), s.tools.begin(), s.tools.end());
  f.warnings.insert(f.warnings.end(), s.warnings.begin(), s.warnings.end());
  f.check = s.check;
  f.seconds += s.seconds;
  return result;
}

}  // namespace

FeatureTool hole_tool(const CylindricalHole& hole) {
  const HoleCylinder c = HoleCylinder::from_axis(hole.origin, hole.axis, 0.5 * hole.diameter, hole.length);
  const gp_Ax2 ax(occt::to_pnt(c.o), gp_Dir(c.d.x(), c.d.y(), c.d.z()), gp_Dir(c.e1.x(), c.e1.y(), c.e1.z()));
  FeatureTool tool;
  tool.feature = hole.name;
  tool.shape.shape = BRepPrimAPI_MakeCylinder(ax, c.radius, c.length).Shape();
  for (TopExp_Explorer e(tool.shape.shape, TopAbs_FACE); e.More(); e.Next())
    tool.shape.faces.push_back({TopoDS::Face(e.Current()), hole.name});
  tool.symmetry_axis = gp_Ax1(ax.Location(), ax.Direction());
  return tool;
}

namespace {

// 1. Patches: walls that many holes reach are split between them (the part unchanged when that does
// not give one clean solid).
brep::NamedShape patch_walls(const brep::NamedShape& input, const std::vector<HolePlan>& plans, std::size_t hole_count,
                             const DrillOptions& o, DrillResult& r) {
  brep::NamedShape base = input;
  if (o.patch_min_holes > 0 && static_cast<int>(hole_count) >= o.patch_min_holes) {
    std::vector<TopoDS_Shape> tools;
    for (const HolePlan& p : plans)
      tools.push_back(BRepPrimAPI_MakeCylinder(gp_Ax2(occt::to_pnt(p.cyl.o), gp_Dir(p.cyl.d.x(), p.cyl.d.y(), p.cyl.d.z())),
                                               p.cyl.radius, p.cyl.length)
                          .Shape());
    PatchOptions po;
    po.min_tools = o.patch_min_holes;
    po.tools_per_patch = o.patch_holes_per_patch;
    po.parallel = o.parallel;
    PatchedPart pp = patch_faces(input, tools, po);
    if (pp.cut_lines > 0 && pp.warnings.empty() && count_solids(pp.part.shape) == 1) {
      base = std::move(pp.part);
      r.patched_faces = pp.faces_after - pp.faces_before;
    }
  }
  return base;
}

// 2. Geometry of every hole (parallel): faces crossed, loops, preconditions, quadrature volume.
// Holes that fall back are cut first, by the boolean path on the part as it is (its cost grows
// with the faces of the part, and the drilled part has many); the others are then planned again on
// that result. A hole that no longer qualifies there is cut by the boolean path after the drilling.
// `applied` marks the holes cut here; `base` and `part` become the part the others are drilled into.
void plan_all_holes(brep::NamedShape& base, Part& part, std::vector<HolePlan>& plans, const std::vector<CylindricalHole>& holes,
                    const DrillOptions& o, DrillResult& r, std::vector<bool>& applied) {
  part = index_part(base);
  plan_holes(part, plans, holes, o);
  applied.assign(plans.size(), false);
  std::vector<std::size_t> early;
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!plans[i].reason.empty()) early.push_back(i);
  if (early.empty()) return;
  const auto tf = Clock::now();
  for (std::size_t i : early) r.holes[i].fallback_reason = plans[i].reason;
  base = apply_fallback(base, early, holes, o, r);
  for (std::size_t i : early) applied[i] = true;
  r.seconds_fallback += since(tf);
  if (early.size() == plans.size()) return;
  part = index_part(base);
  std::vector<std::size_t> rest;
  std::vector<CylindricalHole> rest_holes;
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!applied[i]) rest.push_back(i), rest_holes.push_back(holes[i]);
  std::vector<HolePlan> again = initial_plans(rest_holes, o);
  plan_holes(part, again, rest_holes, o);
  for (std::size_t k = 0; k < rest.size(); ++k) {
    plans[rest[k]] = std::move(again[k]);
    if (!plans[rest[k]].reason.empty())
      plans[rest[k]].reason = "after the other fallback holes were cut: " + plans[rest[k]].reason;
  }
}

// The drilled topology: each hole's faces, the walls rebuilt with their holes.
struct Topology {
  std::vector<HoleShape> shapes;
  std::map<int, std::vector<std::pair<int, LoopEdge*>>> on_face;  // face -> (hole, loop edge in `shapes`)
  std::vector<int> rebuilt_ids;
  std::vector<TopoDS_Face> rebuilt;
};

// 3. Topology: hole faces, rebuilt walls, shells.
void build_topology(const Part& part, std::vector<HolePlan>& plans, const std::vector<CylindricalHole>& holes, DrillResult& r,
                    Topology& topo) {
  std::vector<HoleShape>& shapes = topo.shapes;
  shapes.resize(plans.size());
  for (std::size_t i = 0; i < plans.size(); ++i) {
    HolePlan& p = plans[i];
    DrilledHole& dh = r.holes[i];
    dh.name = holes[i].name;
    if (!p.reason.empty()) {
      dh.fallback_reason = p.reason;
      continue;
    }
    const FaceInfo& fa = part.faces[static_cast<std::size_t>(p.entry)];
    const FaceInfo& fb = part.faces[static_cast<std::size_t>(p.exit)];
    shapes[i] = build_hole_shape(p.cyl, p.entry_loop, part.occt_surfaces[static_cast<std::size_t>(fa.surface)], p.exit_loop,
                                 part.occt_surfaces[static_cast<std::size_t>(fb.surface)]);
    topo.on_face[p.entry].emplace_back(static_cast<int>(i), &shapes[i].entry);
    topo.on_face[p.exit].emplace_back(static_cast<int>(i), &shapes[i].exit);
    dh.drilled = true;
    dh.entry_face = fa.name, dh.exit_face = fb.name;
    dh.independent_volume = p.quadrature;
    dh.edge_tolerance = std::max(shapes[i].entry.tolerance, shapes[i].exit.tolerance);
    dh.nodes = std::max(p.entry_loop.nodes, p.exit_loop.nodes);
  }
  for (const auto& [f, loops] : topo.on_face) topo.rebuilt_ids.push_back(f);
  topo.rebuilt.resize(part.faces.size());
  for (const auto& [f, loops] : topo.on_face) {
    std::vector<LoopEdge*> edges;
    for (const auto& [hole, e] : loops) edges.push_back(e);
    topo.rebuilt[static_cast<std::size_t>(f)] = wall_with_holes(part.faces[static_cast<std::size_t>(f)].face, edges);
  }
  r.rebuilt_faces = static_cast<int>(topo.on_face.size());
}

// 4. (per hole) Volume by the divergence theorem over its faces against the quadrature, and BRepCheck
// of its face and of its loops in their walls; `f` the failure, if any.
void check_drilled_hole(DrilledHole& dh, const HolePlan& p, const HoleShape& s, const Part& part, const DrillOptions& o,
                        std::string& f) {
  const TopoDS_Face cap_a = cap_face(part.faces[static_cast<std::size_t>(p.entry)].oriented, s.entry);
  const TopoDS_Face cap_b = cap_face(part.faces[static_cast<std::size_t>(p.exit)].oriented, s.exit);
  const Eigen::Vector3d mid = p.cyl.o + 0.5 * (p.entry_hit.t + p.exit_hit.t) * p.cyl.d;
  // About two points a hole size apart: a closed boundary gives the same volume ("closure").
  const Eigen::Vector3d mid2 = mid + (p.cyl.radius + 0.5 * (p.exit_hit.t - p.entry_hit.t)) * p.cyl.e1;
  const auto measure = [&](bool adaptive) {
    double v2 = 0;
    dh.volume = 0;
    for (const TopoDS_Face& face : {cap_a, cap_b, s.face}) {
      dh.volume += adaptive ? face_flux(face, occt::to_pnt(mid)) : hole_face_flux(face, occt::to_pnt(mid));
      v2 += adaptive ? face_flux(face, occt::to_pnt(mid2)) : hole_face_flux(face, occt::to_pnt(mid2));
    }
    dh.closure = std::abs(dh.volume - v2);
  };
  measure(false);
  // Edge tolerances leave a band of 2 tol along each loop undefined; its lever about `mid` is at
  // most the loop's distance from it (/3 of the divergence integrand).
  const double lever = std::max((p.entry_loop.start - mid).norm(), (p.exit_loop.start - mid).norm()) +
                       p.cyl.radius / std::max(0.1, p.entry_loop.min_sin_incidence);
  dh.uncertainty = (2 * s.entry.tolerance * s.entry.length + 2 * s.exit.tolerance * s.exit.length) * lever / 3;
  const double allowed = o.volume_rel_tolerance * dh.independent_volume + dh.uncertainty;
  const auto agrees = [&] { return std::abs(dh.volume - dh.independent_volume) <= allowed && dh.closure <= allowed; };
  // The fixed rule first (fast); before a disagreement counts, BRepGProp's adaptive rule at 1e-9.
  if (!agrees()) measure(true);
  if (!agrees()) {
    const ValueLimitText t = format_value_limit(dh.volume, dh.independent_volume, Allowed::near);
    f = "hole '" + dh.name + "': removed volume " + t.value + " mm^3 by its faces, " + t.limit + " mm^3 by quadrature, closure " +
        format_number(dh.closure);
  }
  if (!f.empty()) return;
  if (!BRepCheck_Analyzer(s.face).IsValid()) {
    f = "hole '" + dh.name + "': its face fails BRepCheck";
    return;
  }
  // Its loops as inner wires of the rebuilt walls: the wire and edge checks of BRepCheck in the
  // context of the wall face (2D closure, self-intersection, orientation; pcurve on the wall).
  for (const auto& [face, e] : {std::make_pair(p.entry, &s.entry), std::make_pair(p.exit, &s.exit)}) {
    if (!inner_wire_valid(e->wire, e->edge, part.faces[static_cast<std::size_t>(face)].face)) {
      f = "hole '" + dh.name + "': its loop fails BRepCheck in face '" + part.faces[static_cast<std::size_t>(face)].name + "'";
      return;
    }
  }
}

// 4. (per rebuilt wall) BRepCheck and the integral balance; `f` the failure, if any.
void check_rebuilt_wall(int face, const Part& part, const Topology& topo, const DrillOptions& o, std::string& f,
                        double& balance) {
  const FaceInfo& fi = part.faces[static_cast<std::size_t>(face)];
  const TopoDS_Face& nf = topo.rebuilt[static_cast<std::size_t>(face)];
  if (!o.whole_face_checks) return;
  if (!BRepCheck_Analyzer(nf).IsValid()) {
    f = "face '" + fi.name + "' with its holes fails BRepCheck";
    return;
  }
  // Integral after = before - the caps of its holes (all about one point near the face).
  const gp_Pnt c = occt::to_pnt(0.5 * (Eigen::Vector3d(fi.box.CornerMin().X(), fi.box.CornerMin().Y(), fi.box.CornerMin().Z()) +
                              Eigen::Vector3d(fi.box.CornerMax().X(), fi.box.CornerMax().Y(), fi.box.CornerMax().Z())));
  double caps = 0, cap_sum_abs = 0;
  for (const auto& [hole, e] : topo.on_face.at(face)) {
    const double v = face_flux(cap_face(fi.oriented, *e), c);
    caps += v;
    cap_sum_abs += std::abs(v);
  }
  const double before = face_flux(fi.oriented, c), after = face_flux(nf.Oriented(fi.oriented.Orientation()), c);
  balance = after - before + caps;
  // Tolerance: the integrations' relative accuracy (1e-9 each, x10) plus 1e-6 of the caps.
  if (!(std::abs(after - before + caps) <= 1e-8 * (std::abs(before) + std::abs(after)) + 1e-6 * cap_sum_abs + 1e-9)) {
    const ValueLimitText t = format_value_limit(after, before - caps, Allowed::near);
    f = "face '" + fi.name + "': integral with holes " + t.value + " != without " + format_number(before) + " - caps " +
        format_number(caps) + " = " + t.limit;
  }
}

// 4. Local checks (parallel): per hole, volume by the divergence theorem over its faces against the
// quadrature, and BRepCheck of its face; per rebuilt wall, BRepCheck and the integral balance.
void check_locally(const Part& part, const std::vector<HolePlan>& plans, const Topology& topo, const DrillOptions& o,
                   DrillResult& r) {
  std::vector<std::string> failures(plans.size() + part.faces.size());
  std::vector<double> balance(part.faces.size(), 0.0);
  parallel_for(static_cast<int>(plans.size() + topo.rebuilt_ids.size()), o.parallel ? parallel_workers() : 1, [&](int j, int) {
    if (j < static_cast<int>(plans.size())) {
      DrilledHole& dh = r.holes[static_cast<std::size_t>(j)];
      if (!dh.drilled) return;
      check_drilled_hole(dh, plans[static_cast<std::size_t>(j)], topo.shapes[static_cast<std::size_t>(j)], part, o,
                         failures[static_cast<std::size_t>(j)]);
      return;
    }
    const int face = topo.rebuilt_ids[static_cast<std::size_t>(j) - plans.size()];
    check_rebuilt_wall(face, part, topo, o, failures[plans.size() + static_cast<std::size_t>(face)],
                       balance[static_cast<std::size_t>(face)]);
  });
  std::string failed;
  int failed_count = 0;
  for (const std::string& f : failures)
    if (!f.empty()) failed += (failed_count++ ? "; " : "") + f;
  if (failed_count) throw FeatureFailure("drill_holes: " + std::to_string(failed_count) + " check(s) failed: " + failed);
  for (double b : balance) r.face_balance += std::abs(b);
}

// 5. The solid: shells rebuilt from their faces (a hole joining two shells merges them).
brep::NamedShape assemble_solid(const Part& part, const std::vector<HolePlan>& plans, const Topology& topo,
                                const std::vector<CylindricalHole>& holes, DrillResult& r) {
  BRep_Builder b;
  std::vector<int> shell_of(part.shells.size());
  for (std::size_t i = 0; i < shell_of.size(); ++i) shell_of[i] = static_cast<int>(i);
  const std::function<int(int)> root = [&](int s) { return shell_of[static_cast<std::size_t>(s)] == s ? s : shell_of[static_cast<std::size_t>(s)] = root(shell_of[static_cast<std::size_t>(s)]); };
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (r.holes[i].drilled) {
      const int a = root(part.faces[static_cast<std::size_t>(plans[i].entry)].shell);
      const int c = root(part.faces[static_cast<std::size_t>(plans[i].exit)].shell);
      if (a != c) shell_of[static_cast<std::size_t>(std::max(a, c))] = std::min(a, c);
    }
  std::map<int, TopoDS_Shell> shells;
  const auto shell = [&](int s) -> TopoDS_Shell& {
    const int k = root(s);
    auto it = shells.find(k);
    if (it == shells.end()) {
      TopoDS_Shell sh;
      b.MakeShell(sh);
      it = shells.emplace(k, sh).first;
    }
    return it->second;
  };
  brep::NamedShape result;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const TopoDS_Face& face = topo.rebuilt[f].IsNull() ? part.faces[f].face : topo.rebuilt[f];
    b.Add(shell(part.faces[f].shell), face);
    result.faces.push_back({face, part.faces[f].name});
  }
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (r.holes[i].drilled) {
      // The solid's material is outside the cylinder: REVERSED in the solid, relative to the shell.
      const FaceInfo& fa = part.faces[static_cast<std::size_t>(plans[i].entry)];
      const TopAbs_Orientation frame =
          fa.oriented.Orientation() == fa.face.Orientation() ? TopAbs_FORWARD : TopAbs_REVERSED;
      const TopoDS_Face face = TopoDS::Face(topo.shapes[i].face.Oriented(TopAbs::Compose(TopAbs_REVERSED, frame)));
      b.Add(shell(fa.shell), face);
      result.faces.push_back({face, holes[i].name});
      r.volume_change += r.holes[i].volume;
      ++r.drilled;
    }
  TopoDS_Solid solid;
  b.MakeSolid(solid);
  for (auto& [k, sh] : shells) {
    sh.Closed(true);
    b.Add(solid, sh.Oriented(part.shells[static_cast<std::size_t>(k)].Orientation()));
  }
  result.shape = solid.Oriented(part.solid_orientation);
  const std::string edges = edge_use_failure(result.shape);
  if (!edges.empty()) throw FeatureFailure("drill_holes: the drilled solid is not closed: " + edges);
  return result;
}

}  // namespace

DrillResult drill_holes(const brep::NamedShape& input, const std::vector<CylindricalHole>& holes,
                        const DrillOptions& o) {
  const auto t_start = Clock::now();
  require(!input.shape.IsNull(), "drill_holes: null part");
  std::vector<HolePlan> plans = initial_plans(holes, o);
  DrillResult r;
  r.holes.resize(holes.size());

  // 1. Patches: walls that many holes reach are split between them.
  auto t = Clock::now();
  brep::NamedShape base = patch_walls(input, plans, holes.size(), o, r);
  r.seconds_patches = since(t);

  // 2. Geometry of every hole (parallel): faces crossed, loops, preconditions, quadrature volume.
  t = Clock::now();
  Part part;
  std::vector<bool> applied;
  plan_all_holes(base, part, plans, holes, o, r, applied);
  r.seconds_geometry = since(t) - r.seconds_fallback;

  // 3. Topology: hole faces, rebuilt walls, shells.
  t = Clock::now();
  Topology topo;
  build_topology(part, plans, holes, r, topo);
  r.seconds_topology = since(t);

  // 4. Local checks; 5. the solid.
  t = Clock::now();
  check_locally(part, plans, topo, o, r);
  brep::NamedShape result = assemble_solid(part, plans, topo, holes, r);
  r.seconds_checks = since(t);

  // 6. Holes that could not be drilled directly: the verified boolean path.
  t = Clock::now();
  std::vector<std::size_t> late;
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!r.holes[i].drilled && !applied[i]) late.push_back(i);
  if (!late.empty()) result = apply_fallback(result, late, holes, o, r);
  r.fallen_back = static_cast<int>(plans.size()) - r.drilled;
  r.seconds_fallback += since(t);

  // 7. Optional global verification.
  if (o.verify_solid) {
    t = Clock::now();
    r.check = brep::verify_solid(result.shape, o.verify);
    r.check.one_solid.passed = r.check.one_solid.passed && count_solids(result.shape) == 1;
    r.seconds_verify = since(t);
    if (!r.check.all_passed())
      throw FeatureFailure("drill_holes: the drilled solid fails " + r.check.failed_names());
  }
  r.part = std::move(result);
  r.seconds = since(t_start);
  return r;
}

}  // namespace cg::features
