#include "features/passages/section_trace.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "adaptors/occt_convert.hpp"
#include "src/brep/boolean/verified_boolean.hpp"
#include "src/core/newton.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kMaxStep = 1.0;     // mm
constexpr double kMinStep = 1e-4;    // mm
constexpr double kEndStep = 0.1;     // mm, longest first and last step of a piece (see follow)
constexpr double kMaxTurn = 0.1;     // rad per step
constexpr double kOnCurve = 1e-11;   // mm, Newton's target |g|
constexpr int kMaxSteps = 200000;


// A point of the zero set of f(u, v) = g(S(u, v)) on one surface with what the tracer needs there.
struct Node {
  gp_Pnt2d uv;
  Vec3 p = Vec3::Zero();
  Vec3 tangent = Vec3::Zero();  // S_u f_v - S_v f_u: along the curve, |.| = 3D speed of the uv step (f_v, -f_u)
  double g = 0, fu = 0, fv = 0;
  double t = 0;                 // streamline parameter of p (area coordinates)
};

class CurveTracer {
 public:
  CurveTracer(const TopoDS_Face& face, SpanSurfaceEvaluator& s, BRepTopAdaptor_FClass2d* cls)
      : surf_(face, /*restriction=*/false), s_(s), cls_(cls) {}

  Node eval(const gp_Pnt2d& uv) const {
    gp_Pnt p;
    gp_Vec su, sv;
    surf_.D1(uv.X(), uv.Y(), p, su, sv);
    Node n;
    n.uv = uv;
    n.p = occt::to_eigen(p);
    Vec3 grad;
    n.g = s_.value(n.p, &grad, &n.t);
    n.fu = grad.dot(occt::to_eigen(su));
    n.fv = grad.dot(occt::to_eigen(sv));
    n.tangent = occt::to_eigen(su) * n.fv - occt::to_eigen(sv) * n.fu;
    return n;
  }
  // Newton along grad f onto f = 0.
  std::optional<Node> correct(gp_Pnt2d uv) const {
    for (int it = 0; it < 16; ++it) {
      const Node n = eval(uv);
      if (std::abs(n.g) <= kOnCurve) return n;
      const double gg = n.fu * n.fu + n.fv * n.fv;
      if (!(gg > 0)) return std::nullopt;
      uv.SetCoord(uv.X() - n.g * n.fu / gg, uv.Y() - n.g * n.fv / gg);
    }
    const Node n = eval(uv);
    if (std::abs(n.g) <= 1e3 * kOnCurve) return n;
    return std::nullopt;
  }
  bool outside(const gp_Pnt2d& uv) const { return cls_ && cls_->Perform(uv) == TopAbs_OUT; }
  // q moved by whole periods of a periodic surface to lie nearest to `ref` in uv.
  gp_Pnt2d near(const gp_Pnt2d& ref, gp_Pnt2d q) const {
    if (surf_.IsUPeriodic()) q.SetX(q.X() + surf_.UPeriod() * std::round((ref.X() - q.X()) / surf_.UPeriod()));
    if (surf_.IsVPeriodic()) q.SetY(q.Y() + surf_.VPeriod() * std::round((ref.Y() - q.Y()) / surf_.VPeriod()));
    return q;
  }

 private:
  BRepAdaptor_Surface surf_;
  SpanSurfaceEvaluator& s_;
  BRepTopAdaptor_FClass2d* cls_;
};

// A point the trace may end at.
struct Target {
  gp_Pnt2d uv;
  Vec3 p;
  double t = 0;
  bool consumed = false;
};

void add_arc(SpanSurfaceEvaluator& s, const Vec3& a, double ta, const Vec3& m, double tm, const Vec3& b, double tb,
             SectionPiece& piece) {
  const Vec2 a2 = s.area_coordinates(a, ta), b2 = s.area_coordinates(b, tb), m2 = s.area_coordinates(m, tm);
  const Vec2 c2 = 2 * m2 - 0.5 * (a2 + b2);  // the quadratic Bezier's control point through m at its middle
  auto cross = [](const Vec2& x, const Vec2& y) { return x.x() * y.y() - x.y() * y.x(); };
  piece.green += (2.0 / 3.0) * (cross(a2, c2) + cross(c2, b2)) + (1.0 / 3.0) * cross(a2, b2);
  const double chord = (b - a).norm(), sag = (m - 0.5 * (a + b)).norm();
  piece.length += chord > 0 ? chord + (8.0 / 3.0) * sag * sag / chord : 0;
  piece.points.push_back(m);
  piece.points.push_back(b);
}

