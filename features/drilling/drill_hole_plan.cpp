#include "features/drilling/drill_hole_plan.hpp"

#include <BRepBndLib.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <gp_Lin.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>

#include "adaptors/occt_convert.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/algo/segment_distance.hpp"

namespace cg::features::drill_detail {
namespace {


}  // namespace




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

namespace {

// Per-thread work objects (ray casters and evaluators mutate buffers; classifiers are built lazily).
struct Workspace {
  const Part* part = nullptr;
  std::vector<std::unique_ptr<WallSurface>> walls;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> intersectors;
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
  // Whether the segment p + t d, t in [0, length], meets face f (any surface type).
  bool meets(int f, const Eigen::Vector3d& p, const Eigen::Vector3d& d, double length) {
    auto& x = intersectors[static_cast<std::size_t>(f)];
    if (!x) x = std::make_unique<IntCurvesFace_Intersector>(part->faces[static_cast<std::size_t>(f)].face, 1e-7);
    x->Perform(gp_Lin(occt::to_pnt(p), gp_Dir(d.x(), d.y(), d.z())), 0, length);
    return x->IsDone() ? x->NbPnt() > 0 : true;
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


void plan_hole(Workspace& ws, HolePlan& h, const DrillOptions& o) {
  const Part& part = *ws.part;
  const HoleCylinder& c = h.cyl;
  const double reach = c.radius + o.margin;
  std::vector<int> faces, surfaces, other;
  for (int f = 0; f < static_cast<int>(part.faces.size()); ++f) {
    const FaceInfo& fi = part.faces[static_cast<std::size_t>(f)];
    if (fi.box.IsOut(h.box)) continue;
    if (fi.surface < 0) {
      other.push_back(f);
      continue;
    }
    faces.push_back(f);
    if (std::find(surfaces.begin(), surfaces.end(), fi.surface) == surfaces.end()) surfaces.push_back(fi.surface);
  }
  // Faces that are not B-splines (planes, surfaces of revolution, inlet cylinders) must stay out of
  // reach: the axis and the lines of the margin ring meet none of them within the tool (OCCT's
  // line/face intersector).
  for (int f : other)
    for (int k = -1; k < 8; ++k) {
      const Eigen::Vector3d p = k < 0 ? c.o : c.ruling(2 * kPi * k / 8, reach);
      if (ws.meets(f, p, c.d, c.length)) {
        h.reason = "it meets face '" + part.faces[static_cast<std::size_t>(f)].name + "' (not a B-spline face)";
        return;
      }
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


}  // namespace

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
    plans[i].box.Add(occt::to_pnt(c.o));
    plans[i].box.Add(occt::to_pnt(c.o + c.length * c.d));
    plans[i].box.Enlarge(c.radius + o.margin);
  }
  return plans;
}

// Geometry of every hole (parallel): faces crossed, loops, preconditions, quadrature volume; then
// holes too close to each other fall back together (the boolean path fuses overlapping tools).
void plan_holes(const Part& part, std::vector<HolePlan>& plans, const std::vector<CylindricalHole>& holes,
                const DrillOptions& o) {
  const int threads = o.parallel ? parallel_workers() : 1;
  std::vector<Workspace> ws(static_cast<std::size_t>(threads));
  for (Workspace& w : ws) {
    w.part = &part;
    w.walls.resize(part.surfaces.size());
    w.classifiers.resize(part.faces.size());
    w.intersectors.resize(part.faces.size());
  }
  parallel_for(static_cast<int>(plans.size()), threads,
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
      const double dist = segment_distance(p.cyl.o, p.cyl.o + p.cyl.length * p.cyl.d, q.cyl.o, q.cyl.o + q.cyl.length * q.cyl.d);
      if (dist < p.cyl.radius + q.cyl.radius + o.margin) {
        near[static_cast<std::size_t>(order[a])] = holes[static_cast<std::size_t>(order[b])].name;
        near[static_cast<std::size_t>(order[b])] = holes[static_cast<std::size_t>(order[a])].name;
      }
    }
  for (std::size_t i = 0; i < plans.size(); ++i)
    if (!near[i].empty() && plans[i].reason.empty()) plans[i].reason = "it is within the margin of hole '" + near[i] + "'";
}

}  // namespace cg::features::drill_detail
