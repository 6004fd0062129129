#include "export/sections.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "adaptors/occt_convert.hpp"
#include "export/atomic_file.hpp"

namespace cg::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The cutting face: a bounded plane (large enough for any blade) or the half revolution around the blade.
TopoDS_Face cutting_face(const SectionSurface& s, double size) {
  if (const auto* p = std::get_if<PlaneCut>(&s.surface)) {
    const gp_Pln pln(gp_Pnt(p->origin.x(), p->origin.y(), p->origin.z()), gp_Dir(p->normal.x(), p->normal.y(), p->normal.z()));
    return BRepBuilderAPI_MakeFace(pln, -size, size, -size, size).Face();
  }
  const auto& r = std::get<RevolvedCut>(s.surface);
  const Handle(Geom2d_BSplineCurve) c2 = occt::to_occt(r.meridional);
  // The (x, r) curve in the plane z = 0 (theta = 0), revolved about +x: theta = atan2(z, y).
  TColgp_Array1OfPnt poles(1, c2->NbPoles());
  for (int i = 1; i <= c2->NbPoles(); ++i) poles(i) = gp_Pnt(c2->Pole(i).X(), c2->Pole(i).Y(), 0);
  TColStd_Array1OfReal weights(1, c2->NbPoles());
  for (int i = 1; i <= c2->NbPoles(); ++i) weights(i) = c2->Weight(i);
  TColStd_Array1OfReal knots(1, c2->NbKnots());
  TColStd_Array1OfInteger mults(1, c2->NbKnots());
  c2->Knots(knots);
  c2->Multiplicities(mults);
  const Handle(Geom_BSplineCurve) c3 = new Geom_BSplineCurve(poles, weights, knots, mults, c2->Degree());
  const Handle(Geom_SurfaceOfRevolution) rev = new Geom_SurfaceOfRevolution(c3, gp::OX());
  return BRepBuilderAPI_MakeFace(rev, r.theta_centre - kPi / 2, r.theta_centre + kPi / 2, c3->FirstParameter(),
                                 c3->LastParameter(), 1e-7)
      .Face();
}

Eigen::Vector2d to_2d(const SectionSurface& s, const gp_Pnt& q) {
  const Eigen::Vector3d p(q.X(), q.Y(), q.Z());
  if (const auto* pc = std::get_if<PlaneCut>(&s.surface)) {
    const Eigen::Vector3d y_axis = pc->normal.cross(pc->x_axis);
    return {(p - pc->origin).dot(pc->x_axis), (p - pc->origin).dot(y_axis)};
  }
  const auto& r = std::get<RevolvedCut>(s.surface);
  const double radius = std::hypot(p.y(), p.z());
  double dtheta = std::atan2(p.z(), p.y()) - r.theta_centre;
  dtheta = std::remainder(dtheta, 2 * kPi);
  return {p.x(), radius * dtheta};
}

double signed_area(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

bool inside(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

Eigen::Vector2d centroid(const std::vector<Eigen::Vector2d>& poly) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  double a = 0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % n];
    const double w = p.x() * q.y() - q.x() * p.y();
    a += w;
    c += w * (p + q);
  }
  return std::abs(a) > 0 ? Eigen::Vector2d(c / (3 * a)) : poly.front();
}

