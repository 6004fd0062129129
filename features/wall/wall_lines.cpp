#include "features/wall/wall_lines.hpp"

#include <algorithm>

namespace cg::features {

namespace {
// Patch boxes grown by this much (mm) and the caster's tolerance are tested against the segment.
constexpr double kReach = 1e-6;
}  // namespace

LocalCaster::LocalCaster(const BSplineSurface<3>& surface)
    : pu_(surface.degree_u()),
      pv_(surface.degree_v()),
      periodic_u_(surface.is_periodic_u()),
      periodic_v_(surface.is_periodic_v()),
      tol_(0),
      period_u_(surface.last_u() - surface.first_u()),
      period_v_(surface.last_v() - surface.first_v()),
      patches_(surface_bezier_patches(surface)),
      full_(surface) {
  BoundingBox<3> all;
  for (const auto& p : patches_) all.add(p.box);
  tol_ = 1e-12 * (1.0 + all.diagonal());  // the whole surface's caster tolerance, for every local caster
  for (const auto& p : patches_) {
    if (p.span_u != patches_.front().span_u) break;
    ++rows_;
  }
  cols_ = rows_ > 0 ? static_cast<int>(patches_.size()) / rows_ : 0;
  if (static_cast<std::size_t>(cols_ * rows_) != patches_.size()) cols_ = rows_ = 0;  // not a grid: always full_
  col_hit_.assign(static_cast<std::size_t>(cols_), 0);
  row_hit_.assign(static_cast<std::size_t>(rows_), 0);
}

RaySurfaceCaster& LocalCaster::for_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (cols_ == 0) {
    ++full_queries;
    return full_;
  }
  // The patches whose pole box the segment itself passes through (a long slanted segment's own box
  // would take in many patches it never comes near).
  const double len = (b - a).norm();
  const Eigen::Vector3d d = len > 0 ? Eigen::Vector3d((b - a) / len) : Eigen::Vector3d::UnitX();
  auto meets = [&](const BoundingBox<3>& box) {
    double s0 = 0, s1 = len;
    return box.clip_ray(a, d, s0, s1, kReach + tol_);
  };
  std::fill(col_hit_.begin(), col_hit_.end(), 0);
  std::fill(row_hit_.begin(), row_hit_.end(), 0);
  int hits = 0;
  for (int iu = 0; iu < cols_; ++iu)
    for (int iv = 0; iv < rows_; ++iv)
      if (meets(patches_[static_cast<std::size_t>(iu * rows_ + iv)].box)) {
        col_hit_[static_cast<std::size_t>(iu)] = row_hit_[static_cast<std::size_t>(iv)] = 1;
        ++hits;
      }
  // The smallest index range [lo, hi] holding every hit column (row), grown by one. In a periodic
  // direction the range may run over the seam: hi >= n then stands for index hi - n one period on.
  auto range = [](const std::vector<char>& hit, bool periodic, int& lo, int& hi) {
    const int n = static_cast<int>(hit.size());
    lo = n, hi = -1;
    for (int i = 0; i < n; ++i)
      if (hit[static_cast<std::size_t>(i)]) lo = std::min(lo, i), hi = std::max(hi, i);
    if (hi < 0) return;
    if (periodic) {
      // The complement of the longest cyclic run of missed indices (the run may pass the seam).
      int best_len = 0, best_end = 0;  // run [best_end - best_len + 1, best_end], indices mod n
      int run = 0;
      for (int k = 0; k < 2 * n; ++k) {
        run = hit[static_cast<std::size_t>(k % n)] ? 0 : run + 1;
        if (run > best_len && run <= n) best_len = run, best_end = k;
      }
      lo = (best_end + 1) % n;
      hi = lo + (n - best_len) - 1;
      if (hi - lo + 3 <= n) --lo, ++hi;
      if (lo < 0) lo += n, hi += n;
      return;
    }
    lo = std::max(0, lo - 1), hi = std::min(n - 1, hi + 1);
  };
  int u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  if (hits > 0) {
    range(col_hit_, periodic_u_, u0, u1);
    range(row_hit_, periodic_v_, v0, v1);
    if (2 * (u1 - u0 + 1) * (v1 - v0 + 1) > cols_ * rows_) {
      ++full_queries;
      return full_;
    }
  }
  // hits == 0: no patch box reaches the segment, so it crosses nothing; the caster of patch (0, 0) says
  // so (the ray misses that patch's box as it misses all, clip_ray grows boxes by tol_ < kReach + tol_).
  ++local_queries;
  if (cache_.size() > 256) cache_.clear();
  std::unique_ptr<RaySurfaceCaster>& c = cache_[{u0, u1, v0, v1}];
  if (!c) {
    // The Bézier form of the rectangle: every inner knot of multiplicity p, the patches' poles glued;
    // a column (row) one period on has its parameters moved by the period.
    const int nu = (u1 - u0 + 1) * pu_ + 1, nv = (v1 - v0 + 1) * pv_ + 1;
    auto col = [&](int i, double& shift) {
      shift = i >= cols_ ? period_u_ : 0.0;
      return i % cols_;
    };
    auto row = [&](int j, double& shift) {
      shift = j >= rows_ ? period_v_ : 0.0;
      return j % rows_;
    };
    std::vector<double> U, V;
    double shift = 0;
    for (int i = u0; i <= u1; ++i) {
      const auto& p = patches_[static_cast<std::size_t>(col(i, shift) * rows_)];
      U.insert(U.end(), static_cast<std::size_t>(i == u0 ? pu_ + 1 : pu_), p.u0 + shift);
    }
    U.insert(U.end(), static_cast<std::size_t>(pu_ + 1), patches_[static_cast<std::size_t>(col(u1, shift) * rows_)].u1 + shift);
    for (int j = v0; j <= v1; ++j) {
      const auto& p = patches_[static_cast<std::size_t>(row(j, shift))];
      V.insert(V.end(), static_cast<std::size_t>(j == v0 ? pv_ + 1 : pv_), p.v0 + shift);
    }
    V.insert(V.end(), static_cast<std::size_t>(pv_ + 1), patches_[static_cast<std::size_t>(row(v1, shift))].v1 + shift);
    BSplineSurface<3>::HPoles H(4, nu * nv);
    for (int i = u0; i <= u1; ++i)
      for (int j = v0; j <= v1; ++j) {
        const auto& p = patches_[static_cast<std::size_t>(col(i, shift) * rows_ + row(j, shift))];
        for (int k = 0; k <= pu_; ++k)
          for (int l = 0; l <= pv_; ++l)
            H.col(((i - u0) * pu_ + k) * nv + (j - v0) * pv_ + l) = p.hpoles.col(k * (pv_ + 1) + l);
      }
    c = std::make_unique<RaySurfaceCaster>(
        BSplineSurface<3>::from_homogeneous(pu_, pv_, std::move(U), std::move(V), nu, nv, std::move(H)), tol_);
  }
  return *c;
}

