#include "export/sections.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
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
#include "src/core/parallel.hpp"

namespace cg::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The cutting face: a bounded plane (large enough for any blade) or the surface of revolution over the
// angles theta_centre + [dtheta0, dtheta1] (within +-90 deg).
TopoDS_Face cutting_face(const SectionSurface& s, double size, double dtheta0 = -kPi / 2, double dtheta1 = kPi / 2) {
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
  return BRepBuilderAPI_MakeFace(rev, r.theta_centre + dtheta0, r.theta_centre + dtheta1, c3->FirstParameter(),
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

namespace {

// Where a cutting surface can meet a face, from the face's bounding box: for a plane, the box's corners
// lie on both sides (or on it); for a surface of revolution, the box's (x, r) rectangle (r from the
// box's distance range to the x axis) meets the meridional curve, sampled densely and padded by the
// longest sample step (a smooth curve stays within half a step of its chords). Conservative: a face it
// keeps may still miss the surface; a face it drops cannot meet it, and nor can any of its edges.
class FaceFilter {
 public:
  FaceFilter(const SectionSurface& s, double size) : surface_(s), pad_(1e-6 * size + 1e-9) {
    const auto* r = std::get_if<RevolvedCut>(&s.surface);
    if (!r) return;
    const int n = 2048;
    const double t0 = r->meridional.first_param(), t1 = r->meridional.last_param();
    for (int k = 0; k <= n; ++k) meridional_.push_back(r->meridional.point(t0 + (t1 - t0) * k / n));
    double step = 0;
    for (std::size_t k = 1; k < meridional_.size(); ++k) step = std::max(step, (meridional_[k] - meridional_[k - 1]).norm());
    pad_ += step;
  }

  bool may_meet(const Bnd_Box& box) const {
    if (box.IsVoid()) return false;
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    if (const auto* p = std::get_if<PlaneCut>(&surface_.surface)) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d c(k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0);
        const double d = (c - p->origin).dot(p->normal);
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
      return lo <= pad_ && hi >= -pad_;
    }
    // Distance range of the box from the x axis: nearest and farthest point of the (y, z) rectangle.
    const double ny = y0 > 0 ? y0 : (y1 < 0 ? y1 : 0), nz = z0 > 0 ? z0 : (z1 < 0 ? z1 : 0);
    const double fy = std::max(std::abs(y0), std::abs(y1)), fz = std::max(std::abs(z0), std::abs(z1));
    const double r0 = std::hypot(ny, nz) - pad_, r1 = std::hypot(fy, fz) + pad_;
    const double xa = x0 - pad_, xb = x1 + pad_;
    for (std::size_t k = 1; k < meridional_.size(); ++k) {
      const Eigen::Vector2d& a = meridional_[k - 1];
      const Eigen::Vector2d& b = meridional_[k];
      if (std::max(a.x(), b.x()) >= xa && std::min(a.x(), b.x()) <= xb && std::max(a.y(), b.y()) >= r0 &&
          std::min(a.y(), b.y()) <= r1)
        return true;
    }
    return false;
  }

 private:
  const SectionSurface& surface_;
  double pad_;
  std::vector<Eigen::Vector2d> meridional_;  ///< (x, r)
};

// The angles (about the x axis, relative to the cut's theta_centre) the boxes span, widened by 1 deg and
// kept within +-90 deg; +-90 deg when a box reaches the axis.
std::pair<double, double> angular_range(const RevolvedCut& r, const std::vector<Bnd_Box>& boxes) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Bnd_Box& b : boxes) {
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    if (y0 <= 0 && y1 >= 0 && z0 <= 0 && z1 >= 0) return {-kPi / 2, kPi / 2};
    for (int k = 0; k < 4; ++k) {  // a rectangle clear of the origin sees its extreme angles at corners
      const double a = std::remainder(std::atan2(k & 2 ? z1 : z0, k & 1 ? y1 : y0) - r.theta_centre, 2 * kPi);
      lo = std::min(lo, a), hi = std::max(hi, a);
    }
  }
  const double margin = kPi / 180;
  if (!(hi - lo < kPi)) return {-kPi / 2, kPi / 2};
  return {std::max(-kPi / 2, lo - margin), std::min(kPi / 2, hi + margin)};
}

struct BodyFaces {
  std::vector<const brep::NamedFace*> faces;
  std::vector<Bnd_Box> boxes;
};