// Chains the curves of one body into loops: greedy, joining ends within `tol` (section edges share
// their vertices, so ends agree to the section tolerance).
void chain_loops(const std::vector<SectionCurve>& curves, int body, double tol, SectionCut& cut) {
  std::vector<int> todo;
  for (std::size_t i = 0; i < curves.size(); ++i)
    if (curves[i].body == body && curves[i].points.size() >= 2) todo.push_back(static_cast<int>(i));
  std::vector<bool> used(curves.size(), false);
  for (int start : todo) {
    if (used[static_cast<std::size_t>(start)]) continue;
    used[static_cast<std::size_t>(start)] = true;
    SectionLoop loop;
    loop.body = body;
    std::map<std::string, double> share;
    auto append = [&](const SectionCurve& c, bool reversed) {
      std::vector<Eigen::Vector2d> pts = c.points;
      if (reversed) std::reverse(pts.begin(), pts.end());
      double len = 0;
      for (std::size_t k = 1; k < pts.size(); ++k) len += (pts[k] - pts[k - 1]).norm();
      share[c.name] += len;
      loop.points.insert(loop.points.end(), loop.points.empty() ? pts.begin() : pts.begin() + 1, pts.end());
    };
    append(curves[static_cast<std::size_t>(start)], false);
    bool closed = false;
    for (;;) {
      if ((loop.points.back() - loop.points.front()).norm() <= tol && loop.points.size() > 2) {
        closed = true;
        break;
      }
      bool extended = false;
      for (int i : todo) {
        if (used[static_cast<std::size_t>(i)]) continue;
        const auto& c = curves[static_cast<std::size_t>(i)];
        if ((c.points.front() - loop.points.back()).norm() <= tol) {
          append(c, false);
        } else if ((c.points.back() - loop.points.back()).norm() <= tol) {
          append(c, true);
        } else {
          continue;
        }
        used[static_cast<std::size_t>(i)] = extended = true;
        break;
      }
      if (!extended) break;
    }
    if (!closed) {
      ++cut.open_loops;
      continue;
    }
    loop.points.pop_back();
    loop.area = std::abs(signed_area(loop.points));
    for (std::size_t k = 0, n = loop.points.size(); k < n; ++k) loop.perimeter += (loop.points[(k + 1) % n] - loop.points[k]).norm();
    std::vector<std::pair<double, std::string>> by_length;
    for (const auto& [name, len] : share) by_length.emplace_back(-len, name);
    std::sort(by_length.begin(), by_length.end());
    for (const auto& [len, name] : by_length) loop.names.push_back(name);
    cut.loops.push_back(std::move(loop));
  }
}

}  // namespace

std::vector<SectionSurface> blade_section_surfaces(const blade::BladeModel& model, const std::vector<double>& spans) {
  std::vector<SectionSurface> out;
  for (double s : spans) {
    require(s >= 0 && s <= 1, "section span must be in [0, 1], got " + std::to_string(s));
    SectionSurface ss;
    ss.span = s;
    if (model.trim.straight) {
      PlaneCut p;
      p.origin = Eigen::Vector3d(0, 0, model.trim.hub_z + s * (model.trim.casing_z - model.trim.hub_z));
      ss.surface = p;
    } else {
      require(model.net.has_value(), "meridional blade model without its meridional net");
      RevolvedCut r{model.net->streamline_at(s).curve(), 0};
      // The blade's mean angle at this span, from points around the section iso-curve v = s.
      double sy = 0, sz = 0;
      for (int k = 0; k < 16; ++k) {
        const Eigen::Vector3d p = model.surface.point(k / 16.0, s);
        sy += p.y();
        sz += p.z();
      }
      r.theta_centre = std::atan2(sz, sy);
      ss.surface = r;
    }
    out.push_back(std::move(ss));
  }
  return out;
}

