#include "src/brep/face_flux.hpp"

#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "adaptors/occt_convert.hpp"
#include "src/analyze/gauss_legendre.hpp"
#include "src/core/constants.hpp"
#include "src/core/newton.hpp"
#include "src/core/surface_evaluator.hpp"

namespace cg::brep {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr int kRule = 10;      // points of the boundary panels and of non-polynomial strip pieces
constexpr int kMaxDepth = 30;       // panel halvings (a kink of the integrand converges slowly, not never)
constexpr int kMaxPanels = 50000;  // per face (the cooled blades' faces take up to ~1000)

struct GaussRule {
  int n = 0;
  double x[16], w[16];
};

// Gauss-Legendre rules with 1..16 points on [-1, 1].
const GaussRule& gauss(int n) {
  static const std::array<GaussRule, 17> rules = [] {
    std::array<GaussRule, 17> r{};
    for (int k = 1; k <= 16; ++k) {
      r[static_cast<std::size_t>(k)].n = k;
      gauss_legendre(k, r[static_cast<std::size_t>(k)].x, r[static_cast<std::size_t>(k)].w);
    }
    return r;
  }();
  return rules[static_cast<std::size_t>(std::clamp(n, 1, 16))];
}

// Breaks of `knots` (distinct values) strictly inside (lo, hi), continued by `period` when > 0.
std::vector<double> breaks_inside(const std::vector<double>& knots, double period, double lo, double hi) {
  std::vector<double> out;
  if (knots.empty()) return out;
  const double k0 = knots.front();
  const int m0 = period > 0 ? static_cast<int>(std::floor((lo - k0) / period)) - 1 : 0;
  const int m1 = period > 0 ? static_cast<int>(std::ceil((hi - k0) / period)) + 1 : 0;
  for (int m = m0; m <= m1; ++m)
    for (double k : knots) {
      const double b = k + m * period;
      if (b > lo && b < hi) out.push_back(b);
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The face's surface: S, S_u, S_v, and per direction the pieces on which the strip rule is applied.
class FaceSurface {
 public:
  FaceSurface(const Handle(Geom_Surface)& s, const double range[2][2]) : adaptor_(s) {
    for (int d = 0; d < 2; ++d) {
      lo_[d] = range[d][0];
      hi_[d] = range[d][1];
    }
    if (adaptor_.GetType() == GeomAbs_BSplineSurface) {
      const Handle(Geom_BSplineSurface) bs = adaptor_.BSpline();
      auto shared = std::make_shared<const BSplineSurface<3>>(occt::from_occt(*bs));
      const BSplineSurface<3>& b = *shared;
      evaluator_.emplace(shared);
      for (int d = 0; d < 2; ++d) {
        const bool periodic = d == 0 ? b.is_periodic_u() : b.is_periodic_v();
        const double first = d == 0 ? b.first_u() : b.first_v(), last = d == 0 ? b.last_u() : b.last_v();
        period_[d] = periodic ? last - first : 0;
        domain_[d][0] = first;
        domain_[d][1] = last;
        const std::vector<double>& k = d == 0 ? b.knots_u() : b.knots_v();
        std::vector<double> distinct(k.begin(), k.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        // Every knot (a strip may pass the sampled range of the face a little), continued by the
        // period over the range and one period on each side.
        breaks_[d] = periodic ? breaks_inside(distinct, period_[d], lo_[d] - period_[d], hi_[d] + period_[d])
                              : std::vector<double>(distinct.begin() + 1, distinct.end() - 1);
        // g = (S - c) . (S_u x S_v) is a polynomial of degree 3p - 1 along a polynomial patch: the
        // ceil(3p / 2)-point rule is exact (up to p = 10, the 16-point rule; beyond, refined pieces).
        const int p = d == 0 ? b.degree_u() : b.degree_v();
        exact_[d] = !b.is_rational() && (3 * p + 1) / 2 <= 16;
        order_[d] = exact_[d] ? std::max(1, (3 * p + 1) / 2) : kRule;
      }
    } else {
      for (int d = 0; d < 2; ++d) {
        const bool periodic = d == 0 ? adaptor_.IsUPeriodic() : adaptor_.IsVPeriodic();
        period_[d] = periodic ? (d == 0 ? adaptor_.UPeriod() : adaptor_.VPeriod()) : 0;
        domain_[d][0] = d == 0 ? adaptor_.FirstUParameter() : adaptor_.FirstVParameter();
        domain_[d][1] = d == 0 ? adaptor_.LastUParameter() : adaptor_.LastVParameter();
        std::vector<double> cont;
        const int n = d == 0 ? adaptor_.NbUIntervals(GeomAbs_CN) : adaptor_.NbVIntervals(GeomAbs_CN);
        if (n > 1) {
          TColStd_Array1OfReal t(1, n + 1);
          d == 0 ? adaptor_.UIntervals(t, GeomAbs_CN) : adaptor_.VIntervals(t, GeomAbs_CN);
          for (int i = t.Lower(); i <= t.Upper(); ++i) cont.push_back(t(i));
        }
        breaks_[d] = breaks_inside(cont, 0, lo_[d], hi_[d]);
        order_[d] = kRule;
        // A plane is linear in both parameters: g is linear.
        exact_[d] = adaptor_.GetType() == GeomAbs_Plane;
        if (exact_[d]) order_[d] = 2;
      }
    }
  }

  void d1(double u, double v, Vec3& P, Vec3& Su, Vec3& Sv) {
    clamp(0, u);
    clamp(1, v);
    if (evaluator_) {
      evaluator_->d1(u, v, P, Su, Sv);
      return;
    }
    gp_Pnt p;
    gp_Vec a, b;
    adaptor_.D1(u, v, p, a, b);
    P = Vec3(p.X(), p.Y(), p.Z());
    Su = Vec3(a.X(), a.Y(), a.Z());
    Sv = Vec3(b.X(), b.Y(), b.Z());
  }

  /// Integral of g over s from x0 to x along direction d (d = 0: s is u, y is v), piece by piece;
  /// `size`: the integral of |S - c| |S_u x S_v| over the same strip (g's magnitude before the
  /// cancellation in the dot product: rounding errors scale with it).
  double strip(int d, double x0, double x, double y, const Vec3& c, double* size = nullptr) {
    return strip_with(d, breaks_[d], x0, x, y, c, size);
  }

  /// Makes the pieces of the non-exact directions fine enough: halving every piece must change the
  /// sample strips across the face by less than `tol` (relative to the strip's size, see strip()).
  void refine(const Vec3& c, double tol) {
    for (int d = 0; d < 2; ++d) {
      if (exact_[d]) continue;
      const double lo = lo_[d], hi = hi_[d];
      if (!(hi > lo)) continue;
      // Sample strips at the ends, the quarters and the middle of every piece of the other direction
      // (up to 33 of them): the integrand's difficulty follows the surface's spans there.
      std::vector<double> ys;
      {
        const double a = lo_[1 - d], b = hi_[1 - d];
        std::vector<double> pts{a};
        for (double t : breaks_[1 - d])
          if (t > a && t < b) pts.push_back(t);
        pts.push_back(b);
        for (std::size_t i = 0; i + 1 < pts.size(); ++i)
          for (int q = 0; q < 4; ++q) ys.push_back(pts[i] + 0.25 * q * (pts[i + 1] - pts[i]));
        ys.push_back(b);
        if (ys.size() > 33) {
          std::vector<double> few;
          for (int k = 0; k < 33; ++k) few.push_back(ys[k * (ys.size() - 1) / 32]);
          ys = few;
        }
      }
      // Start: pieces of at most a quarter turn in an analytic surface's periodic (angle) direction.
      const std::vector<double> base = breaks_[d];
      int pieces = period_[d] > 0 && !evaluator_ ? std::max(1, static_cast<int>(std::ceil((hi - lo) / (0.25 * kPi)))) : 1;
      for (int attempt = 0; attempt < 9; ++attempt) {
        const std::vector<double> coarse = subdivided(base, pieces, d), fine = subdivided(base, 2 * pieces, d);
        bool ok = true;
        for (std::size_t k = 0; k < ys.size() && ok; ++k) {
          double size = 0;
          const double a = strip_with(d, coarse, lo, hi, ys[k], c, nullptr);
          const double b = strip_with(d, fine, lo, hi, ys[k], c, &size);
          ok = std::abs(a - b) <= tol * std::max(size, 1e-300);
        }
        breaks_[d] = coarse;
        if (ok) break;
        pieces *= 2;
      }
    }
  }

  /// Cost of one strip across the face along d (evaluations).
  double cost(int d) const { return static_cast<double>(breaks_[d].size() + 1) * order_[d]; }
  /// Where the integrand's smoothness drops in direction d (knots, continuity breaks, refined pieces).
  const std::vector<double>& breaks(int d) const { return breaks_[d]; }

 private:
  void clamp(int d, double& t) const {
    if (period_[d] > 0) return;
    t = std::clamp(t, domain_[d][0], domain_[d][1]);
  }

  // `base` breaks plus each interval between consecutive breaks of [lo, hi] cut into `pieces`.
  std::vector<double> subdivided(const std::vector<double>& base, int pieces, int d) const {
    std::vector<double> pts{lo_[d]};
    pts.insert(pts.end(), base.begin(), base.end());
    pts.push_back(hi_[d]);
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      if (i > 0) out.push_back(pts[i]);
      for (int k = 1; k < pieces; ++k) out.push_back(pts[i] + (pts[i + 1] - pts[i]) * k / pieces);
    }
    return out;
  }

  double strip_with(int d, const std::vector<double>& br, double x0, double x, double y, const Vec3& c, double* abs_sum) {
    if (x == x0) return 0;
    const double sign = x > x0 ? 1.0 : -1.0;
    const double a = std::min(x0, x), b = std::max(x0, x);
    const GaussRule& r = gauss(order_[d]);
    double sum = 0, abs = 0;
    auto piece = [&](double p0, double p1) {
      const double h = 0.5 * (p1 - p0), m = 0.5 * (p0 + p1);
      double s = 0, sa = 0;
      Vec3 P, Su, Sv;
      for (int j = 0; j < r.n; ++j) {
        const double t = m + h * r.x[j];
        if (d == 0) d1(t, y, P, Su, Sv);
        else d1(y, t, P, Su, Sv);
        const double g = (P - c).dot(Su.cross(Sv));
        s += r.w[j] * g;
        if (abs_sum) sa += r.w[j] * (P - c).norm() * Su.cross(Sv).norm();
      }
      sum += h * s;
      abs += h * sa;
    };
    auto it = std::upper_bound(br.begin(), br.end(), a);
    double p0 = a;
    for (; it != br.end() && *it < b; ++it) {
      piece(p0, *it);
      p0 = *it;
    }
    piece(p0, b);
    if (abs_sum) *abs_sum = abs;
    // Direction d = 1 integrates in v: the u-v orientation of the domain flips the sign of the
    // boundary integral, applied by the caller; here only the strip's own direction.
    return sign * sum;
  }

  GeomAdaptor_Surface adaptor_;
  std::optional<SurfaceEvaluator<3>> evaluator_;
  double lo_[2] = {0, 0}, hi_[2] = {0, 0}, period_[2] = {0, 0}, domain_[2][2] = {{0, 0}, {0, 0}};
  std::vector<double> breaks_[2];
  int order_[2] = {kRule, kRule};
  bool exact_[2] = {false, false};
};

struct BoundaryEdge {
  Handle(Geom2d_Curve) curve;
  double a = 0, b = 0;
  double sign = 1;  // -1: the edge runs from b to a in the face
  int group = 0;    // its wire (the strips start at that wire's x0)
  std::vector<double> panels;  // a, breaks, b
  gp_Pnt2d start, end;         // in the face's direction
};

// A straight piece of the boundary between the end of one pcurve and the start of the next: pcurves
// meet only within their vertex's tolerance (up to ~1e-5 in the parameter plane after a boolean), and an
// open boundary's integral would depend on where the strips start.
struct Gap {
  gp_Pnt2d from, to;
  int group = 0;
};

FaceFlux occt_flux(const TopoDS_Face& face, const gp_Pnt& c, double eps) {
  BRepGProp_Face bf(face);
  BRepGProp_Vinert g;
  g.SetLocation(c);
  if (face.NbChildren() == 0) {
    BRepGProp_Domain none;
    g.Perform(bf, none, eps);
  } else {
    BRepGProp_Domain bd(face);
    g.Perform(bf, bd, eps);
  }
  return {g.Mass(), std::abs(g.GetEpsilon() * g.Mass()), false};
}

// Parameter breaks of a pcurve on [a, b]: its knots, or quarter turns of a conic.
std::vector<double> pcurve_panels(const Handle(Geom2d_Curve)& c, double a, double b) {
  std::vector<double> t{a};
  Geom2dAdaptor_Curve ad(c, a, b);
  if (ad.GetType() == GeomAbs_BSplineCurve) {
    const Handle(Geom2d_BSplineCurve) bs = ad.BSpline();
    for (int i = 1; i <= bs->NbKnots(); ++i) {
      const double k = bs->Knot(i);
      if (k > a && k < b) t.push_back(k);
    }
  } else if (ad.GetType() == GeomAbs_Circle || ad.GetType() == GeomAbs_Ellipse) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / (0.5 * kPi))));
    for (int k = 1; k < n; ++k) t.push_back(a + (b - a) * k / n);
  } else if (ad.GetType() != GeomAbs_Line) {
    const int n = ad.NbIntervals(GeomAbs_C2);
    if (n > 1) {
      TColStd_Array1OfReal iv(1, n + 1);
      ad.Intervals(iv, GeomAbs_C2);
      for (int i = iv.Lower() + 1; i < iv.Upper(); ++i)
        if (iv(i) > a && iv(i) < b) t.push_back(iv(i));
    }
    // Higher-order pcurves (offset, Bezier): at least 4 panels to start from.
    if (t.size() < 4) {
      t.assign(1, a);
      for (int k = 1; k < 4; ++k) t.push_back(a + (b - a) * k / 4);
    }
  }
  t.push_back(b);
  std::sort(t.begin(), t.end());
  return t;
}

