#include "features/passage_checks.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <IntTools_Curve.hxx>
#include <IntTools_FaceFace.hxx>
#include <IntTools_SequenceOfCurves.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <ShapeFix_Face.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "adaptors/occt_convert.hpp"
#include "features/face_names.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

bool matches(const std::string& name, const std::vector<std::string>& patterns) {
  for (const std::string& p : patterns) {
    if (!p.empty() && p.back() == '*') {
      if (name.compare(0, p.size() - 1, p, 0, p.size() - 1) == 0) return true;
    } else if (name == p) {
      return true;
    }
  }
  return false;
}

TopoDS_Compound compound_of(const std::vector<TopoDS_Face>& faces) {
  BRep_Builder bb;
  TopoDS_Compound c;
  bb.MakeCompound(c);
  for (const auto& f : faces) bb.Add(c, f);
  return c;
}

std::vector<TopoDS_Face> faces_named(const brep::NamedShape& s, const std::vector<std::string>& patterns) {
  std::vector<TopoDS_Face> out;
  for (const auto& f : s.faces)
    if (matches(f.name, patterns)) out.push_back(f.face);
  return out;
}

double tolerance_for(double configured) { return std::max(0.01, 0.01 * configured); }

// Points on a face: a uv grid kept where inside the face's boundary.
std::vector<Vec3> face_samples(const TopoDS_Face& f, int n) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(f, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d cls(f, 1e-9);
  const Handle(Geom_Surface) s = BRep_Tool::Surface(f);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / n, v = v0 + (v1 - v0) * (j + 0.5) / n;
      if (cls.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      const gp_Pnt p = s->Value(u, v);
      out.emplace_back(p.X(), p.Y(), p.Z());
    }
  return out;
}

}  // namespace

gp_Pln passage_section_plane(const blade::BladeModel& m, const TopoDS_Shape& cooled, double span) {
  Bnd_Box box;
  BRepBndLib::Add(cooled, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  if (m.trim.straight) {
    const double z = m.trim.hub_z + span * (m.trim.casing_z - m.trim.hub_z);
    return gp_Pln(gp_Pnt(0.5 * (x0 + x1), 0.5 * (y0 + y1), z), gp::DZ());
  }
  const blade::BladeCoordinates coords(m);
  const Vec3 c(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1));
  const Vec3 er = Vec3(0, c.y(), c.z()).normalized();
  const Vec3 p = 0.5 * (coords.frame(span, 0.5).point + coords.frame(span, -0.5).point);
  const double r = p.dot(er);
  return gp_Pln(gp_Pnt(c.x(), r * er.y(), r * er.z()), gp_Dir(0, er.y(), er.z()));
}

ThicknessMeasure measure_between(const brep::NamedShape& shape, const std::string& feature,
                                 const std::vector<std::string>& side_a, const std::vector<std::string>& side_b,
                                 double configured) {
  ThicknessMeasure t;
  t.feature = feature;
  t.configured = configured;
  t.tolerance = tolerance_for(configured);
  t.method = "BRepExtrema_DistShapeShape";
  const auto a = faces_named(shape, side_a), b = faces_named(shape, side_b);
  if (a.empty() || b.empty()) throw FeatureFailure("thickness of " + feature + ": no faces on one side");
  BRepExtrema_DistShapeShape d(compound_of(a), compound_of(b));
  if (!d.IsDone()) throw FeatureFailure("thickness of " + feature + ": BRepExtrema_DistShapeShape failed");
  t.min = d.Value();
  t.passed = t.min >= configured - t.tolerance;
  return t;
}