enum class TraceEnd { Target, WrongWay, Lost };

// Follows the curve from `start` (on it) in direction `sign` until it reaches an unconsumed target
// (returned in `reached`; with `closing` >= 0, that target only after a few steps: a closed curve).
// Appends the arcs to `piece`, whose first point the caller has set. The first and the last step are
// at most kEndStep long: a piece starts and ends at its crossings' points on the edges, which lie up to
// the edge tolerance off the face; that offset then changes the area by at most tolerance x step.
TraceEnd follow(const CurveTracer& tr, SpanSurfaceEvaluator& s, Node cur, double sign, std::vector<Target>& targets,
                int closing, double max_length, SectionPiece& piece, int& reached, std::string& why) {
  auto unit = [&](const Node& n) { return Vec3(sign * n.tangent.normalized()); };
  Vec3 T = unit(cur);
  double h = 0.05, travelled = 0;
  for (int step = 0; step < kMaxSteps; ++step) {
    // A target ahead on the tangent within the step: the curve ends there.
    double d_near = HUGE_VAL, d_snap = HUGE_VAL;
    int snap = -1;
    for (std::size_t j = 0; j < targets.size(); ++j) {
      if (targets[j].consumed) continue;
      if (static_cast<int>(j) == closing && step < 3) continue;
      const Vec3 r = targets[j].p - cur.p;
      const double d = r.norm(), along = r.dot(T);
      d_near = std::min(d_near, d);
      if (along > 0 && d <= std::min(h, kEndStep) && (r - along * T).norm() <= 0.05 * d + 1e-9 && d < d_snap) {
        d_snap = d;
        snap = static_cast<int>(j);
      }
    }
    auto finish = [&](int j) {
      Target& q = targets[static_cast<std::size_t>(j)];
      const gp_Pnt2d quv = tr.near(cur.uv, q.uv);
      const auto m = tr.correct(gp_Pnt2d(0.5 * (cur.uv.X() + quv.X()), 0.5 * (cur.uv.Y() + quv.Y())));
      const Node mid = m ? *m : cur;
      add_arc(s, cur.p, cur.t, mid.p, mid.t, q.p, q.t, piece);
      q.consumed = true;
      reached = j;
      return TraceEnd::Target;
    };
    if (snap >= 0) return finish(snap);
    // One step, halved until the corrector lands near the predicted point without turning too far.
    double hs = std::min(h, std::max(0.5 * d_near, kMinStep));
    Node next;
    for (;;) {
      const double c = sign * hs / cur.tangent.norm();
      const auto n = tr.correct(gp_Pnt2d(cur.uv.X() + c * cur.fv, cur.uv.Y() - c * cur.fu));
      bool ok = n.has_value();
      if (ok) {
        const double chord = (n->p - cur.p).norm(), cosine = unit(*n).dot(T);
        ok = chord <= 2 * hs && chord >= 0.25 * hs && cosine >= std::cos(2 * kMaxTurn);
      }
      if (ok || hs <= kMinStep) {
        if (!n) {
          why = "the corrector does not converge";
          return TraceEnd::Lost;
        }
        next = *n;
        break;
      }
      hs *= 0.5;
    }
    if (tr.outside(next.uv)) {
      // Left the face without reaching a crossing ahead: the nearest target within the step if any
      // (a crossing just off the tangent), else the curve runs the wrong way or is lost.
      int best = -1;
      double bd = 2 * hs;
      for (std::size_t j = 0; j < targets.size(); ++j)
        if (!targets[j].consumed && static_cast<int>(j) != closing && (targets[j].p - cur.p).norm() <= bd) {
          bd = (targets[j].p - cur.p).norm();
          best = static_cast<int>(j);
        }
      if (best >= 0) return finish(best);
      if (step == 0) return TraceEnd::WrongWay;
      why = "it leaves the face where no edge crossing was found";
      return TraceEnd::Lost;
    }
    const auto m = tr.correct(gp_Pnt2d(0.5 * (cur.uv.X() + next.uv.X()), 0.5 * (cur.uv.Y() + next.uv.Y())));
    add_arc(s, cur.p, cur.t, m ? m->p : Vec3(0.5 * (cur.p + next.p)), m ? m->t : next.t, next.p, next.t, piece);
    const double chord = (next.p - cur.p).norm();
    travelled += chord;
    if (travelled > max_length) {
      why = "it does not reach a crossing";
      return TraceEnd::Lost;
    }
    const Vec3 T1 = unit(next);
    const double turn = std::acos(std::clamp(T1.dot(T), -1.0, 1.0));
    h = std::min(kMaxStep, 1.5 * hs);
    if (turn > 0 && chord > 0) h = std::min(h, std::max(kMinStep, kMaxTurn * chord / turn));
    cur = next;
    T = T1;
  }
  why = "too many steps";
  return TraceEnd::Lost;
}