// Adds to e.panels the parameters where the pcurve crosses u = b (b in ub) or v = b (b in vb).
void split_at_breaks(BoundaryEdge& e, const std::vector<double>& ub, const std::vector<double>& vb) {
  if (ub.empty() && vb.empty()) return;
  constexpr int kSamples = 8;  // per panel
  std::vector<double> ts;
  std::vector<gp_Pnt2d> ps;
  for (std::size_t k = 0; k + 1 < e.panels.size(); ++k)
    for (int j = 0; j < kSamples; ++j) ts.push_back(e.panels[k] + (e.panels[k + 1] - e.panels[k]) * j / kSamples);
  ts.push_back(e.panels.back());
  for (double t : ts) ps.push_back(e.curve->Value(t));
  std::vector<double> added;
  for (int d = 0; d < 2; ++d) {
    const std::vector<double>& br = d == 0 ? ub : vb;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const double c0 = ps[k].Coord(d + 1), c1 = ps[k + 1].Coord(d + 1);
      const double lo = std::min(c0, c1), hi = std::max(c0, c1);
      for (auto it = std::upper_bound(br.begin(), br.end(), lo); it != br.end() && *it < hi; ++it) {
        const double b = *it;
        const double tol = 1e-15 * (std::abs(ts[k]) + std::abs(ts[k + 1]) + 1);
        added.push_back(newton::solve_bracketed_secant([&](double t) { return e.curve->Value(t).Coord(d + 1) - b; },
                                                       ts[k], ts[k + 1], c0 - b, c1 - b, tol, 1e-14 * (std::abs(b) + 1)));
      }
    }
  }
  if (added.empty()) return;
  e.panels.insert(e.panels.end(), added.begin(), added.end());
  std::sort(e.panels.begin(), e.panels.end());
  // Drop panels shorter than 1e-12 of the edge (a crossing at a knot or at an end).
  const double tiny = 1e-12 * (e.b - e.a);
  std::vector<double> kept{e.panels.front()};
  for (std::size_t k = 1; k + 1 < e.panels.size(); ++k)
    if (e.panels[k] - kept.back() > tiny) kept.push_back(e.panels[k]);
  if (e.panels.back() - kept.back() <= tiny && kept.size() > 1) kept.pop_back();
  kept.push_back(e.panels.back());
  e.panels = std::move(kept);
}

