#include "features/passage_checks.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <IntTools_Curve.hxx>
#include <IntTools_FaceFace.hxx>
#include <IntTools_SequenceOfCurves.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TColStd_Array1OfReal.hxx>
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
#include <set>
#include <exception>
#include <memory>
#include <thread>

#include "adaptors/occt_convert.hpp"
#include "features/face_names.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/core/newton.hpp"

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

namespace {
gp_Pln section_plane(const blade::BladeModel& m, const blade::BladeCoordinates& coords, const Bnd_Box& box,
                     double span) {
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  if (m.trim.straight) {
    const double z = m.trim.hub_z + span * (m.trim.casing_z - m.trim.hub_z);
    return gp_Pln(gp_Pnt(0.5 * (x0 + x1), 0.5 * (y0 + y1), z), gp::DZ());
  }
  const Vec3 c(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1));
  const Vec3 er = Vec3(0, c.y(), c.z()).normalized();
  const Vec3 p = 0.5 * (coords.frame(span, 0.5).point + coords.frame(span, -0.5).point);
  const double r = p.dot(er);
  return gp_Pln(gp_Pnt(c.x(), r * er.y(), r * er.z()), gp_Dir(0, er.y(), er.z()));
}
}  // namespace

gp_Pln passage_section_plane(const blade::BladeModel& m, const TopoDS_Shape& cooled, double span) {
  Bnd_Box box;
  BRepBndLib::Add(cooled, box);
  const blade::BladeCoordinates coords(m);
  return section_plane(m, coords, box, span);
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
  BRepExtrema_DistShapeShape d;
  d.SetMultiThread(true);  // the face pairs on both cores; the same minimum
  d.LoadS1(compound_of(a));
  d.LoadS2(compound_of(b));
  d.Perform();
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
  ff.SetParameters(true, true, false, 1e-5);
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

// Plane sections of a B-spline face, on OCCT's evaluation of the face's surface: f(u, v) = n . (S(u, v) - o)
// sampled on a grid of four cells per knot span, its zero set traced by marching squares (crossings on
// the grid edges solved by bisection to 1e-13 of the edge), the polylines clipped to the face by its 2D
// classifier (crossings bisected, points pulled back onto f = 0 by Newton steps along grad f), chords
// refined until their midpoints lie within 1e-6 mm of the curve, and integrated as parabolic arcs
// through each chord's midpoint (Green's theorem, error O(h^4)). Exact-surface points throughout; far
// faster than a boolean section of the whole solid.
class BSplinePlaneSection {
 public:
  BSplinePlaneSection(const TopoDS_Face& face, const gp_Pln& pln) : s_(BRep_Tool::Surface(face)) {
    BRepTools::UVBounds(face, u0_, u1_, v0_, v1_);
    o_ = pln.Location();
    n_ = pln.Axis().Direction();
  }
  double f(double u, double v) const {
    const gp_Pnt p = s_.Value(u, v);
    return n_.X() * (p.X() - o_.X()) + n_.Y() * (p.Y() - o_.Y()) + n_.Z() * (p.Z() - o_.Z());
  }
  // Newton steps along grad f from (u, v) onto f = 0.
  gp_Pnt2d project(double u, double v) const {
    for (int it = 0; it < 8; ++it) {
      gp_Pnt p;
      gp_Vec du, dv;
      s_.D1(u, v, p, du, dv);
      const double fv = n_.X() * (p.X() - o_.X()) + n_.Y() * (p.Y() - o_.Y()) + n_.Z() * (p.Z() - o_.Z());
      const double gu = du.Dot(gp_Vec(n_)), gv = dv.Dot(gp_Vec(n_)), g2 = gu * gu + gv * gv;
      if (!(g2 > 0)) break;
      u = std::clamp(u - fv * gu / g2, u0_, u1_);
      v = std::clamp(v - fv * gv / g2, v0_, v1_);
      if (std::abs(fv) < 1e-12) break;
    }
    return gp_Pnt2d(u, v);
  }
  Vec3 point(const gp_Pnt2d& uv) const {
    const gp_Pnt p = s_.Value(uv.X(), uv.Y());
    return Vec3(p.X(), p.Y(), p.Z());
  }
  // Grid parameters along one direction: four per knot interval inside [a, b].
  std::vector<double> grid(bool along_u) const {
    std::vector<double> knots;
    const int n = along_u ? s_.NbUIntervals(GeomAbs_C2) : s_.NbVIntervals(GeomAbs_C2);
    TColStd_Array1OfReal t(1, n + 1);
    if (along_u) s_.UIntervals(t, GeomAbs_C2); else s_.VIntervals(t, GeomAbs_C2);
    const double a = along_u ? u0_ : v0_, b = along_u ? u1_ : v1_;
    knots.push_back(a);
    for (int i = 1; i <= n + 1; ++i)
      if (t(i) > a && t(i) < b) knots.push_back(t(i));
    knots.push_back(b);
    std::vector<double> g;
    const int per = knots.size() > 100 ? 2 : 4;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i)
      for (int k = 0; k < per; ++k) g.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / per);
    g.push_back(b);
    return g;
  }

 private:
  GeomAdaptor_Surface s_;
  double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0;
  gp_Pnt o_;
  gp_Dir n_;
};

