#include "features/passages/section_surface.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <gp_Pln.hxx>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr int kSamples = 512;  // streamline samples: foot search start, area function nodes

}  // namespace

std::vector<SpanSurface> span_surfaces(const blade::BladeModel& model, const std::vector<double>& spans) {
  std::vector<SpanSurface> out;
  for (double s : spans) {
    if (!(s >= 0 && s <= 1)) throw InvalidGeometry("section span must be in [0, 1], got " + format_number(s));
    SpanSurface ss;
    ss.span = s;
    if (model.trim.straight) {
      ss.origin = Vec3(0, 0, model.trim.hub_z + s * (model.trim.casing_z - model.trim.hub_z));
    } else {
      if (!model.net) throw InvalidGeometry("meridional blade model without its meridional net");
      ss.kind = SpanSurfaceKind::Revolved;
      ss.meridional = std::make_shared<const BSplineCurve<2>>(model.net->streamline_at(s).curve());
      // The blade's mean angle at this span, from points around the section iso-curve v = s.
      double sy = 0, sz = 0;
      for (int k = 0; k < 16; ++k) {
        const Vec3 p = model.surface.point(k / 16.0, s);
        sy += p.y();
        sz += p.z();
      }
      ss.theta_centre = std::atan2(sz, sy);
    }
    out.push_back(std::move(ss));
  }
  return out;
}

SpanSurfaceEvaluator::SpanSurfaceEvaluator(const SpanSurface& surface) : surface_(surface) {
  if (surface_.kind == SpanSurfaceKind::Plane) {
    surface_.normal.normalize();
    surface_.x_axis = (surface_.x_axis - surface_.x_axis.dot(surface_.normal) * surface_.normal).normalized();
    y_axis_ = surface_.normal.cross(surface_.x_axis);
    pad_ = 1e-6;
    return;
  }
  require(surface_.meridional != nullptr, "revolved span surface without its meridional curve");
  curve_ = std::make_unique<CurveEvaluator<2>>(surface_.meridional);
  const double t0 = surface_.meridional->first_param(), t1 = surface_.meridional->last_param();
  // Area function F(t) = int r |C'| dt: 8-point Gauss-Legendre per sample interval (exact to rounding
  // for the smooth streamline), F' at the nodes for the cubic Hermite interpolation between them.
  static const double gx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double gw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  auto integrand = [&](double t) {
    Vec2 c, d;
    curve_->d1(t, c, d);
    return c.y() * d.norm();
  };
  double step = 0;
  monotone_x_ = true;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = t0 + (t1 - t0) * k / kSamples;
    ts_.push_back(t);
    pts_.push_back(curve_->point(t));
    darea_.push_back(integrand(t));
    if (k == 0) {
      area_.push_back(0);
      continue;
    }
    const double a = ts_[k - 1], h = 0.5 * (t - a), m = 0.5 * (t + a);
    double sum = 0;
    for (int i = 0; i < 4; ++i) sum += gw[i] * (integrand(m - h * gx[i]) + integrand(m + h * gx[i]));
    area_.push_back(area_.back() + h * sum);
    step = std::max(step, (pts_[k] - pts_[k - 1]).norm());
    monotone_x_ = monotone_x_ && pts_[k].x() > pts_[k - 1].x();
  }
  pad_ = 1e-6 + step;  // a smooth curve stays within half a sample step of its chords
}

double SpanSurfaceEvaluator::foot_parameter(const Vec2& q) {
  // Start: the nearest sample (by x on an x-monotone streamline, else by distance), then Newton on
  // (C(t) - q) . C'(t) = 0.
  std::size_t best = 0;
  if (monotone_x_) {
    const auto it = std::lower_bound(pts_.begin(), pts_.end(), q.x(), [](const Vec2& p, double x) { return p.x() < x; });
    best = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(it - pts_.begin(), 0, static_cast<std::ptrdiff_t>(pts_.size()) - 1));
    for (std::size_t k = best > 2 ? best - 2 : 0; k < std::min(pts_.size(), best + 3); ++k)
      if ((pts_[k] - q).squaredNorm() < (pts_[best] - q).squaredNorm()) best = k;
  } else {
    for (std::size_t k = 1; k < pts_.size(); ++k)
      if ((pts_[k] - q).squaredNorm() < (pts_[best] - q).squaredNorm()) best = k;
  }
  const double lo = ts_.front(), hi = ts_.back();
  double t = ts_[best];
  for (int it = 0; it < 30; ++it) {
    Vec2 c, d1, d2;
    curve_->d2(t, c, d1, d2);
    const double f = (c - q).dot(d1), df = d1.squaredNorm() + (c - q).dot(d2);
    if (!(df > 0)) break;
    const double next = std::clamp(t - f / df, lo, hi);
    const bool done = std::abs(next - t) <= 1e-15 * (hi - lo);
    t = next;
    if (done) break;
  }
  return t;
}