// The boundary: pcurves in the forward face (material on the left), grouped by wire.
struct FaceBoundary {
  std::vector<BoundaryEdge> edges;
  std::vector<bool> closed;  // per wire: its pcurves return to their start (not around a period)
  double range[2][2] = {{1e300, -1e300}, {1e300, -1e300}};
  std::vector<std::array<double, 4>> wire_box;  // per wire: x range in u and in v
};

// The boundary of the forward face `fwd`; false when this integration does not take it (a child that
// is not a wire, an edge without a pcurve or not FORWARD / REVERSED, no edges): BRepGProp then.
bool face_boundary(const TopoDS_Face& fwd, FaceBoundary& fb) {
  std::vector<BoundaryEdge>& edges = fb.edges;
  int wire = 0;
  for (TopoDS_Iterator w(fwd); w.More(); w.Next(), ++wire) {
    if (w.Value().ShapeType() != TopAbs_WIRE) return false;
    Eigen::Vector2d sum(0, 0), extent(0, 0);
    bool wire_closed = true;
    std::array<double, 4> box{1e300, -1e300, 1e300, -1e300};
    for (TopExp_Explorer e(w.Value(), TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
      BoundaryEdge be;
      be.curve = BRep_Tool::CurveOnSurface(edge, fwd, be.a, be.b);
      if (be.curve.IsNull() || !(be.b > be.a)) return false;
      const TopAbs_Orientation o = edge.Orientation();
      if (o != TopAbs_FORWARD && o != TopAbs_REVERSED) return false;
      be.sign = o == TopAbs_REVERSED ? -1 : 1;
      be.group = wire;
      if (BRep_Tool::Degenerated(edge) || BRep_Tool::IsClosed(edge, fwd)) wire_closed = false;
      be.panels = pcurve_panels(be.curve, be.a, be.b);
      // The pcurve's extent from its panel ends and midpoints (the strips' start x0 needs only a
      // value inside the wire's range, the clamp below the surface's domain).
      for (std::size_t k = 0; k < be.panels.size(); ++k) {
        for (int half = 0; half < 2; ++half) {
          if (half == 1 && k + 1 == be.panels.size()) break;
          const double t = half == 0 ? be.panels[k] : 0.5 * (be.panels[k] + be.panels[k + 1]);
          const gp_Pnt2d q = be.curve->Value(t);
          box[0] = std::min(box[0], q.X());
          box[1] = std::max(box[1], q.X());
          box[2] = std::min(box[2], q.Y());
          box[3] = std::max(box[3], q.Y());
        }
      }
      gp_Pnt2d p0 = be.curve->Value(be.a), p1 = be.curve->Value(be.b);
      if (be.sign < 0) std::swap(p0, p1);
      be.start = p0;
      be.end = p1;
      const Eigen::Vector2d step(p1.X() - p0.X(), p1.Y() - p0.Y());
      sum += step;
      extent = extent.cwiseMax(step.cwiseAbs());
      edges.push_back(std::move(be));
    }
    fb.closed.push_back(wire_closed && sum.norm() <= 1e-6 * (1 + extent.norm()));
    fb.wire_box.push_back(box);
    fb.range[0][0] = std::min(fb.range[0][0], box[0]);
    fb.range[0][1] = std::max(fb.range[0][1], box[1]);
    fb.range[1][0] = std::min(fb.range[1][0], box[2]);
    fb.range[1][1] = std::max(fb.range[1][1], box[3]);
  }
  return !edges.empty();
}

// Close every wire: each pcurve's end joins the nearest start of its wire (the wire's order is not
// needed; every start is some edge's successor).
std::vector<Gap> closing_gaps(const std::vector<BoundaryEdge>& edges) {
  std::vector<Gap> gaps;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    std::size_t best = i;
    double dmin = 1e300;
    for (std::size_t j = 0; j < edges.size(); ++j) {
      if (edges[j].group != edges[i].group) continue;
      const double dist = edges[i].end.SquareDistance(edges[j].start);
      if (dist < dmin) {
        dmin = dist;
        best = j;
      }
    }
    if (dmin > 0) gaps.push_back({edges[i].end, edges[best].start, edges[i].group});
  }
  return gaps;
}

