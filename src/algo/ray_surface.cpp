#include "src/algo/ray_surface.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "src/core/error.hpp"
#include "src/core/newton.hpp"

namespace cg {

namespace {

constexpr int kMaxDepth = 60;         // about 30 halvings in each direction
constexpr double kFlatTol = 0.02;  // "nearly planar": pole deviation / patch box diagonal

}  // namespace

RaySurfaceCaster::RaySurfaceCaster(const BSplineSurface<3>& surface, double tolerance)
    : s_(std::make_shared<const BSplineSurface<3>>(surface)), pu_(surface.degree_u()), pv_(surface.degree_v()), patches_(surface_bezier_patches(surface)) {
  BoundingBox<3> all;
  for (const auto& p : patches_) all.add(p.box);
  scale_ = all.diagonal();
  tol_ = tolerance > 0 ? tolerance : 1e-12 * (1.0 + scale_);
  order_.resize(patches_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  if (!patches_.empty()) build_tree(0, static_cast<int>(patches_.size()));
}

// Node over order_[begin, end): the union of its patches' boxes; more than 4 patches are split at the
// median of their box centres along the longest axis of those centres' extent.
int RaySurfaceCaster::build_tree(int begin, int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  BoundingBox<3> box, centres;
  for (int i = begin; i < end; ++i) {
    const BoundingBox<3>& b = patches_[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])].box;
    box.add(b);
    centres.add(0.5 * (b.lo + b.hi));
  }
  nodes_[static_cast<std::size_t>(index)].box = box;
  nodes_[static_cast<std::size_t>(index)].begin = begin;
  nodes_[static_cast<std::size_t>(index)].end = end;
  if (end - begin <= 4) return index;
  int axis = 0;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  auto centre = [&](int p) {
    const BoundingBox<3>& b = patches_[static_cast<std::size_t>(p)].box;
    return b.lo[axis] + b.hi[axis];
  };
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centre(a) < centre(b); });
  const int left = build_tree(begin, mid);
  const int right = build_tree(mid, end);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

std::size_t RaySurfaceCaster::new_block() {
  if (!free_.empty()) {
    const std::size_t b = free_.back();
    free_.pop_back();
    return b;
  }
  const std::size_t size = static_cast<std::size_t>((pu_ + 1) * (pv_ + 1) * 4);
  pool_.resize(pool_.size() + size);
  return pool_.size() / size - 1;
}

// Newton on F(s, u, v) = o + s d - S(u, v) = 0 (J = [d, -S_u, -S_v]) from the patch centre, to half
// the residual tol_ a hit is checked against (newton::solve_system); (u, v) may leave the patch by half
// its size while converging, a hit must end inside it.
bool RaySurfaceCaster::newton(const Item& it, const Eigen::Vector3d& o, const Eigen::Vector3d& d, RaySurfaceHit& hit) {
  const double u = 0.5 * (it.u0 + it.u1), v = 0.5 * (it.v0 + it.v1);
  const double mu = 0.5 * (it.u1 - it.u0), mv = 0.5 * (it.v1 - it.v0);
  newton::Domain<3> dom;
  dom.lo[1] = std::max(s_->first_u(), it.u0 - mu);
  dom.hi[1] = std::min(s_->last_u(), it.u1 + mu);
  dom.lo[2] = std::max(s_->first_v(), it.v0 - mv);
  dom.hi[2] = std::min(s_->last_v(), it.v1 + mv);
  const double s0 = d.dot(s_->point(u, v) - o) / d.squaredNorm();
  newton::SystemOptions opt;
  opt.max_iterations = 30;
  // Half the tolerance the hit is checked against below: stopping just under tol_ left the recomputed
  // residual (point() instead of derivatives(): other rounding) just above it, and a TE pin ray's wall
  // crossing was missed from some starts (found from others).
  opt.residual_tol = 0.5 * tol_;
  opt.step_tol = 0;  // only the residual decides: a hit is a point on both
  opt.max_stalls = 0;
  const Eigen::Vector3d scale(1.0 + std::abs(s0), it.u1 - it.u0, it.v1 - it.v0);
  const auto r = newton::solve_system<3>(
      [&](const Eigen::Vector3d& x, Eigen::Vector3d& F, Eigen::Matrix3d& J) {
        const auto D = s_->derivatives<1>(x[1], x[2]);
        F = o + x[0] * d - D.S();
        J.col(0) = d;
        J.col(1) = -D.S_u();
        J.col(2) = -D.S_v();
      },
      Eigen::Vector3d(s0, u, v), dom, scale, opt);
  if (!r.settled || r.singular) return false;
  const double eu = 1e-12 * (it.u1 - it.u0), ev = 1e-12 * (it.v1 - it.v0);
  const double hu = r.x[1], hv = r.x[2];
  if (hu < it.u0 - eu || hu > it.u1 + eu || hv < it.v0 - ev || hv > it.v1 + ev) return false;
  const Eigen::Vector3d S = s_->point(hu, hv);
  if (!((o + r.x[0] * d - S).norm() <= tol_)) return false;
  hit.found = true;
  hit.ray_param = r.x[0];
  hit.u = hu;
  hit.v = hv;
  hit.point = S;
  hit.gap = (o + r.x[0] * d - S).norm();
  return true;
}

