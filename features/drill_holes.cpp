#include "features/drill_holes.hpp"

#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_Edge.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Wire.hxx>
#include <BRepGProp.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <unordered_map>

#include "adaptors/occt_convert.hpp"
#include "features/boolean_patches.hpp"
#include "features/boolean_volume.hpp"
#include "features/drill_hole_geometry.hpp"
#include "features/drill_hole_topology.hpp"
#include "src/core/error.hpp"

namespace cg::features {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

gp_Pnt pnt(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

// Worker threads: one per core, or 1.
int worker_count(bool parallel) {
  return parallel ? std::max(1, static_cast<int>(std::thread::hardware_concurrency())) : 1;
}

// Runs f(i, worker) for i in [0, n) on worker_count(parallel) threads; worker < worker_count.
void for_each_index(int n, bool parallel, const std::function<void(int, int)>& f) {
  const int threads = std::min(n, worker_count(parallel));
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) f(i, 0);
    return;
  }
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex m;
  for (int k = 0; k < threads; ++k)
    pool.emplace_back([&, k] {
      try {
        for (int i = next++; i < n; i = next++) f(i, k);
      } catch (...) {
        std::lock_guard<std::mutex> g(m);
        if (!error) error = std::current_exception();
        next = n;
      }
    });
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

// A face of the (patched) part.
struct FaceInfo {
  TopoDS_Face face;      // oriented as in its shell (relative)
  TopoDS_Face oriented;  // oriented as in the solid (outward normal of the part)
  std::string name;
  int surface = -1;  // index into Part::surfaces; -1: not a B-spline face without location
  int shell = 0;
  Bnd_Box box;
};

struct Part {
  std::vector<FaceInfo> faces;
  std::vector<TopoDS_Shell> shells;
  std::vector<std::shared_ptr<const BSplineSurface<3>>> surfaces;
  std::vector<WallFaceGeometry> occt_surfaces;
  std::vector<std::vector<int>> faces_on_surface;
  TopAbs_Orientation solid_orientation = TopAbs_FORWARD;
};

Part index_part(const brep::NamedShape& p) {
  Part part;
  TopTools_IndexedMapOfShape named;
  for (const brep::NamedFace& f : p.faces) named.Add(f.face);
  std::vector<std::string> names(static_cast<std::size_t>(named.Extent()));
  for (const brep::NamedFace& f : p.faces) names[static_cast<std::size_t>(named.FindIndex(f.face) - 1)] = f.name;
  std::map<const Geom_Surface*, int> surface_index;
  TopExp_Explorer solids(p.shape, TopAbs_SOLID);
  require(solids.More(), "drill_holes: the part has no solid");
  int count = 0;
  for (; solids.More(); solids.Next()) ++count;
  require(count == 1, "drill_holes: the part must be one solid");
  const TopoDS_Shape solid = TopExp_Explorer(p.shape, TopAbs_SOLID).Current();
  part.solid_orientation = solid.Orientation();
  for (TopoDS_Iterator sh(solid, false); sh.More(); sh.Next()) {
    if (sh.Value().ShapeType() != TopAbs_SHELL) continue;
    part.shells.push_back(TopoDS::Shell(sh.Value()));
    for (TopoDS_Iterator it(sh.Value(), false); it.More(); it.Next()) {
      FaceInfo fi;
      fi.face = TopoDS::Face(it.Value());
      fi.oriented = TopoDS::Face(fi.face.Oriented(
          TopAbs::Compose(TopAbs::Compose(fi.face.Orientation(), sh.Value().Orientation()), solid.Orientation())));
      const int idx = named.FindIndex(fi.face);
      fi.name = idx > 0 ? names[static_cast<std::size_t>(idx - 1)] : std::string();
      fi.shell = static_cast<int>(part.shells.size()) - 1;
      BRepBndLib::Add(fi.face, fi.box, false);
      TopLoc_Location loc;
      const Handle(Geom_Surface) s = BRep_Tool::Surface(fi.face, loc);
      Handle(Geom_Surface) basis = s;
      if (auto tr = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) basis = tr->BasisSurface();
      const auto bs = Handle(Geom_BSplineSurface)::DownCast(basis);
      if (bs && loc.IsIdentity()) {
        auto [pos, inserted] = surface_index.emplace(s.get(), static_cast<int>(part.surfaces.size()));
        if (inserted) {
          part.surfaces.push_back(std::make_shared<const BSplineSurface<3>>(occt::from_occt(*bs)));
          part.occt_surfaces.push_back({s, loc});
          part.faces_on_surface.emplace_back();
        }
        fi.surface = pos->second;
        part.faces_on_surface[static_cast<std::size_t>(fi.surface)].push_back(static_cast<int>(part.faces.size()));
      }
      part.faces.push_back(std::move(fi));
    }
  }
  return part;
}

// Per-thread work objects (ray casters and evaluators mutate buffers; classifiers are built lazily).
struct Workspace {
  const Part* part = nullptr;
  std::vector<std::unique_ptr<WallSurface>> walls;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;
  WallSurface& wall(int s) {
    auto& w = walls[static_cast<std::size_t>(s)];
    if (!w) w = std::make_unique<WallSurface>(part->surfaces[static_cast<std::size_t>(s)]);
    return *w;
  }
  TopAbs_State state(int f, double u, double v) {
    auto& c = classifiers[static_cast<std::size_t>(f)];
    if (!c)
      c = std::make_unique<BRepTopAdaptor_FClass2d>(
          TopoDS::Face(part->faces[static_cast<std::size_t>(f)].face.Oriented(TopAbs_FORWARD)), 1e-9);
    return c->Perform(gp_Pnt2d(u, v));
  }
  // IN or ON the face (a point on the boundary counts as reaching it).
  bool inside(int f, double u, double v) { return state(f, u, v) != TopAbs_OUT; }
};

struct LineHit {
  double t;
  int face;
  double u, v;
};

// Every hit of the segment p + t d, t in [0, length], with the candidate B-spline faces (sorted by t).
std::vector<LineHit> line_hits(Workspace& ws, const std::vector<int>& candidate_surfaces,
                               const std::vector<int>& candidate_faces, const Eigen::Vector3d& p,
                               const Eigen::Vector3d& d, double length) {
  std::vector<LineHit> hits;
  for (int s : candidate_surfaces) {
    WallSurface& w = ws.wall(s);
    double t = 0;
    for (int k = 0; k < 8 && t < length; ++k) {
      const RaySurfaceHit h = w.first_hit(p + t * d, d, length - t);
      if (!h.found) break;
      const double th = t + h.ray_param;
      for (int f : candidate_faces)
        if (ws.part->faces[static_cast<std::size_t>(f)].surface == s && ws.inside(f, h.u, h.v))
          hits.push_back({th, f, h.u, h.v});
      t = th + 1e-6;
    }
  }
  std::sort(hits.begin(), hits.end(), [](const LineHit& a, const LineHit& b) { return a.t < b.t; });
  return hits;
}

// What the geometry stage finds for one hole.
struct HolePlan {
  HoleCylinder cyl;
  Bnd_Box box;
  std::string reason;  // fallback reason ("" = drillable)
  int entry = -1, exit = -1;
  AxisHit entry_hit, exit_hit;
  HoleLoop entry_loop, exit_loop;
  double quadrature = std::numeric_limits<double>::quiet_NaN();
};

void plan_hole(Workspace& ws, HolePlan& h, const DrillOptions& o) {
  const Part& part = *ws.part;
  const HoleCylinder& c = h.cyl;
  const double reach = c.radius + o.margin;
  std::vector<int> faces, surfaces;
  for (int f = 0; f < static_cast<int>(part.faces.size()); ++f) {
    const FaceInfo& fi = part.faces[static_cast<std::size_t>(f)];
    if (fi.box.IsOut(h.box)) continue;
    if (fi.surface < 0) {
      h.reason = "comes near face '" + fi.name + "', which is not a B-spline face";
      return;
    }
    faces.push_back(f);
    if (std::find(surfaces.begin(), surfaces.end(), fi.surface) == surfaces.end()) surfaces.push_back(fi.surface);
  }
  // Along the axis: exactly two faces, the entry and the exit.
  const std::vector<LineHit> axis = line_hits(ws, surfaces, faces, c.o, c.d, c.length);
  if (axis.size() != 2) {
    h.reason = axis.size() < 2 ? "its axis does not cross a wall (entry and exit face)"
                               : "its axis meets " + std::to_string(axis.size()) + " faces, not one wall";
    return;
  }
  h.entry = axis[0].face, h.exit = axis[1].face;
  h.entry_hit = {axis[0].t, axis[0].u, axis[0].v};
  h.exit_hit = {axis[1].t, axis[1].u, axis[1].v};
  const FaceInfo& fa = part.faces[static_cast<std::size_t>(h.entry)];
  const FaceInfo& fb = part.faces[static_cast<std::size_t>(h.exit)];
  WallSurface& wa = ws.wall(fa.surface);
  WallSurface& wb = ws.wall(fb.surface);
  // The tool must pass through material between them: into the part at the entry (against the
  // part's outward normal) and out of it at the exit. A tool starting inside the material and reaching
  // across a cavity also meets two faces, the other way round.
  const auto outward = [&](const FaceInfo& f, WallSurface& w, const AxisHit& a) {
    const Eigen::Vector3d n = w.unit_normal(a.u, a.v);
    return f.oriented.Orientation() == TopAbs_REVERSED ? Eigen::Vector3d(-n) : n;
  };
  if (c.d.dot(outward(fa, wa, h.entry_hit)) >= 0 || c.d.dot(outward(fb, wb, h.exit_hit)) <= 0) {
    h.reason = "the material between its two faces is not where the tool passes (it starts inside the part)";
    return;
  }

  if (h.entry == h.exit) {
    h.reason = "it enters and leaves through the same face '" + fa.name + "'";
    return;
  }

  // The loops, fitted.
  h.entry_loop = hole_loop(wa, c, h.entry_hit, o.fit_tolerance);
  if (h.entry_loop.ok) h.exit_loop = hole_loop(wb, c, h.exit_hit, o.fit_tolerance);
  const HoleLoop& bad = h.entry_loop.ok ? h.exit_loop : h.entry_loop;
  if (!bad.ok) {
    h.reason = bad.failure;
    return;
  }
  if (std::max(h.entry_loop.deviation, h.exit_loop.deviation) > 100 * o.fit_tolerance) {
    h.reason = "its loops could not be fitted within 100x the fit tolerance";
    return;
  }
  const double min_sin = std::sin(o.min_incidence_deg * kPi / 180);
  if (std::min(h.entry_loop.min_sin_incidence, h.exit_loop.min_sin_incidence) < min_sin) {
    h.reason = "it meets a wall at less than the minimum incidence angle";
    return;
  }
  if (h.entry_loop.t_min <= 0 || h.exit_loop.t_max >= c.length || h.entry_loop.t_max >= h.exit_loop.t_min) {
    h.reason = "its tool does not start outside the wall and end behind it";
    return;
  }
  // The loops stay inside their faces with the margin: a ring of radius r + margin on each wall.
  std::vector<Eigen::Vector2d> ring;
  for (const auto& [f, w, hit] : {std::make_tuple(h.entry, &wa, h.entry_hit), std::make_tuple(h.exit, &wb, h.exit_hit)}) {
    if (!ring_parameters(*w, c, hit, reach, 32, ring)) {
      h.reason = "the margin ring around it could not be followed on '" + part.faces[static_cast<std::size_t>(f)].name + "'";
      return;
    }
    for (const Eigen::Vector2d& q : ring)
      if (ws.state(f, q.x(), q.y()) != TopAbs_IN) {
        h.reason = "it comes within the margin of an edge of face '" + part.faces[static_cast<std::size_t>(f)].name + "'";
        return;
      }
  }
  // Ruling lines (and lines of the margin ring): nothing but the entry and exit faces in reach.
  for (int k = 0; k < 8; ++k) {
    const double theta = 2 * kPi * k / 8;
    for (const double rho : {reach}) {
      const std::vector<LineHit> hits = line_hits(ws, surfaces, faces, c.ruling(theta, rho), c.d, c.length);
      for (const LineHit& x : hits)
        if (x.face != h.entry && x.face != h.exit) {
          h.reason = "it meets face '" + part.faces[static_cast<std::size_t>(x.face)].name + "'";
          return;
        }
      if (hits.size() != 2 || hits[0].face != h.entry || hits[1].face != h.exit) {
        h.reason = "a line of it crosses the walls other than once each";
        return;
      }
    }
  }
  h.quadrature = quadrature_volume(wa, h.entry_hit, wb, h.exit_hit, c);
  if (!std::isfinite(h.quadrature)) h.reason = "the volume quadrature could not follow the walls";
}

// Smallest distance between segments [p0, p0 + d0 l0] and [p1, p1 + d1 l1] (unit d).
double segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& d0, double l0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& d1, double l1) {
  const Eigen::Vector3d w = p0 - p1;
  const double b = d0.dot(d1), dd = d0.dot(w), e = d1.dot(w), den = 1 - b * b;
  double s = den > 1e-12 ? std::clamp((b * e - dd) / den, 0.0, l0) : 0.0;
  double t = std::clamp(e + b * s, 0.0, l1);
  s = std::clamp(b * t - dd, 0.0, l0);
  return (p0 + s * d0 - p1 - t * d1).norm();
}

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