// Strip start per wire: its own middle if it is closed in the parameter plane, else the middle of
// all the other wires together (their integrals only add up to the face's as a whole).
std::vector<double> strip_starts(const FaceBoundary& fb, int d) {
  const std::vector<bool>& closed = fb.closed;
  std::vector<double> x0(closed.size());
  double open_lo = 1e300, open_hi = -1e300;
  for (std::size_t k = 0; k < closed.size(); ++k)
    if (!closed[k]) {
      open_lo = std::min(open_lo, fb.wire_box[k][2 * d]);
      open_hi = std::max(open_hi, fb.wire_box[k][2 * d + 1]);
    }
  for (std::size_t k = 0; k < closed.size(); ++k)
    x0[k] = closed[k] ? 0.5 * (fb.wire_box[k][2 * d] + fb.wire_box[k][2 * d + 1]) : 0.5 * (open_lo + open_hi);
  return x0;
}

// f(t) = G(x(t), y(t)) y'(t) along an edge, by the 10-point rule on [t0, t1]. A face that needs more
// than kMaxPanels panels (an integrand the rule cannot resolve) goes to BRepGProp instead.
struct BoundaryPanels {
  FaceSurface& S;
  int d;  // strips in u (0) or in v (1)
  const std::vector<double>& x0;
  const Vec3& c;
  const GaussRule& r;
  int panels = 0;