// The crossings of one edge with the surface: g along the edge's 3D curve, sampled (four per continuity
// interval, at least 12), each sign change solved by bracketed secant. Between samples of one sign an
// interval is split until |g| at its ends exceeds its length (g changes by at most the distance moved:
// no root inside) or it is shorter than 1e-7 mm: two crossings close together, where the cut just
// passes through a small hole's opening, are found as well.
void edge_crossings(const TopoDS_Edge& edge, int index, SpanSurfaceEvaluator& s, std::vector<SectionCrossing>& out) {
  if (BRep_Tool::Degenerated(edge)) return;
  const BRepAdaptor_Curve c(edge);
  const double a = c.FirstParameter(), b = c.LastParameter(), xtol = 1e-15 * (std::abs(a) + std::abs(b) + (b - a));
  auto g = [&](double t) { return s.value(occt::to_eigen(c.Value(t))); };
  struct Sample {
    double t, g;
    Vec3 p;
  };
  auto sample = [&](double t) {
    const Vec3 p = occt::to_eigen(c.Value(t));
    return Sample{t, s.value(p), p};
  };
  auto scan = [&](auto& self, const Sample& x, const Sample& y, int depth) -> void {
    if ((x.g < 0) != (y.g < 0)) {
      const double r = newton::solve_bracketed_secant(g, x.t, y.t, x.g, y.g, xtol);
      out.push_back({index, r, occt::to_eigen(c.Value(r))});
      return;
    }
    const Sample m = sample(0.5 * (x.t + y.t));
    const double arc = 1.05 * ((m.p - x.p).norm() + (y.p - m.p).norm());  // chords of halves turning < 20 deg
    if (std::abs(x.g) + std::abs(y.g) > arc || arc < 1e-7 || depth > 60) return;
    self(self, x, m, depth + 1);
    self(self, m, y, depth + 1);
  };
  const int n = std::clamp(4 * c.NbIntervals(GeomAbs_C2), 12, 1024);
  Sample prev = sample(a);
  for (int k = 1; k <= n; ++k) {
    const Sample cur = sample(a + (b - a) * k / n);
    scan(scan, prev, cur, 0);
    prev = cur;
  }
}

// uv grid lines of a face for the closed-curve seeds: two per knot interval (one beyond 32 intervals)
// of a B-spline surface, at least 12 intervals over the face's uv range.
std::vector<double> seed_grid(const TopoDS_Face& face, bool along_u) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const double a = along_u ? u0 : v0, b = along_u ? u1 : v1;
  std::vector<double> g;
  const BRepAdaptor_Surface sa(face, false);
  if (sa.GetType() == GeomAbs_BSplineSurface) {
    const int n = along_u ? sa.NbUIntervals(GeomAbs_C2) : sa.NbVIntervals(GeomAbs_C2);
    TColStd_Array1OfReal t(1, n + 1);
    if (along_u) sa.UIntervals(t, GeomAbs_C2); else sa.VIntervals(t, GeomAbs_C2);
    std::vector<double> knots{a};
    for (int i = 1; i <= n + 1; ++i)
      if (t(i) > a && t(i) < b) knots.push_back(t(i));
    knots.push_back(b);
    const int per = knots.size() > 33 ? 1 : 2;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i)
      for (int k = 0; k < per; ++k) g.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / per);
    g.push_back(b);
  }
  if (g.size() < 13) {
    g.clear();
    for (int k = 0; k <= 12; ++k) g.push_back(a + (b - a) * k / 12);
  }
  return g;
}