namespace {

// A piece of a section loop on one face: its end points, the line integral of (x dy - y dx) in the
// plane's frame along it (twice the signed area it contributes, by Green's theorem) and its length.
struct SectionPiece {
  Vec3 first, last;
  double green = 0, length = 0;
  int passage = -1;
};

// Composite Gauss-Legendre (16 intervals x 5 points) of the Green integrand and the speed along
// c3 on [a, b].
void integrate_piece(const Geom_Curve& c3, double a, double b, const Vec3& ex, const Vec3& ey, SectionPiece& p) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  const int m = 16;
  const double h = (b - a) / m;
  for (int i = 0; i < m; ++i)
    for (int k = 0; k < 5; ++k) {
      const double t = a + h * (i + 0.5 * (x[k] + 1));
      gp_Pnt q;
      gp_Vec d;
      c3.D1(t, q, d);
      const Vec3 P(q.X(), q.Y(), q.Z()), D(d.X(), d.Y(), d.Z());
      p.green += 0.5 * h * w[k] * (P.dot(ex) * D.dot(ey) - P.dot(ey) * D.dot(ex));
      p.length += 0.5 * h * w[k] * D.norm();
    }
}

// The intersection of one face with the section plane, clipped to the face's boundary. The curves come
// from IntTools_FaceFace (approximated within 1e-7 mm, with their curves on the face); the parameter
// ranges inside the face are found by the face's 2D classifier on 256 steps, each boundary crossing
// refined by bisection; every inside range is integrated exactly (Gauss) for area and length.
void face_section(const TopoDS_Face& face, BRepTopAdaptor_FClass2d& cls, const TopoDS_Face& plane, int passage,
                  const Vec3& ex, const Vec3& ey, std::vector<SectionPiece>& out) {
  IntTools_FaceFace ff;
  ff.SetParameters(true, true, false, 1e-7);
  ff.Perform(face, plane);
  if (!ff.IsDone()) throw FeatureFailure("passage cross-sections: a face-plane intersection failed");
  for (const IntTools_Curve& ic : ff.Lines()) {
    const Handle(Geom_Curve) c3 = ic.Curve();
    const Handle(Geom2d_Curve) c2 = ic.FirstCurve2d();
    if (c3.IsNull() || c2.IsNull()) continue;
    const double t0 = c3->FirstParameter(), t1 = c3->LastParameter();
    auto in = [&](double t) { return cls.Perform(c2->Value(t)) != TopAbs_OUT; };
    auto point = [&](double t) {
      const gp_Pnt q = c3->Value(t);
      return Vec3(q.X(), q.Y(), q.Z());
    };
    auto crossing = [&](double a, double b) {  // in(a) != in(b): bisection on the classifier
      const bool ia = in(a);
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (a + b);
        (in(mid) == ia ? a : b) = mid;
      }
      return 0.5 * (a + b);
    };
    auto emit = [&](double a, double b) {
      if (!(b > a)) return;
      SectionPiece p;
      p.passage = passage;
      p.first = point(a);
      p.last = point(b);
      integrate_piece(*c3, a, b, ex, ey, p);
      out.push_back(p);
    };
    const int n = 256;
    bool inside = in(t0);
    double start = t0, prev = t0;
    for (int k = 1; k <= n; ++k) {
      const double t = t0 + (t1 - t0) * k / n;
      const bool cur = in(t);
      if (cur != inside) {
        const double x = crossing(prev, t);
        if (inside) emit(start, x);
        start = x;
        inside = cur;
      }
      prev = t;
    }
    if (inside) emit(start, t1);
  }
}

// Joins pieces into closed loops (end points within `tol`), summing their Green integrals with the
// sign of the direction they are traversed in.
std::vector<SectionPiece> join_loops(const std::vector<SectionPiece>& pieces, double tol) {
  std::vector<SectionPiece> loops;
  std::vector<bool> used(pieces.size(), false);
  for (std::size_t s = 0; s < pieces.size(); ++s) {
    if (used[s]) continue;
    used[s] = true;
    SectionPiece loop = pieces[s];
    while ((loop.last - loop.first).norm() > tol) {
      bool grown = false;
      for (std::size_t k = 0; k < pieces.size() && !grown; ++k) {
        if (used[k]) continue;
        const SectionPiece& p = pieces[k];
        const bool fwd = (p.first - loop.last).norm() <= tol, rev = (p.last - loop.last).norm() <= tol;
        if (!fwd && !rev) continue;
        loop.green += fwd ? p.green : -p.green;
        loop.length += p.length;
        loop.last = fwd ? p.last : p.first;
        if (loop.passage < 0) loop.passage = p.passage;
        used[k] = grown = true;
      }
      if (!grown)
        throw FeatureFailure("passage cross-sections: a section loop does not close (gap " +
                             std::to_string((loop.last - loop.first).norm()) + " mm)");
    }
    loops.push_back(loop);
  }
  return loops;
}

}  // namespace