WallLines::WallLines(const BSplineSurface<3>& outer, const BSplineSurface<3>& inner)
    : outer_(outer), inner_(inner), inner_surface_(&inner) {}

Eigen::Vector3d WallLines::inner_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double len = (b - a).norm();
  const RaySurfaceHit h = inner_.for_segment(a, b).first_hit(a, (b - a) / len, len);
  return h.found ? inner_surface_->normal(h.u, h.v) : Eigen::Vector3d::Zero();
}

std::vector<double> WallLines::crossings(LocalCaster& local, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (!((b - a).norm() > 0)) return {};
  return segment_crossings(local.for_segment(a, b), a, b);
}

std::vector<double> WallLines::outer_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return crossings(outer_, a, b);
}
std::vector<double> WallLines::inner_crossings(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return crossings(inner_, a, b);
}

Intervals WallLines::intervals(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Region start, Region wanted,
                               Region* end, bool chamber) {
  std::vector<std::pair<double, bool>> events;  // (t, true: outer wall)
  for (double t : outer_crossings(a, b)) events.emplace_back(t, true);
  if (chamber)
    for (double t : inner_crossings(a, b)) events.emplace_back(t, false);
  std::sort(events.begin(), events.end());
  // The chamber lies inside the blade: the two toggles are tracked separately.
  bool in_blade = start != Region::Outside, in_chamber = start == Region::Chamber;
  auto region = [&] { return !in_blade ? Region::Outside : in_chamber ? Region::Chamber : Region::Material; };
  Intervals out;
  double t0 = 0;
  for (const auto& [t, outer] : events) {
    if (region() == wanted && t > t0) out.emplace_back(t0, t);
    (outer ? in_blade : in_chamber) = !(outer ? in_blade : in_chamber);
    t0 = t;
  }
  if (region() == wanted && t0 < 1) out.emplace_back(t0, 1.0);
  if (end) *end = region();
  return out;
}

double total(const Intervals& iv) {
  double s = 0;
  for (const auto& [a, b] : iv) s += b - a;
  return s;
}

}  // namespace cg::features