// The curves of one face: from its crossings, then the closed ones from grid seeds.
class FaceSection {
 public:
  FaceSection(const SectionBody& body, int face, SectionTrace& out, SpanSurfaceEvaluator& s, BRepTopAdaptor_FClass2d& cls)
      : nf_(body.shape->faces[static_cast<std::size_t>(face)]), face_(face), tr_(nf_.face, s, &cls), out_(out), s_(s),
        cls_(cls), first_piece_(out.pieces.size()) {}

  // From each crossing not yet reached into the face, to the crossing the curve gets to.
  void from_crossings(const std::vector<int>& verts) {
    std::vector<Target> targets;
    for (int v : verts) {
      const SectionCrossing& c = out_.crossings[static_cast<std::size_t>(vertex(v).crossing)];
      double t = 0;
      s_.value(c.point, nullptr, &t);
      targets.push_back({vertex(v).uv, c.point, t, false});
    }
    for (std::size_t k = 0; k < targets.size(); ++k) {
      if (targets[k].consumed) continue;
      targets[k].consumed = true;
      const SectionFaceVertex& fv = vertex(verts[k]);
      const auto start = tr_.correct(fv.uv);
      if (!start) fail("the corrector does not converge", targets[k].p);
      // Into the face: the curve's uv direction (f_v, -f_u) against the boundary's inward normal.
      double sign = start->fv * fv.inward.X() - start->fu * fv.inward.Y() >= 0 ? 1 : -1;
      // On a seam the crossing is on the face twice: the curve may end at its twin only after going round.
      int twin = -1;
      for (std::size_t j = 0; j < targets.size(); ++j)
        if (j != k && vertex(verts[j]).crossing == fv.crossing) twin = static_cast<int>(j);
      TraceEnd end = TraceEnd::WrongWay;
      SectionPiece piece;
      int reached = -1;
      std::string why;
      for (int attempt = 0; attempt < 2 && end == TraceEnd::WrongWay; ++attempt, sign = -sign) {
        piece = SectionPiece{};
        piece.face = face_;
        piece.points.push_back(targets[k].p);
        end = follow(tr_, s_, *start, sign, targets, twin, kMaxLength, piece, reached, why);
      }
      if (end != TraceEnd::Target) fail(end == TraceEnd::WrongWay ? "it leaves the face both ways" : why, targets[k].p);
      piece.first = fv.crossing;
      piece.last = vertex(verts[static_cast<std::size_t>(reached)]).crossing;
      out_.pieces.push_back(std::move(piece));
    }
  }

  // Closed curves inside the face: from sign changes of f along the grid lines that no traced piece
  // passes through.
  void closed_curves() {
    const std::vector<double> gu = seed_grid(nf_.face, true), gv = seed_grid(nf_.face, false);
    const std::size_t nv = gv.size();
    std::vector<double> f(gu.size() * nv);
    for (std::size_t i = 0; i < gu.size(); ++i)
      for (std::size_t j = 0; j < nv; ++j) f[i * nv + j] = tr_.eval(gp_Pnt2d(gu[i], gv[j])).g;
    for (std::size_t i = 0; i < gu.size(); ++i)
      for (std::size_t j = 0; j < nv; ++j) {
        const double fij = f[i * nv + j];
        if (i + 1 < gu.size() && (fij < 0) != (f[(i + 1) * nv + j] < 0))
          seed(gp_Pnt2d(gu[i], gv[j]), gp_Pnt2d(gu[i + 1], gv[j]), fij, f[(i + 1) * nv + j]);
        if (j + 1 < nv && (fij < 0) != (f[i * nv + j + 1] < 0))
          seed(gp_Pnt2d(gu[i], gv[j]), gp_Pnt2d(gu[i], gv[j + 1]), fij, f[i * nv + j + 1]);
      }
  }

 private:
  static constexpr double kMaxLength = 1e4;  // mm, no section curve is longer

