#include "src/algo/bounding_spans.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "src/core/bezier_ops.hpp"

#include "src/core/error.hpp"

namespace cg {

template <int Dim>
bool BoundingBox<Dim>::clip_ray(const Point& o, const Point& d, double& s0, double& s1, double tol) const {
  if (empty()) return false;
  for (int k = 0; k < Dim; ++k) {
    const double a = lo[k] - tol, b = hi[k] + tol;
    if (d[k] == 0.0) {
      if (o[k] < a || o[k] > b) return false;
      continue;
    }
    const double inv = 1.0 / d[k];
    double ta = (a - o[k]) * inv, tb = (b - o[k]) * inv;
    if (ta > tb) std::swap(ta, tb);
    s0 = std::max(s0, ta);
    s1 = std::min(s1, tb);
    if (s0 > s1) return false;
  }
  return true;
}

template <int Dim>
BoundingBox<Dim> homogeneous_pole_box(const double* hpoles, int count) {
  BoundingBox<Dim> box;
  for (int i = 0; i < count; ++i) {
    const double* h = hpoles + i * (Dim + 1);
    const double iw = 1.0 / h[Dim];
    typename BoundingBox<Dim>::Point q;
    for (int d = 0; d < Dim; ++d) q[d] = h[d] * iw;
    box.add(q);
  }
  return box;
}

template <int Dim>
std::vector<CurveBezierSpan<Dim>> curve_bezier_spans(const BSplineCurve<Dim>& curve) {
  require(curve.num_poles() > 0, "curve_bezier_spans needs a non-empty curve");
  const int p = curve.degree();
  const auto& U = curve.knots();
  const auto& H = curve.homogeneous_poles();
  std::vector<CurveBezierSpan<Dim>> out;
  for (int s = p; s < curve.num_poles(); ++s) {
    if (!(U[static_cast<std::size_t>(s + 1)] > U[static_cast<std::size_t>(s)])) continue;
    CurveBezierSpan<Dim> piece;
    piece.a = U[static_cast<std::size_t>(s)];
    piece.b = U[static_cast<std::size_t>(s + 1)];
    piece.span = s;
    piece.hpoles.resize(Dim + 1, p + 1);
    span_bezier_poles(p, U.data(), s, H.col(s - p).data(), Dim + 1, piece.hpoles.data());
    piece.box = homogeneous_pole_box<Dim>(piece.hpoles.data(), p + 1);
    out.push_back(std::move(piece));
  }
  return out;
}

template <int Dim>
std::vector<BoundingBox<Dim>> curve_span_boxes(const BSplineCurve<Dim>& curve) {
  std::vector<BoundingBox<Dim>> out;
  for (const auto& s : curve_bezier_spans(curve)) out.push_back(s.box);
  return out;
}

template <int Dim>
std::vector<SurfaceBezierPatch<Dim>> surface_bezier_patches(const BSplineSurface<Dim>& surface) {
  constexpr int W = Dim + 1;
  const int pu = surface.degree_u(), pv = surface.degree_v();
  const int nv = surface.num_poles_v();
  const auto& U = surface.knots_u();
  const auto& V = surface.knots_v();
  const auto& H = surface.homogeneous_poles();
  std::vector<SurfaceBezierPatch<Dim>> out;
  std::vector<double> rows(static_cast<std::size_t>((pu + 1) * (pv + 1) * W));
  std::vector<double> column(static_cast<std::size_t>((pu + 1) * W)), bez(column.size());
  for (int su = pu; su < surface.num_poles_u(); ++su) {
    if (!(U[static_cast<std::size_t>(su + 1)] > U[static_cast<std::size_t>(su)])) continue;
    for (int sv = pv; sv < nv; ++sv) {
      if (!(V[static_cast<std::size_t>(sv + 1)] > V[static_cast<std::size_t>(sv)])) continue;
      // Rows first (v direction: the poles of row i are consecutive in H), then columns along u.
      for (int k = 0; k <= pu; ++k) {
        const int i = su - pu + k;
        span_bezier_poles(pv, V.data(), sv, H.col(i * nv + sv - pv).data(), W,
                          rows.data() + static_cast<std::size_t>(k * (pv + 1) * W));
      }
      SurfaceBezierPatch<Dim> patch;
      patch.u0 = U[static_cast<std::size_t>(su)];
      patch.u1 = U[static_cast<std::size_t>(su + 1)];
      patch.v0 = V[static_cast<std::size_t>(sv)];
      patch.v1 = V[static_cast<std::size_t>(sv + 1)];
      patch.span_u = su;
      patch.span_v = sv;
      patch.hpoles.resize(W, (pu + 1) * (pv + 1));
      for (int l = 0; l <= pv; ++l) {
        for (int k = 0; k <= pu; ++k)
          std::memcpy(column.data() + k * W, rows.data() + (k * (pv + 1) + l) * W, sizeof(double) * W);
        span_bezier_poles(pu, U.data(), su, column.data(), W, bez.data());
        for (int k = 0; k <= pu; ++k)
          std::memcpy(patch.hpoles.col(k * (pv + 1) + l).data(), bez.data() + k * W, sizeof(double) * W);
      }
      patch.box = homogeneous_pole_box<Dim>(patch.hpoles.data(), (pu + 1) * (pv + 1));
      out.push_back(std::move(patch));
    }
  }
  return out;
}

template <int Dim>
std::vector<BoundingBox<Dim>> surface_patch_boxes(const BSplineSurface<Dim>& surface) {
  std::vector<BoundingBox<Dim>> out;
  for (const auto& p : surface_bezier_patches(surface)) out.push_back(p.box);
  return out;
}

#define CG_INSTANTIATE(D)                                                                               \
  template struct BoundingBox<D>;                                                                       \
  template BoundingBox<D> homogeneous_pole_box<D>(const double*, int);                                  \
  template std::vector<CurveBezierSpan<D>> curve_bezier_spans<D>(const BSplineCurve<D>&);               \
  template std::vector<BoundingBox<D>> curve_span_boxes<D>(const BSplineCurve<D>&);                     \
  template std::vector<SurfaceBezierPatch<D>> surface_bezier_patches<D>(const BSplineSurface<D>&);      \
  template std::vector<BoundingBox<D>> surface_patch_boxes<D>(const BSplineSurface<D>&);
CG_INSTANTIATE(1)
CG_INSTANTIATE(2)
CG_INSTANTIATE(3)
#undef CG_INSTANTIATE

}  // namespace cg