std::vector<PassageMeasure> passage_sections(const blade::BladeModel& model, const brep::NamedShape& cooled,
                                             const std::vector<double>& spans,
                                             const std::vector<std::string>& passages) {
  std::vector<PassageMeasure> out(passages.size());
  for (std::size_t k = 0; k < passages.size(); ++k) out[k].name = passages[k];
  if (passages.empty()) return out;
  Bnd_Box box;
  BRepBndLib::Add(cooled.shape, box);
  // Passage of a face: chamber_<k>_wall -> chamber_<k>; a radial passage's faces carry its name.
  auto passage_of = [&](const std::string& face) -> int {
    std::string p = face;
    if (p.rfind("chamber_", 0) == 0 && p.size() > 5 && p.compare(p.size() - 5, 5, "_wall") == 0) p.resize(p.size() - 5);
    const auto it = std::find(passages.begin(), passages.end(), p);
    return it == passages.end() ? -1 : static_cast<int>(it - passages.begin());
  };
  std::vector<std::pair<TopoDS_Face, int>> bounding;  // faces that bound passages, with their passage
  std::vector<Bnd_Box> boxes;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;  // built on first use
  for (const auto& f : cooled.faces)
    if (passage_of(f.name) >= 0 || matches(f.name, {"rib_*", "turnaround_*", "inlet_*", "tip_cap", "hub_floor"})) {
      bounding.emplace_back(f.face, passage_of(f.name));
      boxes.emplace_back();
      BRepBndLib::Add(f.face, boxes.back());
      classifiers.emplace_back();
    }
  for (double span : spans) {
    const gp_Pln pln = passage_section_plane(model, cooled.shape, span);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const double h = 2 * std::max({x1 - x0, y1 - y0, z1 - z0});
    const TopoDS_Face plane = BRepBuilderAPI_MakeFace(pln, -h, h, -h, h).Face();
    const gp_Dir xd = pln.XAxis().Direction(), yd = pln.YAxis().Direction();
    const Vec3 ex(xd.X(), xd.Y(), xd.Z()), ey(yd.X(), yd.Y(), yd.Z());
    std::vector<SectionPiece> pieces;
    for (std::size_t i = 0; i < bounding.size(); ++i) {
      // Skip faces entirely on one side of the plane (their box corners all on one side).
      double x0, y0, z0, x1, y1, z1;
      boxes[i].Get(x0, y0, z0, x1, y1, z1);
      int below = 0, above = 0;
      for (int c = 0; c < 8; ++c) {
        const gp_Pnt q(c & 1 ? x1 : x0, c & 2 ? y1 : y0, c & 4 ? z1 : z0);
        (gp_Vec(pln.Location(), q).Dot(gp_Vec(pln.Axis().Direction())) < 0 ? below : above)++;
      }
      if (below == 0 || above == 0) continue;
      if (!classifiers[i]) classifiers[i] = std::make_unique<BRepTopAdaptor_FClass2d>(bounding[i].first, 1e-9);
      face_section(bounding[i].first, *classifiers[i], plane, bounding[i].second, ex, ey, pieces);
    }
    std::vector<CrossSection> per(passages.size());
    for (const SectionPiece& loop : join_loops(pieces, 1e-4)) {
      if (loop.passage < 0) continue;
      per[static_cast<std::size_t>(loop.passage)].area += 0.5 * std::abs(loop.green);
      per[static_cast<std::size_t>(loop.passage)].wetted_perimeter += loop.length;
    }
    for (std::size_t q = 0; q < passages.size(); ++q) {
      CrossSection c = per[q];
      c.span = span;
      c.hydraulic_diameter = c.wetted_perimeter > 0 ? 4 * c.area / c.wetted_perimeter : 0;
      if (c.area > 0) out[q].sections.push_back(c);
    }
  }
  return out;
}