RaySurfaceHit RaySurfaceCaster::first_hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double s_max) {
  require(o.allFinite(), "ray origin must have finite coordinates");
  require(d.allFinite() && d.norm() > 0, "ray direction must be finite and non-zero");
  require(s_max >= 0, "s_max must be >= 0");
  const int n = (pu_ + 1) * (pv_ + 1);
  const std::size_t block_size = static_cast<std::size_t>(n * 4);
  const double grow = tol_;
  heap_.clear();
  free_.clear();
  pool_.clear();
  // Two planes through the line (normals a, b perpendicular to d) and their two bisectors: a patch
  // whose poles all lie strictly on one side of one of them cannot meet the line (convex hull).
  const Eigen::Vector3d dn = d.normalized();
  const Eigen::Vector3d a = dn.unitOrthogonal(), b = dn.cross(a);
  const Eigen::Vector3d sides[4] = {a, b, (a + b) / std::sqrt(2.0), (a - b) / std::sqrt(2.0)};
  double offsets[4];
  for (int k = 0; k < 4; ++k) offsets[k] = sides[k].dot(o);
  auto misses_line = [&](const double* hp) {
    for (int k = 0; k < 4; ++k) {
      bool below = false, above = false;
      for (int i = 0; i < n && !(below && above); ++i) {
        const double* h = hp + 4 * i;
        const double f = (sides[k].x() * h[0] + sides[k].y() * h[1] + sides[k].z() * h[2]) / h[3] - offsets[k];
        below = below || f <= grow;
        above = above || f >= -grow;
      }
      if (!(below && above)) return true;
    }
    return false;
  };
  // The patch meets the line at most once when its projection along d onto the plane (a, b) is
  // injective. Projected homogeneously, G(u, v) = sum B_kl w_kl (a.(P_kl - o), b.(P_kl - o)) is a
  // polynomial map with the same zeros as the patch's projection (w > 0); G_u and G_v are non-negative
  // combinations of the differences of its control points along u and along v. If every such u
  // difference and v difference have determinants of one strict sign, det(G_u, G_v) is of that sign
  // for every pair of such combinations (bilinear), so G(q) - G(p) = du U + dv V (U, V averages of
  // G_u, G_v along the segment pq) vanishes only for p = q: G is injective and has at most one zero.
  auto meets_line_once = [&](const double* hp) {
    cu_.resize(static_cast<std::size_t>(2 * n));
    for (int i = 0; i < n; ++i) {
      const double* h = hp + 4 * i;
      cu_[static_cast<std::size_t>(2 * i)] = a.x() * h[0] + a.y() * h[1] + a.z() * h[2] - offsets[0] * h[3];
      cu_[static_cast<std::size_t>(2 * i + 1)] = b.x() * h[0] + b.y() * h[1] + b.z() * h[2] - offsets[1] * h[3];
    }
    auto c = [&](int k, int l, int x) { return cu_[static_cast<std::size_t>(2 * (k * (pv_ + 1) + l) + x)]; };
    int sign = 0;
    for (int k = 0; k < pu_; ++k)
      for (int l = 0; l <= pv_; ++l) {
        const double ux = c(k + 1, l, 0) - c(k, l, 0), uy = c(k + 1, l, 1) - c(k, l, 1);
        for (int kk = 0; kk <= pu_; ++kk)
          for (int ll = 0; ll < pv_; ++ll) {
            const double vx = c(kk, ll + 1, 0) - c(kk, ll, 0), vy = c(kk, ll + 1, 1) - c(kk, ll, 1);
            const double det = ux * vy - uy * vx;
            const int sg = det > 0 ? 1 : (det < 0 ? -1 : 0);
            if (sg == 0 || (sign != 0 && sg != sign)) return false;
            sign = sg;
          }
      }
    return true;
  };
  auto push_in = [&](const BoundingBox<3>& box, const double* hp, double u0, double u1, double v0, double v1, int depth) {
    double e0 = 0.0, e1 = s_max;
    if (!box.clip_ray(o, d, e0, e1, grow) || misses_line(hp)) return;
    const std::size_t b = new_block();
    std::memcpy(&pool_[b * block_size], hp, sizeof(double) * block_size);
    heap_.push_back(Item{e0, u0, u1, v0, v1, depth, b});
    std::push_heap(heap_.begin(), heap_.end(), std::greater<Item>());
  };
  auto push = [&](const double* hp, double u0, double u1, double v0, double v1, int depth) {
    push_in(homogeneous_pole_box<3>(hp, n), hp, u0, u1, v0, v1, depth);
  };
  // The knot patches whose boxes the ray enters, through the tree of boxes.
  stack_.clear();
  if (!nodes_.empty()) stack_.push_back(0);
  while (!stack_.empty()) {
    const Node& node = nodes_[static_cast<std::size_t>(stack_.back())];
    stack_.pop_back();
    double e0 = 0.0, e1 = s_max;
    if (!node.box.clip_ray(o, d, e0, e1, grow)) continue;
    if (node.left >= 0) {
      stack_.push_back(node.left);
      stack_.push_back(node.right);
      continue;
    }
    for (int i = node.begin; i < node.end; ++i) {
      const auto& p = patches_[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
      push_in(p.box, p.hpoles.data(), p.u0, p.u1, p.v0, p.v1, 0);
    }
  }

  RaySurfaceHit best;
  double best_s = s_max;
  left_.resize(block_size);
  right_.resize(block_size);
  hp_.resize(block_size);
  double* left = left_.data();
  double* right = right_.data();
  double* hp = hp_.data();
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<Item>());
    const Item it = heap_.back();
    heap_.pop_back();
    if (it.entry > best_s) break;
    std::memcpy(hp, &pool_[it.block * block_size], sizeof(double) * block_size);
    free_.push_back(it.block);

    // Flatness: poles within 2% of the patch size from the plane through the corners' centroid with
    // the mean corner normal, and weights within 2% of each other (a rational patch with unequal
    // weights can be curved even when its poles are coplanar, e.g. degree 1).
    auto pole = [&](int k, int l) {
      const double* h = &hp[static_cast<std::size_t>((k * (pv_ + 1) + l) * 4)];
      return Eigen::Vector3d(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
    };
    const Eigen::Vector3d c00 = pole(0, 0), c01 = pole(0, pv_), c10 = pole(pu_, 0), c11 = pole(pu_, pv_);
    const Eigen::Vector3d nc[4] = {(c10 - c00).cross(c01 - c00), (c11 - c10).cross(c00 - c10),
                                   (c01 - c11).cross(c10 - c11), (c00 - c01).cross(c11 - c01)};
    const Eigen::Vector3d centre = 0.25 * (c00 + c01 + c10 + c11);
    Eigen::Vector3d mean_n = Eigen::Vector3d::Zero();
    for (const auto& nv : nc)
      if (nv.norm() > 0) mean_n += nv.normalized();
    if (mean_n.norm() > 0) mean_n.normalize();
    BoundingBox<3> box;
    double dev = 0, len_u = 0, len_v = 0, wmin = 1e300, wmax = 0;
    for (int k = 0; k <= pu_; ++k)
      for (int l = 0; l <= pv_; ++l) {
        const Eigen::Vector3d q = pole(k, l);
        const double wq = hp[static_cast<std::size_t>((k * (pv_ + 1) + l) * 4 + 3)];
        wmin = std::min(wmin, wq);
        wmax = std::max(wmax, wq);
        box.add(q);
        dev = std::max(dev, std::abs((q - centre).dot(mean_n)));
        if (k < pu_) len_u += (pole(k + 1, l) - q).norm();
        if (l < pv_) len_v += (pole(k, l + 1) - q).norm();
      }
    const bool flat = mean_n.norm() > 0 && dev <= kFlatTol * box.diagonal() && wmax <= (1 + kFlatTol) * wmin;
    if (flat || it.depth >= kMaxDepth) {
      RaySurfaceHit h;
      const bool hit = newton(it, o, d, h) && h.ray_param >= -tol_ / d.norm() && h.ray_param <= best_s;
      if (hit) {
        h.ray_param = std::max(h.ray_param, 0.0);
        best = h;
        best_s = h.ray_param;
      }
      if (it.depth >= kMaxDepth || (hit && meets_line_once(hp))) continue;
      // The patch may be met twice, or Newton did not settle: examine its halves while the ray runs inside
      // the box before the best hit.
      if (hit && (best_s - it.entry) * d.norm() <= 1e3 * tol_) continue;
    }
    const bool along_u = len_u * (pv_ + 1) >= len_v * (pu_ + 1);
    split_bezier_patch(pu_, pv_, 4, hp, along_u, 0.5, left, right);
    const double um = 0.5 * (it.u0 + it.u1), vm = 0.5 * (it.v0 + it.v1);
    if (along_u) {
      push(left, it.u0, um, it.v0, it.v1, it.depth + 1);
      push(right, um, it.u1, it.v0, it.v1, it.depth + 1);
    } else {
      push(left, it.u0, it.u1, it.v0, vm, it.depth + 1);
      push(right, it.u0, it.u1, vm, it.v1, it.depth + 1);
    }
  }
  return best;
}

RaySurfaceHit ray_surface_first_hit(const BSplineSurface<3>& surface, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& direction, double s_max) {
  RaySurfaceCaster caster(surface);
  return caster.first_hit(origin, direction, s_max);
}

std::vector<double> segment_crossings(RaySurfaceCaster& caster, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  std::vector<double> out;
  const double len = (b - a).norm();
  if (!(len > 0)) return out;
  const Eigen::Vector3d d = (b - a) / len;
  constexpr double kStep = 1e-9;
  double s = 0;
  while (s < len) {
    const RaySurfaceHit h = caster.first_hit(a + s * d, d, len - s);
    if (!h.found) break;
    s += h.ray_param;
    out.push_back(s / len);
    s += kStep;
    if (out.size() > 64) break;
  }
  return out;
}

}  // namespace cg