  const SectionFaceVertex& vertex(int v) const { return out_.vertices[static_cast<std::size_t>(v)]; }

  [[noreturn]] void fail(const std::string& why, const Vec3& p) const {
    throw FeatureFailure("section at span " + format_number(s_.surface().span) + ": the curve on face " + nf_.name +
                         " from (" + format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) +
                         ") cannot be followed: " + why);
  }

  // Whether p lies on a piece this face traced (within the chords' sag: points 1 mm apart at most).
  bool on_traced(const Vec3& p) const {
    for (std::size_t k = first_piece_; k < out_.pieces.size(); ++k) {
      const auto& pts = out_.pieces[k].points;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec3 ab = pts[i + 1] - pts[i];
        const double t = ab.squaredNorm() > 0 ? std::clamp((p - pts[i]).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        if ((p - pts[i] - t * ab).norm() <= 1e-3 + 0.05 * ab.norm()) return true;
      }
    }
    return false;
  }

  // The root of f on the grid segment a-b; a closed curve traced from it when it is new.
  void seed(gp_Pnt2d a, gp_Pnt2d b, double fa, double fb) {
    auto at = [&](double x) { return gp_Pnt2d(a.X() + x * (b.X() - a.X()), a.Y() + x * (b.Y() - a.Y())); };
    const gp_Pnt2d uv = at(newton::solve_bracketed_secant([&](double x) { return tr_.eval(at(x)).g; }, 0.0, 1.0, fa, fb, 1e-13));
    if (cls_.Perform(uv) != TopAbs_IN) return;
    const auto n = tr_.correct(uv);
    if (!n || on_traced(n->p)) return;
    std::vector<Target> closing{{n->uv, n->p, n->t, false}};
    SectionPiece piece;
    piece.face = face_;
    piece.points.push_back(n->p);
    int reached = -1;
    std::string why;
    if (follow(tr_, s_, *n, 1, closing, 0, kMaxLength, piece, reached, why) != TraceEnd::Target)
      fail("a closed curve inside the face does not close" + (why.empty() ? std::string() : ": " + why), n->p);
    out_.pieces.push_back(std::move(piece));
  }

  const brep::NamedFace& nf_;
  int face_;
  CurveTracer tr_;
  SectionTrace& out_;
  SpanSurfaceEvaluator& s_;
  BRepTopAdaptor_FClass2d& cls_;
  std::size_t first_piece_;
};

}  // namespace

SectionBody::SectionBody(const brep::NamedShape& body) : shape(&body) {
  for (const brep::NamedFace& nf : body.faces) {
    Bnd_Box box;
    BRepBndLib::Add(nf.face, box);  // enlarged by the tolerances of the face and its edges and vertices
    face_boxes.push_back(box);
    std::vector<FaceEdge> fe;
    const TopoDS_Face fwd = TopoDS::Face(nf.face.Oriented(TopAbs_FORWARD));
    for (TopExp_Explorer e(fwd, TopAbs_EDGE); e.More(); e.Next()) {
      const TopAbs_Orientation o = e.Current().Orientation();
      if (o != TopAbs_FORWARD && o != TopAbs_REVERSED) continue;  // internal / external edges bound nothing
      const int index = edges.Add(e.Current());
      if (index > static_cast<int>(edge_boxes.size())) {
        Bnd_Box eb;
        BRepBndLib::Add(e.Current(), eb);
        edge_boxes.push_back(eb);
      }
      fe.push_back({index, o == TopAbs_REVERSED});
    }
    face_edges.push_back(std::move(fe));
    TopLoc_Location loc;
    surfaces.push_back(BRep_Tool::Surface(nf.face, loc));
    locations.push_back(loc);
  }
}

bool SectionBody::same_surface(int a, int b) const {
  const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  return surfaces[i] == surfaces[j] && locations[i].IsEqual(locations[j]);
}

BRepTopAdaptor_FClass2d& FaceClassifiers::of(int face) {
  auto& c = cls_[static_cast<std::size_t>(face)];
  if (!c) c = std::make_unique<BRepTopAdaptor_FClass2d>(body_->shape->faces[static_cast<std::size_t>(face)].face, 1e-9);
  return *c;
}