std::vector<SectionCut> cut_sections(const brep::Part& part, const std::vector<SectionSurface>& surfaces, double deflection) {
  if (part.empty()) throw ExportError("sections: empty part");
  std::vector<SectionCut> cuts;
  for (const SectionSurface& s : surfaces) {
    SectionCut cut;
    cut.span = s.span;
    double size = 0;  // for the plane's extent and the chaining tolerance
    for (const auto& body : part) {
      Bnd_Box box;
      BRepBndLib::Add(body.geometry.shape, box);
      size = std::max(size, std::sqrt(box.SquareExtent()));
    }
    const TopoDS_Face tool = cutting_face(s, 10 * size + 1);
    for (std::size_t b = 0; b < part.size(); ++b) {
      const brep::NamedShape& g = part[b].geometry;
      NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher> name_of;
      for (const auto& f : g.faces) name_of.Bind(f.face, f.name);
      BRepAlgoAPI_Section sec(g.shape, tool, /*PerformNow=*/false);
      sec.ComputePCurveOn1(false);
      sec.Approximation(true);  // without it the walking lines of the revolved cuts leave gaps between edges
      sec.Build();
      if (!sec.IsDone() || sec.HasErrors())
        throw ExportError("section of body \"" + part[b].name + "\" at span " + std::to_string(s.span) + " failed");
      for (TopExp_Explorer e(sec.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(e.Current());
        TopoDS_Shape face;
        SectionCurve c;
        c.body = static_cast<int>(b);
        if (sec.HasAncestorFaceOn1(edge, face))
          if (const std::string* n = name_of.Seek(face)) c.name = *n;
        BRepAdaptor_Curve curve(edge);
        GCPnts_TangentialDeflection d(curve, 0.05, deflection, 4);
        for (int k = 1; k <= d.NbPoints(); ++k) c.points.push_back(to_2d(s, d.Value(k)));
        cut.curves.push_back(std::move(c));
      }
      chain_loops(cut.curves, static_cast<int>(b), 1e-5 * size + 1e-6, cut);
    }
    // Nesting depth within each body; metal area = sum of +-area by depth parity.
    for (auto& l : cut.loops) {
      for (const auto& o : cut.loops)
        if (&o != &l && o.body == l.body && o.area > l.area && inside(o.points, l.points.front())) ++l.depth;
      cut.metal_area += (l.depth % 2 == 0 ? 1 : -1) * l.area;
    }
    const SectionLoop* outer = nullptr;
    for (const auto& l : cut.loops)
      if (l.body == 0 && l.depth == 0 && (!outer || l.area > outer->area)) outer = &l;
    if (outer) {
      for (std::size_t i = 0; i < outer->points.size(); ++i)
        for (std::size_t j = i + 1; j < outer->points.size(); ++j) {
          const double d = (outer->points[i] - outer->points[j]).norm();
          if (d > cut.chord) {
            cut.chord = d;
            cut.chord_a = outer->points[i];
            cut.chord_b = outer->points[j];
          }
        }
      for (const auto& l : cut.loops) {
        if (l.body != 0 || l.depth != 1 || !inside(outer->points, l.points.front())) continue;
        Passage p;
        p.name = l.names.empty() ? "" : l.names.front();
        p.area = l.area;
        p.wetted_perimeter = l.perimeter;
        p.centroid = centroid(l.points);
        for (const auto& m : cut.loops) {  // other bodies (inserts) inside the cavity
          if (m.body == 0 || !inside(l.points, m.points.front())) continue;
          p.area += (m.depth % 2 == 0 ? -1 : 1) * m.area;
          p.wetted_perimeter += m.perimeter;
        }
        p.hydraulic_diameter = 4 * p.area / p.wetted_perimeter;
        cut.passages.push_back(p);
      }
      std::sort(cut.passages.begin(), cut.passages.end(),
                [](const Passage& a, const Passage& b) { return a.centroid.x() < b.centroid.x(); });
    }
    cuts.push_back(std::move(cut));
  }
  return cuts;
}

nlohmann::ordered_json sections_json(const std::vector<SectionCut>& cuts) {
  using json = nlohmann::ordered_json;
  json out = json::array();
  for (const auto& c : cuts) {
    json passages = json::array();
    for (const auto& p : c.passages)
      passages.push_back({{"name", p.name},
                          {"area_mm2", p.area},
                          {"wetted_perimeter_mm", p.wetted_perimeter},
                          {"hydraulic_diameter_mm", p.hydraulic_diameter}});
    out.push_back({{"span", c.span}, {"chord_mm", c.chord}, {"metal_area_mm2", c.metal_area}, {"passages", passages}});
  }
  return out;
}

}  // namespace cg::io