double SpanSurfaceEvaluator::value(const Vec3& p, Vec3* gradient, double* t_out) {
  if (surface_.kind == SpanSurfaceKind::Plane) {
    if (gradient) *gradient = surface_.normal;
    if (t_out) *t_out = 0;
    return surface_.normal.dot(p - surface_.origin);
  }
  const double rho = std::hypot(p.y(), p.z());
  const Vec2 q(p.x(), rho);
  const double t = foot_parameter(q);
  Vec2 c, d;
  curve_->d1(t, c, d);
  const Vec2 n = Vec2(-d.y(), d.x()).normalized();  // towards larger r where the curve runs along +x
  if (gradient) {
    const Vec3 er = rho > 0 ? Vec3(0, p.y() / rho, p.z() / rho) : Vec3::UnitY();
    *gradient = n.x() * Vec3::UnitX() + n.y() * er;
  }
  if (t_out) *t_out = t;
  return (q - c).dot(n);
}

double SpanSurfaceEvaluator::area_function(double t) const {
  const double t0 = ts_.front(), t1 = ts_.back();
  const double s = std::clamp((t - t0) / (t1 - t0) * kSamples, 0.0, static_cast<double>(kSamples));
  const int k = std::min(kSamples - 1, static_cast<int>(s));
  const double h = ts_[k + 1] - ts_[k], x = s - k;
  // Cubic Hermite on [t_k, t_k+1] from F and F'.
  const double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x), h01 = x * x * (3 - 2 * x),
               h11 = x * x * (x - 1);
  return h00 * area_[k] + h10 * h * darea_[k] + h01 * area_[k + 1] + h11 * h * darea_[k + 1];
}

Vec2 SpanSurfaceEvaluator::area_coordinates(const Vec3& p, double t) const {
  if (surface_.kind == SpanSurfaceKind::Plane) return {(p - surface_.origin).dot(surface_.x_axis), (p - surface_.origin).dot(y_axis_)};
  return {area_function(t), std::remainder(std::atan2(p.z(), p.y()) - surface_.theta_centre, 2 * kPi)};
}

Vec2 SpanSurfaceEvaluator::drawing(const Vec3& p) const {
  if (surface_.kind == SpanSurfaceKind::Plane) return {(p - surface_.origin).dot(surface_.x_axis), (p - surface_.origin).dot(y_axis_)};
  const double dtheta = std::remainder(std::atan2(p.z(), p.y()) - surface_.theta_centre, 2 * kPi);
  return {p.x(), std::hypot(p.y(), p.z()) * dtheta};
}

bool SpanSurfaceEvaluator::may_meet(const Bnd_Box& box) const {
  if (box.IsVoid()) return false;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  if (surface_.kind == SpanSurfaceKind::Plane) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < 8; ++k) {
      const double d = (Vec3(k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0) - surface_.origin).dot(surface_.normal);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    return lo <= pad_ && hi >= -pad_;
  }
  // The box's (x, r) rectangle (r: nearest and farthest point of its (y, z) rectangle from the axis)
  // against the sampled streamline, padded.
  const double ny = y0 > 0 ? y0 : (y1 < 0 ? y1 : 0), nz = z0 > 0 ? z0 : (z1 < 0 ? z1 : 0);
  const double fy = std::max(std::abs(y0), std::abs(y1)), fz = std::max(std::abs(z0), std::abs(z1));
  const double r0 = std::hypot(ny, nz) - pad_, r1 = std::hypot(fy, fz) + pad_, xa = x0 - pad_, xb = x1 + pad_;
  for (std::size_t k = 1; k < pts_.size(); ++k) {
    const Vec2& a = pts_[k - 1];
    const Vec2& b = pts_[k];
    if (std::max(a.x(), b.x()) >= xa && std::min(a.x(), b.x()) <= xb && std::max(a.y(), b.y()) >= r0 &&
        std::min(a.y(), b.y()) <= r1)
      return true;
  }
  return false;
}

TopoDS_Face span_surface_face(const SpanSurface& s, double size) {
  if (s.kind == SpanSurfaceKind::Plane) {
    const gp_Pln pln(gp_Pnt(s.origin.x(), s.origin.y(), s.origin.z()), gp_Dir(s.normal.x(), s.normal.y(), s.normal.z()));
    return BRepBuilderAPI_MakeFace(pln, -size, size, -size, size).Face();
  }
  const Handle(Geom2d_BSplineCurve) c2 = occt::to_occt(*s.meridional);
  // The (x, r) curve in the plane z = 0 (theta = 0), revolved about +x: theta = atan2(z, y).
  TColgp_Array1OfPnt poles(1, c2->NbPoles());
  TColStd_Array1OfReal weights(1, c2->NbPoles()), knots(1, c2->NbKnots());
  TColStd_Array1OfInteger mults(1, c2->NbKnots());
  for (int i = 1; i <= c2->NbPoles(); ++i) {
    poles(i) = gp_Pnt(c2->Pole(i).X(), c2->Pole(i).Y(), 0);
    weights(i) = c2->Weight(i);
  }
  c2->Knots(knots);
  c2->Multiplicities(mults);
  const Handle(Geom_BSplineCurve) c3 = new Geom_BSplineCurve(poles, weights, knots, mults, c2->Degree());
  const Handle(Geom_SurfaceOfRevolution) rev = new Geom_SurfaceOfRevolution(c3, gp::OX());
  return BRepBuilderAPI_MakeFace(rev, s.theta_centre - kPi / 2, s.theta_centre + kPi / 2, c3->FirstParameter(),
                                 c3->LastParameter(), 1e-7)
      .Face();
}

}  // namespace cg::features