// Validated holes with their cylinders and boxes.
std::vector<HolePlan> initial_plans(const std::vector<CylindricalHole>& holes, const DrillOptions& o) {
  std::set<std::string> names;
  std::vector<HolePlan> plans(holes.size());
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const CylindricalHole& h = holes[i];
    require(!h.name.empty() && names.insert(h.name).second, "drill_holes: hole names must be unique and non-empty ('" + h.name + "')");
    require(h.origin.allFinite() && h.axis.allFinite() && h.axis.norm() > 1e-12,
            "drill_holes: hole '" + h.name + "': origin and axis must be finite, axis non-zero");
    require(std::isfinite(h.diameter) && h.diameter > 0 && std::isfinite(h.length) && h.length > 0,
            "drill_holes: hole '" + h.name + "': diameter and length must be > 0");
    plans[i].cyl = HoleCylinder::from_axis(h.origin, h.axis, 0.5 * h.diameter, h.length);
    const HoleCylinder& c = plans[i].cyl;
    plans[i].box.Add(pnt(c.o));
    plans[i].box.Add(pnt(c.o + c.length * c.d));
    plans[i].box.Enlarge(c.radius + o.margin);
  }
  return plans;
}

// Geometry of every hole (parallel): faces crossed, loops, preconditions, quadrature volume; then
// holes too close to each other fall back together (the boolean path fuses overlapping tools).
void plan_holes(const Part& part, std::vector<HolePlan>& plans, const std::vector<CylindricalHole>& holes,
                const DrillOptions& o) {
  const int threads = worker_count(o.parallel);
  std::vector<Workspace> ws(static_cast<std::size_t>(threads));
  for (Workspace& w : ws) {
    w.part = &part;
    w.walls.resize(part.surfaces.size());
    w.classifiers.resize(part.faces.size());
  }
  for_each_index(static_cast<int>(plans.size()), o.parallel,
                 [&](int i, int k) { plan_hole(ws[static_cast<std::size_t>(k)], plans[static_cast<std::size_t>(i)], o); });
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(plans.size()); ++i) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return plans[static_cast<std::size_t>(a)].box.CornerMin().X() < plans[static_cast<std::size_t>(b)].box.CornerMin().X();
  });
  std::vector<std::string> near(plans.size());
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      HolePlan& p = plans[static_cast<std::size_t>(order[a])];
      HolePlan& q = plans[static_cast<std::size_t>(order[b])];
      if (q.box.CornerMin().X() > p.box.CornerMax().X()) break;
      if (p.box.IsOut(q.box)) continue;
      const double dist = segment_distance(p.cyl.o, p.cyl.d, p.cyl.length, q.cyl.o, q.cyl.d, q.cyl.length);
      if (dist < p.cyl.radius + q.cyl.radius + o.margin) {
        near[static_cast<std::size_t>(order[a])] = holes[static_cast<std::size_t>(order[b])].name;
        near[static_cast<std::size_t>(order[b])] = holes[static_cast<std::size_t>(order[a])].name;
      }
    }
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!near[i].empty() && plans[i].reason.empty()) plans[i].reason = "it is within the margin of hole '" + near[i] + "'";
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
  const gp_Ax2 ax(pnt(c.o), gp_Dir(c.d.x(), c.d.y(), c.d.z()), gp_Dir(c.e1.x(), c.e1.y(), c.e1.z()));
  FeatureTool tool;
  tool.feature = hole.name;
  tool.shape.shape = BRepPrimAPI_MakeCylinder(ax, c.radius, c.length).Shape();
  for (TopExp_Explorer e(tool.shape.shape, TopAbs_FACE); e.More(); e.Next())
    tool.shape.faces.push_back({TopoDS::Face(e.Current()), hole.name});
  tool.symmetry_axis = gp_Ax1(ax.Location(), ax.Direction());
  return tool;
}