void bspline_face_section(const TopoDS_Face& face, BRepTopAdaptor_FClass2d& cls, const gp_Pln& pln, int passage,
                          const Vec3& ex, const Vec3& ey, std::vector<SectionPiece>& out) {
  const BSplinePlaneSection ps(face, pln);
  const std::vector<double> gu = ps.grid(true), gv = ps.grid(false);
  const int nu = static_cast<int>(gu.size()), nv = static_cast<int>(gv.size());
  std::vector<double> fv(static_cast<std::size_t>(nu * nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) fv[static_cast<std::size_t>(i * nv + j)] = ps.f(gu[i], gv[j]);
  auto F = [&](int i, int j) { return fv[static_cast<std::size_t>(i * nv + j)]; };
  // Crossing points on grid edges, id: horizontal edge (i, j)-(i+1, j) -> 2 (i nv + j), vertical -> +1.
  std::map<long, gp_Pnt2d> cross;
  // The crossing on a grid edge whose ends differ in sign: Illinois regula falsi to the 6e-14 of the
  // edge that 44 bisection steps gave, in ~8 surface evaluations instead of 44.
  auto root = [&](double ua, double va, double ub, double vb, double fa, double fb) {
    const double m = newton::solve_bracketed_secant(
        [&](double t) { return ps.f(ua + t * (ub - ua), va + t * (vb - va)); }, 0.0, 1.0, fa, fb, 0x1p-44);
    return gp_Pnt2d(ua + m * (ub - ua), va + m * (vb - va));
  };
  auto edge_point = [&](long id) -> gp_Pnt2d {
    auto it = cross.find(id);
    if (it != cross.end()) return it->second;
    const long e = id / 2;
    const int i = static_cast<int>(e / nv), j = static_cast<int>(e % nv);
    const gp_Pnt2d p = (id % 2 == 0) ? root(gu[i], gv[j], gu[i + 1], gv[j], F(i, j), F(i + 1, j))
                                     : root(gu[i], gv[j], gu[i], gv[j + 1], F(i, j), F(i, j + 1));
    cross.emplace(id, p);
    return p;
  };
  auto sign_change = [](double a, double b) { return (a < 0) != (b < 0); };
  // Segments between crossing ids, cell by cell (marching squares; saddles split by the centre value).
  std::map<long, std::vector<long>> adj;
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      const long bottom = 2L * (i * nv + j), top = 2L * (i * nv + j + 1), left = 2L * (i * nv + j) + 1,
                 right = 2L * ((i + 1) * nv + j) + 1;
      std::vector<long> e;
      if (sign_change(F(i, j), F(i + 1, j))) e.push_back(bottom);
      if (sign_change(F(i + 1, j), F(i + 1, j + 1))) e.push_back(right);
      if (sign_change(F(i, j + 1), F(i + 1, j + 1))) e.push_back(top);
      if (sign_change(F(i, j), F(i, j + 1))) e.push_back(left);
      if (e.size() == 2) {
        adj[e[0]].push_back(e[1]);
        adj[e[1]].push_back(e[0]);
      } else if (e.size() == 4) {
        const double c = ps.f(0.5 * (gu[i] + gu[i + 1]), 0.5 * (gv[j] + gv[j + 1]));
        const bool pair_bottom_right = sign_change(c, F(i + 1, j));  // centre on the other side of that corner
        const long a1 = pair_bottom_right ? bottom : bottom, a2 = pair_bottom_right ? left : right;
        const long b1 = pair_bottom_right ? right : left, b2 = top;
        adj[a1].push_back(a2);
        adj[a2].push_back(a1);
        adj[b1].push_back(b2);
        adj[b2].push_back(b1);
      }
    }
  // Chain into polylines (open ones start at an end of degree 1).
  std::set<long> done;
  std::vector<std::vector<gp_Pnt2d>> lines;
  auto walk = [&](long start) {
    std::vector<gp_Pnt2d> line;
    long prev = -1, cur = start;
    while (cur >= 0 && !done.count(cur)) {
      done.insert(cur);
      line.push_back(edge_point(cur));
      long next = -1;
      for (long n : adj[cur])
        if (n != prev && !done.count(n)) {
          next = n;
          break;
        }
      if (next < 0)  // closed: back to the start
        for (long n : adj[cur])
          if (n == start && n != prev && line.size() > 2) line.push_back(edge_point(start));
      prev = cur;
      cur = next;
    }
    if (line.size() >= 2) lines.push_back(line);
  };
  for (const auto& [id, n] : adj)
    if (n.size() == 1 && !done.count(id)) walk(id);
  for (const auto& [id, n] : adj)
    if (!done.count(id)) walk(id);
  // Clip each polyline to the face and integrate the inside runs.
  auto inside = [&](const gp_Pnt2d& p) { return cls.Perform(p) != TopAbs_OUT; };
  // Where a polyline leaves the face, the section curve crosses one of the face's edges: the plane's
  // crossings of every edge (its pcurve sampled, then Illinois regula falsi) are the exact exit points,
  // computed once per face and plane. Bisection on the classifier (which near the boundary runs the
  // exact 2D intersector, ~40 times per exit) is the fallback when no single crossing lies on the chord.
  std::vector<gp_Pnt2d> exits;
  bool exits_found = false;
  auto edge_exits = [&] {
    exits_found = true;
    for (TopExp_Explorer x(face, TopAbs_EDGE); x.More(); x.Next()) {
      double a = 0, b = 0;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(x.Current()), face, a, b);
      if (pc.IsNull() || !(b > a)) continue;
      auto fe = [&](double t) {
        const gp_Pnt2d q = pc->Value(t);
        return ps.f(q.X(), q.Y());
      };
      constexpr int kSamples = 32;
      double t_prev = a, f_prev = fe(a);
      for (int k = 1; k <= kSamples; ++k) {
        const double t = a + (b - a) * k / kSamples, fv = fe(t);
        if ((f_prev < 0) != (fv < 0)) {
          const double r = newton::solve_bracketed_secant(fe, t_prev, t, f_prev, fv, 1e-15 * (std::abs(a) + std::abs(b) + (b - a)));
          exits.push_back(pc->Value(r));
        }
        t_prev = t;
        f_prev = fv;
      }
    }
  };
  auto boundary = [&](gp_Pnt2d a, gp_Pnt2d b) {  // inside(a) != inside(b)
    if (!exits_found) edge_exits();
    // The exit on the chord a-b: within a quarter of the chord's length of it (the curve between two
    // grid crossings stays far closer to its chord), and the only one there.
    const gp_Vec2d ab(a, b);
    const double len2 = ab.SquareMagnitude();
    int hits = 0;
    gp_Pnt2d hit;
    for (const gp_Pnt2d& q : exits) {
      const double t = len2 > 0 ? std::clamp(gp_Vec2d(a, q).Dot(ab) / len2, 0.0, 1.0) : 0.0;
      const gp_Pnt2d foot(a.X() + t * ab.X(), a.Y() + t * ab.Y());
      if (foot.SquareDistance(q) <= 0.0625 * len2) {
        ++hits;
        hit = q;
      }
    }
    if (hits == 1) return hit;
    const bool ia = inside(a);
    for (int it = 0; it < 40; ++it) {
      const gp_Pnt2d m = ps.project(0.5 * (a.X() + b.X()), 0.5 * (a.Y() + b.Y()));
      (inside(m) == ia ? a : b) = m;
    }
    return ps.project(0.5 * (a.X() + b.X()), 0.5 * (a.Y() + b.Y()));
  };
  auto emit = [&](const std::vector<gp_Pnt2d>& run) {
    if (run.size() < 2) return;
    SectionPiece piece;
    piece.passage = passage;
    piece.first = ps.point(run.front());
    piece.last = ps.point(run.back());
    auto to2 = [&](const Vec3& p) { return Eigen::Vector2d(p.dot(ex), p.dot(ey)); };
    auto cross2 = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
    for (std::size_t k = 0; k + 1 < run.size(); ++k) {
      // Refine the chord until its midpoint is within 1e-6 mm of the curve, then integrate each chord as
      // the parabola through its midpoint.
      std::vector<std::pair<gp_Pnt2d, gp_Pnt2d>> stack{{run[k], run[k + 1]}};
      while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        const gp_Pnt2d m = ps.project(0.5 * (a.X() + b.X()), 0.5 * (a.Y() + b.Y()));
        const Vec3 A = ps.point(a), B = ps.point(b), M = ps.point(m);
        const double sag = (M - 0.5 * (A + B)).norm();
        if (sag > 1e-6 && a.Distance(b) > 1e-12 && stack.size() < 64) {
          stack.push_back({m, b});
          stack.push_back({a, m});
          continue;
        }
        const Eigen::Vector2d a2 = to2(A), b2 = to2(B), c2 = 2 * to2(M) - 0.5 * (a2 + b2);
        piece.green += (2.0 / 3.0) * (cross2(a2, c2) + cross2(c2, b2)) + (1.0 / 3.0) * cross2(a2, b2);
        const double chord = (B - A).norm();
        piece.length += chord > 0 ? chord + (8.0 / 3.0) * sag * sag / chord : 0;
      }
    }
    out.push_back(piece);
  };
  for (const auto& line : lines) {
    std::vector<gp_Pnt2d> run;
    bool in = inside(line.front());
    if (in) run.push_back(line.front());
    for (std::size_t k = 1; k < line.size(); ++k) {
      const bool cur = inside(line[k]);
      if (cur != in) {
        const gp_Pnt2d x = boundary(line[k - 1], line[k]);
        run.push_back(x);
        if (in) {
          emit(run);
          run.clear();
        } else {
          run.assign(1, x);
        }
        in = cur;
      }
      if (cur) run.push_back(line[k]);
    }
    if (in) emit(run);
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
  for (const auto& f : cooled.faces)
    if (passage_of(f.name) >= 0 || matches(f.name, {"rib_*", "turnaround_*", "inlet_*", "tip_cap", "hub_floor"})) {
      bounding.emplace_back(f.face, passage_of(f.name));
      boxes.emplace_back();
      BRepBndLib::Add(f.face, boxes.back());
    }
  const blade::BladeCoordinates coords(model);
  std::vector<gp_Pln> planes;
  for (double span : spans) planes.push_back(section_plane(model, coords, box, span));
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double h = 2 * std::max({x1 - x0, y1 - y0, z1 - z0});
  // The sections are independent: two threads, each with its own face classifiers (OCCT's shapes and
  // geometry are only read).
  std::vector<std::vector<CrossSection>> per_span(spans.size(), std::vector<CrossSection>(passages.size()));
  auto work = [&](std::size_t first, std::size_t step) {
    std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers(bounding.size());
    for (std::size_t k = first; k < spans.size(); k += step) {
      const gp_Pln& pln = planes[k];
      const TopoDS_Face plane = BRepBuilderAPI_MakeFace(pln, -h, h, -h, h).Face();
      const gp_Dir xd = pln.XAxis().Direction(), yd = pln.YAxis().Direction();
      const Vec3 ex(xd.X(), xd.Y(), xd.Z()), ey(yd.X(), yd.Y(), yd.Z());
      std::vector<SectionPiece> pieces;
      for (std::size_t i = 0; i < bounding.size(); ++i) {
        // Skip faces entirely on one side of the plane (their box corners all on one side).
        double a0, b0, c0, a1, b1, c1;
        boxes[i].Get(a0, b0, c0, a1, b1, c1);
        int below = 0, above = 0;
        for (int c = 0; c < 8; ++c) {
          const gp_Pnt q(c & 1 ? a1 : a0, c & 2 ? b1 : b0, c & 4 ? c1 : c0);
          (gp_Vec(pln.Location(), q).Dot(gp_Vec(pln.Axis().Direction())) < 0 ? below : above)++;
        }
        if (below == 0 || above == 0) continue;
        if (!classifiers[i]) classifiers[i] = std::make_unique<BRepTopAdaptor_FClass2d>(bounding[i].first, 1e-9);
        if (BRepAdaptor_Surface(bounding[i].first, false).GetType() == GeomAbs_BSplineSurface)
          bspline_face_section(bounding[i].first, *classifiers[i], pln, bounding[i].second, ex, ey, pieces);
        else
          face_section(bounding[i].first, *classifiers[i], plane, bounding[i].second, ex, ey, pieces);
      }
      for (const SectionPiece& loop : join_loops(pieces, 1e-4)) {
        if (loop.passage < 0) continue;
        per_span[k][static_cast<std::size_t>(loop.passage)].area += 0.5 * std::abs(loop.green);
        per_span[k][static_cast<std::size_t>(loop.passage)].wetted_perimeter += loop.length;
      }
    }
  };
  std::exception_ptr failure;
  std::thread second([&] {
    try {
      work(1, 2);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    work(0, 2);
  } catch (...) {
    second.join();
    throw;
  }
  second.join();
  if (failure) std::rethrow_exception(failure);
  for (std::size_t k = 0; k < spans.size(); ++k)
    for (std::size_t q = 0; q < passages.size(); ++q) {
      CrossSection c = per_span[k][q];
      c.span = spans[k];
      c.hydraulic_diameter = c.wetted_perimeter > 0 ? 4 * c.area / c.wetted_perimeter : 0;
      if (c.area > 0) out[q].sections.push_back(c);
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
    ThicknessMeasure wall;
    if (std::isnan(report.wall_clearance)) {
      wall = measure_between(cooled, "outer_wall", {"blade_wall"}, {"chamber_*", "rib_*", "turnaround_*"},
                             cd.wall_thickness.min_value());
    } else {  // measured between the same faces when the chambers were inserted (passage_boolean.hpp)
      wall.feature = "outer_wall";
      wall.configured = cd.wall_thickness.min_value();
      wall.tolerance = tolerance_for(wall.configured);
      wall.min = report.wall_clearance;
      wall.passed = wall.min >= wall.configured - wall.tolerance;
      wall.method = "BRepExtrema_DistShapeShape";
    }
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