void measure_passages(const blade::BladeModel& model, const brep::NamedShape& cooled, const PassagesDefinition& def,
                      const CoreBuild* core, const RadialPassageBuild* radial, PassageReport& report) {
  // Cavities: a chamber system without an opening is a closed inner shell of the solid.
  int shells = 0;
  for (TopExp_Explorer e(cooled.shape, TopAbs_SHELL); e.More(); e.Next()) ++shells;
  report.closed_cavities = shells - 1;
  report.all_chambers_fed = report.closed_cavities == 0;

  std::vector<std::string> passages;
  std::vector<double> spans;
  if (core) {
    const CoreDefinition& cd = *def.core;
    report.inner_wall_poles_u = core->inner_wall.poles_u();
    report.inner_wall_poles_v = core->inner_wall.poles_v();
    report.inner_wall_fit_error = core->inner_wall.max_fit_error;
    // Outer wall: minimum by BRepExtrema between the outer wall and every face of the chambers;
    // maximum and the local value against a varying thickness from points on the chamber walls,
    // projected onto the outer wall (global projection, src/algo/project_point_surface).
    ThicknessMeasure wall = measure_between(cooled, "outer_wall", {"blade_wall"},
                                            {"chamber_*", "rib_*", "turnaround_*"}, cd.wall_thickness.min_value());
    const blade::BladeCoordinates coords(model);
    double max_d = 0, worst = 0;
    for (const auto& f : faces_named(cooled, {"chamber_*"}))
      for (const Vec3& p : face_samples(f, 10)) {
        const blade::BladeLocateResult r = coords.locate(p);
        if (!r.found) continue;
        max_d = std::max(max_d, r.coordinate.depth);
        worst = std::max(worst, cd.wall_thickness.at(r.coordinate.span, r.coordinate.chord) - r.coordinate.depth);
      }
    wall.max = max_d;
    wall.method += " (min); sampled projection onto the outer wall (max, local value)";
    wall.passed = wall.passed && worst <= wall.tolerance;
    report.thickness.push_back(wall);
    if (!cd.tip_cap.open)
      report.thickness.push_back(measure_between(cooled, "tip_cap", {"casing"}, {"tip_cap"}, cd.tip_cap.thickness));
    if (!cd.hub_floor.open)
      report.thickness.push_back(measure_between(cooled, "hub_floor", {"hub"}, {"hub_floor"}, cd.hub_floor.thickness));
    // Ribs: their two sides (faces named rib_<i>, told apart by the side of the mid-surface they lie on).
    for (std::size_t i = 0; i < cd.ribs.size(); ++i) {
      const std::string name = "rib_" + std::to_string(i + 1);
      const RibMidSurface mid(coords, cd.wall_thickness, cd.ribs[i]);
      std::vector<TopoDS_Face> le_side, te_side;
      for (const auto& f : faces_named(cooled, {name})) {
        const auto pts = face_samples(f, 5);
        if (pts.empty()) continue;
        const blade::BladeLocateResult r = coords.locate(pts.front());
        Vec3 n, t;
        mid.frame(0.5, r.coordinate.span, n, t);
        ((pts.front() - mid.point(0.5, r.coordinate.span)).dot(n) > 0 ? te_side : le_side).push_back(f);
      }
      ThicknessMeasure m;
      m.feature = name;
      m.configured = cd.ribs[i].thickness;
      m.tolerance = tolerance_for(m.configured);
      m.method = "BRepExtrema_DistShapeShape between its two sides";
      if (le_side.empty() || te_side.empty()) throw FeatureFailure(name + ": cannot find both of its sides on the blade");
      BRepExtrema_DistShapeShape d(compound_of(le_side), compound_of(te_side));
      m.min = d.IsDone() ? d.Value() : 0;
      double mx = 0;
      for (const auto& f : le_side)
        for (const Vec3& p : face_samples(f, 4)) {
          BRepExtrema_DistShapeShape dp(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z())).Vertex(), compound_of(te_side));
          if (dp.IsDone()) mx = std::max(mx, dp.Value());
        }
      m.max = mx;
      m.passed = m.min >= m.configured - m.tolerance;
      report.thickness.push_back(m);
    }
    // Volumes.
    report.volumes.push_back({"core", core->core_volume, "coolant + rib material before the ribs"});
    for (const auto& c : core->chambers) report.volumes.push_back({"chamber_" + std::to_string(c.number), c.volume, "coolant"});
    for (std::size_t i = 0; i < core->rib_volumes.size(); ++i) {
      report.volumes.push_back({"rib_" + std::to_string(i + 1), core->rib_volumes[i], "material"});
      report.volumes.push_back({"rib_" + std::to_string(i + 1) + "_fillets", core->fillet_volumes[i], "material"});
    }
    for (std::size_t m = 0; m < core->inlet_volumes.size(); ++m)
      report.volumes.push_back({"inlet_" + std::to_string(m + 1), core->inlet_volumes[m], "removed"});
    // Cross-sections on 10 spans where every rib is present (between the turnaround gaps).
    double lo = 0.05, hi = 0.95;
    for (const auto& r : core->ribs) {
      const std::size_t mid = r.stations.size() / 2;
      if (r.hub_junction[mid] > 0) lo = std::max(lo, r.hub_junction[mid] + 0.02);
      if (r.tip_junction[mid] < 1) hi = std::min(hi, r.tip_junction[mid] - 0.02);
    }
    for (int k = 0; k < 10; ++k) spans.push_back(lo + (hi - lo) * k / 9);
    for (const auto& c : core->chambers) {
      passages.push_back("chamber_" + std::to_string(c.number));
    }
  }
  if (radial) {
    for (std::size_t k = 0; k < radial->tools.size(); ++k) {
      const std::string name = radial->tools[k].feature;
      report.thickness.push_back(measure_between(cooled, name + "_wall", {"blade_wall"}, {name}, std::numeric_limits<double>::quiet_NaN()));
      ThicknessMeasure& t = report.thickness.back();
      t.passed = t.min > 0;
      t.tolerance = 0;
      report.volumes.push_back({name, radial->tools[k].expected_volume, "removed"});
      passages.push_back(name);
    }
    if (spans.empty())
      for (int k = 0; k < 10; ++k) spans.push_back(0.05 + 0.9 * k / 9);
  }
  std::vector<PassageMeasure> measured = passage_sections(model, cooled, spans, passages);
  for (auto& m : measured) {
    for (const auto& v : report.volumes)
      if (v.feature == m.name) m.volume = v.volume;
    if (core && m.name.rfind("chamber_", 0) == 0) {
      const int number = std::stoi(m.name.substr(8));
      const ChamberInfo& c = core->chambers[static_cast<std::size_t>(number - 1)];
      std::string fed;
      for (std::size_t in = 0; in < def.core->inlets.size(); ++in)
        if (def.core->inlets[in].chamber == number) fed += (fed.empty() ? "" : ", ") + std::string("inlet_") + std::to_string(in + 1);
      if (def.core->hub_floor.open) fed += std::string(fed.empty() ? "" : ", ") + "open hub";
      if (def.core->tip_cap.open) fed += std::string(fed.empty() ? "" : ", ") + "open tip";
      if (fed.empty() && c.fed) fed = "through turnarounds (" + core->systems[static_cast<std::size_t>(c.system)].feature + ")";
      m.fed_by = fed.empty() ? "none" : fed;
    } else {
      m.fed_by = "both ends open";
    }
  }
  report.passages = std::move(measured);
}

}  // namespace cg::features