  double operator()(const BoundaryEdge& e, double t0, double t1, double* abs_sum) {
    const double h = 0.5 * (t1 - t0), m = 0.5 * (t0 + t1);
    if (++panels > kMaxPanels) throw std::runtime_error("face flux: panel budget exhausted");
    double s = 0, sa = 0;
    gp_Pnt2d q;
    gp_Vec2d dq;
    for (int j = 0; j < r.n; ++j) {
      e.curve->D1(m + h * r.x[j], q, dq);
      const double x = d == 0 ? q.X() : q.Y(), y = d == 0 ? q.Y() : q.X();
      const double dy = d == 0 ? dq.Y() : dq.X();
      if (dy == 0) continue;
      double size = 0;
      s += r.w[j] * S.strip(d, x0[static_cast<std::size_t>(e.group)], x, y, c, abs_sum ? &size : nullptr) * dy;
      sa += r.w[j] * size * std::abs(dy);
    }
    if (abs_sum) *abs_sum = h * sa;
    return h * s;
  }
};

// The boundary integral over the edges (relative accuracy eps), its error estimate into out.error.
double integrate_edges(BoundaryPanels& panel, const std::vector<BoundaryEdge>& edges, double eps, FaceFlux& out) {
  // First pass: every initial panel, and the scale of the integral (the boundary integral of the
  // strips' sizes: a face whose flux cancels to ~0, e.g. a plane through c, still has a finite target
  // above the rounding level).
  std::vector<std::vector<double>> whole(edges.size());
  double scale = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const BoundaryEdge& e = edges[i];
    for (std::size_t k = 0; k + 1 < e.panels.size(); ++k) {
      double a = 0;
      whole[i].push_back(panel(e, e.panels[k], e.panels[k + 1], &a));
      scale += a;
    }
  }
  const double tol = eps * scale;
  double total = 0;
  // Adaptive: a panel is accepted when its halves agree with it to its share of the tolerance.
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const BoundaryEdge& e = edges[i];
    const double width = e.b - e.a, share = tol / static_cast<double>(edges.size());
    struct Item {
      double t0, t1, value;
      int depth;
    };
    std::vector<Item> stack;
    for (std::size_t k = 0; k + 1 < e.panels.size(); ++k) stack.push_back({e.panels[k], e.panels[k + 1], whole[i][k], 0});
    double edge_sum = 0;
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const double tm = 0.5 * (it.t0 + it.t1);
      const double left = panel(e, it.t0, tm, nullptr), right = panel(e, tm, it.t1, nullptr);
      const double diff = std::abs(left + right - it.value);
      if (diff <= share * (it.t1 - it.t0) / width || it.depth >= kMaxDepth) {
        edge_sum += left + right;
        out.error += diff;
      } else {
        stack.push_back({tm, it.t1, right, it.depth + 1});
        stack.push_back({it.t0, tm, left, it.depth + 1});
      }
    }
    total += e.sign * edge_sum;
  }
  return total;
}