DrillResult drill_holes(const brep::NamedShape& input, const std::vector<CylindricalHole>& holes,
                        const DrillOptions& o) {
  const auto t_start = Clock::now();
  require(!input.shape.IsNull(), "drill_holes: null part");
  std::vector<HolePlan> plans = initial_plans(holes, o);
  DrillResult r;
  r.holes.resize(holes.size());

  // 1. Patches: walls that many holes reach are split between them.
  auto t = Clock::now();
  brep::NamedShape base = input;
  if (o.patch_min_holes > 0 && static_cast<int>(holes.size()) >= o.patch_min_holes) {
    std::vector<TopoDS_Shape> tools;
    for (const HolePlan& p : plans)
      tools.push_back(BRepPrimAPI_MakeCylinder(gp_Ax2(pnt(p.cyl.o), gp_Dir(p.cyl.d.x(), p.cyl.d.y(), p.cyl.d.z())),
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
  r.seconds_patches = since(t);

  // 2. Geometry of every hole (parallel): faces crossed, loops, preconditions, quadrature volume.
  t = Clock::now();
  Part part = index_part(base);
  plan_holes(part, plans, holes, o);
  // Holes that fall back are cut first, by the boolean path on the part as it is (its cost grows
  // with the faces of the part, and the drilled part has many); the others are then planned again on
  // that result. A hole that no longer qualifies there is cut by the boolean path after the drilling.
  std::vector<bool> applied(plans.size(), false);
  std::vector<std::size_t> early;
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!plans[i].reason.empty()) early.push_back(i);
  if (!early.empty()) {
    const auto tf = Clock::now();
    for (std::size_t i : early) r.holes[i].fallback_reason = plans[i].reason;
    base = apply_fallback(base, early, holes, o, r);
    for (std::size_t i : early) applied[i] = true;
    r.seconds_fallback += since(tf);
    if (early.size() < plans.size()) {
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
  }
  r.seconds_geometry = since(t) - r.seconds_fallback;

  // 3. Topology: hole faces, rebuilt walls, shells.
  t = Clock::now();
  std::vector<HoleShape> shapes(plans.size());
  std::map<int, std::vector<std::pair<int, LoopEdge*>>> on_face;  // face -> (hole, loop edge)
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
    on_face[p.entry].emplace_back(static_cast<int>(i), &shapes[i].entry);
    on_face[p.exit].emplace_back(static_cast<int>(i), &shapes[i].exit);
    dh.drilled = true;
    dh.entry_face = fa.name, dh.exit_face = fb.name;
    dh.independent_volume = p.quadrature;
    dh.edge_tolerance = std::max(shapes[i].entry.tolerance, shapes[i].exit.tolerance);
    dh.nodes = std::max(p.entry_loop.nodes, p.exit_loop.nodes);
  }
  std::vector<int> rebuilt_ids;
  for (const auto& [f, loops] : on_face) rebuilt_ids.push_back(f);
  std::vector<TopoDS_Face> rebuilt(part.faces.size());
  for (const auto& [f, loops] : on_face) {
    std::vector<LoopEdge*> edges;
    for (const auto& [hole, e] : loops) edges.push_back(e);
    rebuilt[static_cast<std::size_t>(f)] = wall_with_holes(part.faces[static_cast<std::size_t>(f)].face, edges);
  }
  r.rebuilt_faces = static_cast<int>(on_face.size());
  r.seconds_topology = since(t);

  // 4. Local checks (parallel): per hole, volume by the divergence theorem over its faces against the
  // quadrature, and BRepCheck of its face; per rebuilt wall, BRepCheck and the integral balance.
  t = Clock::now();
  std::vector<std::string> failures(plans.size() + part.faces.size());
  std::vector<double> balance(part.faces.size(), 0.0);
  for_each_index(static_cast<int>(plans.size() + rebuilt_ids.size()), o.parallel, [&](int j, int) {
    if (j < static_cast<int>(plans.size())) {
      DrilledHole& dh = r.holes[static_cast<std::size_t>(j)];
      if (!dh.drilled) return;
      const HolePlan& p = plans[static_cast<std::size_t>(j)];
      const HoleShape& s = shapes[static_cast<std::size_t>(j)];
      const TopoDS_Face cap_a = cap_face(part.faces[static_cast<std::size_t>(p.entry)].oriented, s.entry);
      const TopoDS_Face cap_b = cap_face(part.faces[static_cast<std::size_t>(p.exit)].oriented, s.exit);
      const Eigen::Vector3d mid = p.cyl.o + 0.5 * (p.entry_hit.t + p.exit_hit.t) * p.cyl.d;
      // About two points a hole size apart: a closed boundary gives the same volume ("closure").
      const Eigen::Vector3d mid2 = mid + (p.cyl.radius + 0.5 * (p.exit_hit.t - p.entry_hit.t)) * p.cyl.e1;
      const auto measure = [&](bool adaptive) {
        double v2 = 0;
        dh.volume = 0;
        for (const TopoDS_Face& face : {cap_a, cap_b, s.face}) {
          dh.volume += adaptive ? face_flux(face, pnt(mid)) : hole_face_flux(face, pnt(mid));
          v2 += adaptive ? face_flux(face, pnt(mid2)) : hole_face_flux(face, pnt(mid2));
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
      std::string& f = failures[static_cast<std::size_t>(j)];
      const auto agrees = [&] { return std::abs(dh.volume - dh.independent_volume) <= allowed && dh.closure <= allowed; };
      // The fixed rule first (fast); before a disagreement counts, BRepGProp's adaptive rule at 1e-9.
      if (!agrees()) measure(true);
      if (!agrees())
        f = "hole '" + dh.name + "': removed volume " + std::to_string(dh.volume) + " mm^3 by its faces, " +
            std::to_string(dh.independent_volume) + " mm^3 by quadrature, closure " + std::to_string(dh.closure);
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
      return;
    }
    const int face = rebuilt_ids[static_cast<std::size_t>(j) - plans.size()];
    const FaceInfo& fi = part.faces[static_cast<std::size_t>(face)];
    const TopoDS_Face& nf = rebuilt[static_cast<std::size_t>(face)];
    std::string& f = failures[plans.size() + static_cast<std::size_t>(face)];
    if (!o.whole_face_checks) return;
    if (!BRepCheck_Analyzer(nf).IsValid()) {
      f = "face '" + fi.name + "' with its holes fails BRepCheck";
      return;
    }
    // Integral after = before - the caps of its holes (all about one point near the face).
    const gp_Pnt c = pnt(0.5 * (Eigen::Vector3d(fi.box.CornerMin().X(), fi.box.CornerMin().Y(), fi.box.CornerMin().Z()) +
                                Eigen::Vector3d(fi.box.CornerMax().X(), fi.box.CornerMax().Y(), fi.box.CornerMax().Z())));
    double caps = 0, cap_sum_abs = 0;
    for (const auto& [hole, e] : on_face.at(face)) {
      const double v = face_flux(cap_face(fi.oriented, *e), c);
      caps += v;
      cap_sum_abs += std::abs(v);
    }
    const double before = face_flux(fi.oriented, c), after = face_flux(nf.Oriented(fi.oriented.Orientation()), c);
    balance[static_cast<std::size_t>(face)] = after - before + caps;
    // Tolerance: the integrations' relative accuracy (1e-9 each, x10) plus 1e-6 of the caps.
    if (!(std::abs(after - before + caps) <= 1e-8 * (std::abs(before) + std::abs(after)) + 1e-6 * cap_sum_abs + 1e-9))
      f = "face '" + fi.name + "': integral with holes " + std::to_string(after) + " != without " + std::to_string(before) +
          " - caps " + std::to_string(caps);
  });
  std::string failed;
  int failed_count = 0;
  for (const std::string& f : failures)
    if (!f.empty()) failed += (failed_count++ ? "; " : "") + f;
  if (failed_count) throw FeatureFailure("drill_holes: " + std::to_string(failed_count) + " check(s) failed: " + failed);
  for (double b : balance) r.face_balance += std::abs(b);

  // 5. The solid: shells rebuilt from their faces (a hole joining two shells merges them).
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
    const TopoDS_Face& face = rebuilt[f].IsNull() ? part.faces[f].face : rebuilt[f];
    b.Add(shell(part.faces[f].shell), face);
    result.faces.push_back({face, part.faces[f].name});
  }
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (r.holes[i].drilled) {
      // The solid's material is outside the cylinder: REVERSED in the solid, relative to the shell.
      const FaceInfo& fa = part.faces[static_cast<std::size_t>(plans[i].entry)];
      const TopAbs_Orientation frame =
          fa.oriented.Orientation() == fa.face.Orientation() ? TopAbs_FORWARD : TopAbs_REVERSED;
      const TopoDS_Face face = TopoDS::Face(shapes[i].face.Oriented(TopAbs::Compose(TopAbs_REVERSED, frame)));
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