// The section curves of one body with one surface: BRepAlgoAPI_Section of the faces the surface can
// meet (a copy of them, so sections can run side by side and the part is left untouched).
std::vector<SectionCurve> section_curves(const BodyFaces& body, int b, const std::string& body_name,
                                         const SectionSurface& s, TopoDS_Face tool, double size, double deflection) {
  const FaceFilter filter(s, size);
  TopoDS_Compound faces;
  BRep_Builder builder;
  builder.MakeCompound(faces);
  std::vector<const brep::NamedFace*> kept;
  std::vector<Bnd_Box> kept_boxes;
  for (std::size_t i = 0; i < body.faces.size(); ++i)
    if (filter.may_meet(body.boxes[i])) {
      builder.Add(faces, body.faces[i]->face);
      kept.push_back(body.faces[i]);
      kept_boxes.push_back(body.boxes[i]);
    }
  std::vector<SectionCurve> curves;
  if (kept.empty()) return curves;
  // A surface of revolution only over the angles the kept faces span: its box then holds a thin shell
  // of the blade, and edges away from it are not intersected at all (10x faster on the cooled example;
  // the curves are the same up to the approximation of the walking lines, see the commit).
  if (const auto* r = std::get_if<RevolvedCut>(&s.surface)) {
    const auto [a0, a1] = angular_range(*r, kept_boxes);
    tool = cutting_face(s, size, a0, a1);
  }
  BRepBuilderAPI_Copy copy(faces, /*copyGeom=*/false, /*copyMesh=*/false);
  NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher> name_of;
  for (const brep::NamedFace* f : kept) name_of.Bind(copy.ModifiedShape(f->face), f->name);
  BRepAlgoAPI_Section sec(copy.Shape(), tool, /*PerformNow=*/false);
  sec.ComputePCurveOn1(false);
  // Curves on the cutting surface too: without them OCCT measures each section curve's tolerance by
  // projecting points onto the surface of revolution, and rebuilds its search grid for every point
  // (Extrema_ExtPRevS; 6x the time of the section itself measured on the cooled example).
  sec.ComputePCurveOn2(true);
  sec.Approximation(true);  // without it the walking lines of the revolved cuts leave gaps between edges
  sec.Build();
  if (!sec.IsDone() || sec.HasErrors())
    throw ExportError("section of body \"" + body_name + "\" at span " + std::to_string(s.span) + " failed");
  for (TopExp_Explorer e(sec.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    TopoDS_Shape face;
    SectionCurve c;
    c.body = b;
    if (sec.HasAncestorFaceOn1(edge, face))
      if (const std::string* n = name_of.Seek(face)) c.name = *n;
    BRepAdaptor_Curve curve(edge);
    GCPnts_TangentialDeflection d(curve, 0.05, deflection, 4);
    for (int k = 1; k <= d.NbPoints(); ++k) c.points.push_back(to_2d(s, d.Value(k)));
    curves.push_back(std::move(c));
  }
  return curves;
}

}  // namespace

std::vector<SectionCut> cut_sections(const brep::Part& part, const std::vector<SectionSurface>& surfaces, double deflection) {
  if (part.empty()) throw ExportError("sections: empty part");
  double size = 0;  // for the plane's extent and the chaining tolerance
  std::vector<BodyFaces> bodies(part.size());
  for (std::size_t b = 0; b < part.size(); ++b) {
    Bnd_Box box;
    BRepBndLib::Add(part[b].geometry.shape, box);
    size = std::max(size, std::sqrt(box.SquareExtent()));
    for (const brep::NamedFace& f : part[b].geometry.faces) {
      Bnd_Box fb;
      BRepBndLib::Add(f.face, fb);  // enlarged by the tolerances of the face and its edges and vertices
      bodies[b].faces.push_back(&f);
      bodies[b].boxes.push_back(fb);
    }
  }
  // Every (surface, body) section is independent: they run on all cores, results kept in order.
  const std::size_t tasks = surfaces.size() * part.size();
  std::vector<TopoDS_Face> tools;
  for (const SectionSurface& s : surfaces) tools.push_back(cutting_face(s, 10 * size + 1));
  std::vector<std::vector<SectionCurve>> curves(tasks);
  parallel_for(static_cast<int>(tasks), parallel_workers(), [&](int k, int) {
    const std::size_t si = static_cast<std::size_t>(k) / part.size(), b = static_cast<std::size_t>(k) % part.size();
    curves[static_cast<std::size_t>(k)] =
        section_curves(bodies[b], static_cast<int>(b), part[b].name, surfaces[si], tools[si], size, deflection);
  });

  std::vector<SectionCut> cuts;
  for (std::size_t si = 0; si < surfaces.size(); ++si) {
    SectionCut cut;
    cut.span = surfaces[si].span;
    for (std::size_t b = 0; b < part.size(); ++b) {
      std::vector<SectionCurve>& c = curves[si * part.size() + b];
      cut.curves.insert(cut.curves.end(), std::make_move_iterator(c.begin()), std::make_move_iterator(c.end()));
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