SectionTrace trace_section(const SectionBody& body, SpanSurfaceEvaluator& s, FaceClassifiers& classifiers) {
  SectionTrace out;
  std::vector<int> faces;
  for (std::size_t f = 0; f < body.face_boxes.size(); ++f)
    if (s.may_meet(body.face_boxes[f])) faces.push_back(static_cast<int>(f));
  // Crossings of every edge of those faces, once per edge.
  std::vector<std::vector<int>> of_edge(static_cast<std::size_t>(body.edges.Extent()) + 1);
  std::vector<char> done(of_edge.size(), 0);
  for (int f : faces)
    for (const SectionBody::FaceEdge& fe : body.face_edges[static_cast<std::size_t>(f)]) {
      if (done[static_cast<std::size_t>(fe.edge)]) continue;
      done[static_cast<std::size_t>(fe.edge)] = 1;
      if (!s.may_meet(body.edge_boxes[static_cast<std::size_t>(fe.edge - 1)])) continue;
      const std::size_t before = out.crossings.size();
      edge_crossings(TopoDS::Edge(body.edges(fe.edge)), fe.edge, s, out.crossings);
      for (std::size_t c = before; c < out.crossings.size(); ++c) of_edge[static_cast<std::size_t>(fe.edge)].push_back(static_cast<int>(c));
    }
  // Their places on each face, then the face's curves.
  for (int f : faces) {
    const brep::NamedFace& nf = body.shape->faces[static_cast<std::size_t>(f)];
    const TopoDS_Face fwd = TopoDS::Face(nf.face.Oriented(TopAbs_FORWARD));
    std::vector<int> verts;
    for (const SectionBody::FaceEdge& fe : body.face_edges[static_cast<std::size_t>(f)]) {
      const auto& cs = of_edge[static_cast<std::size_t>(fe.edge)];
      if (cs.empty()) continue;
      const TopoDS_Edge edge = TopoDS::Edge(body.edges(fe.edge).Oriented(fe.reversed ? TopAbs_REVERSED : TopAbs_FORWARD));
      double a = 0, b = 0;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, fwd, a, b);
      if (pc.IsNull())
        throw FeatureFailure("section at span " + std::to_string(s.surface().span) + ": an edge of face " + nf.name +
                             " has no curve on it");
      for (int c : cs) {
        gp_Pnt2d uv;
        gp_Vec2d d;
        pc->D1(out.crossings[static_cast<std::size_t>(c)].t, uv, d);
        if (fe.reversed) d.Reverse();
        verts.push_back(static_cast<int>(out.vertices.size()));
        out.vertices.push_back({f, c, uv, gp_Vec2d(-d.Y(), d.X())});  // the face lies left of its edges
      }
    }
    FaceSection fs(body, f, out, s, classifiers.of(f));
    fs.from_crossings(verts);
    fs.closed_curves();
  }
  return out;
}

std::optional<SectionPiece> trace_bridge(const SectionBody& body, const SectionFaceVertex& a, const SectionFaceVertex& b,
                                         const SectionTrace& trace, SpanSurfaceEvaluator& s) {
  const CurveTracer tr(body.shape->faces[static_cast<std::size_t>(a.face)].face, s, nullptr);
  const Vec3 pa = trace.crossings[static_cast<std::size_t>(a.crossing)].point;
  const Vec3 pb = trace.crossings[static_cast<std::size_t>(b.crossing)].point;
  const auto start = tr.correct(a.uv);
  if (!start) return std::nullopt;
  double tb = 0;
  s.value(pb, nullptr, &tb);
  std::vector<Target> targets{{b.uv, pb, tb, false}};
  SectionPiece piece;
  piece.face = a.face;
  piece.bridge = true;
  piece.points.push_back(pa);
  int reached = -1;
  std::string why;
  const double sign = start->tangent.dot(pb - pa) >= 0 ? 1 : -1;
  if (follow(tr, s, *start, sign, targets, -1, 4 * (pb - pa).norm() + 1, piece, reached, why) != TraceEnd::Target)
    return std::nullopt;
  piece.first = a.crossing;
  piece.last = b.crossing;
  return piece;
}

}  // namespace cg::features