// The straight gaps' share of the boundary integral, added to `total`.
void add_gaps(BoundaryPanels& panel, const std::vector<Gap>& gaps, double& total) {
  const GaussRule& r = panel.r;
  const int d = panel.d;
  for (const Gap& g : gaps) {
    const double dx = g.to.X() - g.from.X(), dy = g.to.Y() - g.from.Y();
    const double w = d == 0 ? dy : dx;
    double s = 0;
    for (int j = 0; j < r.n; ++j) {
      const double t = 0.5 + 0.5 * r.x[j];
      const double u = g.from.X() + t * dx, v = g.from.Y() + t * dy;
      s += r.w[j] * panel.S.strip(d, panel.x0[static_cast<std::size_t>(g.group)], d == 0 ? u : v, d == 0 ? v : u, panel.c);
    }
    total += 0.5 * s * w;
  }
}

}  // namespace

FaceFlux face_volume_flux(const TopoDS_Face& face, const gp_Pnt& cp, double eps, StripDirection direction) {
  if (face.NbChildren() == 0) return occt_flux(face, cp, eps);
  const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(fwd);
  if (surface.IsNull()) return occt_flux(face, cp, eps);

  // The boundary: pcurves in the forward face (material on the left), grouped by wire.
  FaceBoundary fb;
  if (!face_boundary(fwd, fb)) return occt_flux(face, cp, eps);
  const std::vector<Gap> gaps = closing_gaps(fb.edges);

  try {
    FaceSurface S(surface, fb.range);
    const Vec3 c(cp.X(), cp.Y(), cp.Z());
    S.refine(c, 0.01 * eps);
    // Strips in the cheaper direction: d = 0 integrates in u (boundary integral of G dv), d = 1 in v
    // (boundary integral of -H du).
    const int d = direction == StripDirection::U ? 0 : direction == StripDirection::V ? 1 : S.cost(1) < S.cost(0) ? 1 : 0;
    const double dir_sign = d == 0 ? 1.0 : -1.0;
    // The boundary integrand G(x, y) y' is only as smooth as the surface across its knot lines: panels
    // also end where a pcurve crosses one (found between samples of the panel, by Illinois regula falsi).
    for (BoundaryEdge& e : fb.edges) split_at_breaks(e, S.breaks(0), S.breaks(1));
    const std::vector<double> x0 = strip_starts(fb, d);
    BoundaryPanels panel{S, d, x0, c, gauss(kRule)};
    FaceFlux out;
    double total = integrate_edges(panel, fb.edges, eps, out);
    add_gaps(panel, gaps, total);
    const double face_sign = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
    out.value = face_sign * dir_sign * total / 3;
    out.error /= 3;
    return out;
  } catch (const Standard_Failure&) {
    return occt_flux(face, cp, eps);
  } catch (const std::exception&) {
    return occt_flux(face, cp, eps);
  }
}

}  // namespace cg::brep
