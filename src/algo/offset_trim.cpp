#include "src/algo/offset_trim.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "src/algo/fillet_arc.hpp"
#include "src/algo/intersect_curves.hpp"
#include "src/algo/offset_approximate.hpp"
#include "src/algo/offset_exact.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/algo/self_intersect.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/modify/degree_elevation.hpp"
#include "src/modify/reparametrize.hpp"
#include "src/modify/split.hpp"

namespace cg {

namespace {

// The raw offset as one clamped NURBS: pieces raised to a common degree, placed on consecutive
// parameter ranges and joined with knots of multiplicity q (C0: cusps and corner joints).
struct JoinedOffset {
  Curve2 curve;
  std::vector<double> start;  // start[i]: parameter of piece i on `curve`; start.back() = end
  std::vector<double> shift;  // offset pieces: curve parameter = base parameter + shift[i]
};

JoinedOffset join_pieces(const RawOffset& raw, double domain) {
  JoinedOffset J;
  int q = 1;
  for (const auto& p : raw.pieces) q = std::max(q, p.curve.degree());
  std::vector<double> knots;
  std::vector<Eigen::Vector3d> hp;
  double s = 0;
  for (const auto& p : raw.pieces) {
    // Corner arcs get a parameter length proportional to their turning angle (any positive
    // length would do; this keeps the parametrisation speed of the same order as the stretches).
    const double len = p.kind == RawOffsetPiece::Kind::offset ? p.u1 - p.u0 : domain * std::abs(p.sweep) / (2 * kPi) + 1e-3 * domain;
    Curve2 c = p.curve.degree() < q ? elevate_degree(p.curve, q - p.curve.degree()) : p.curve;
    c = reparametrized(c, s, s + len);
    J.start.push_back(s);
    J.shift.push_back(s - p.u0);
    const auto& U = c.knots();
    const auto& H = c.homogeneous_poles();
    if (hp.empty()) {
      knots.assign(U.begin(), U.end() - 1);
      for (int i = 0; i < H.cols(); ++i) hp.push_back(H.col(i));
    } else {
      // Rational curves are invariant under a common weight scale: match the joint weights.
      const double scale = hp.back()[2] / H(2, 0);
      knots.insert(knots.end(), U.begin() + q + 1, U.end() - 1);
      for (int i = 1; i < H.cols(); ++i) hp.push_back(scale * H.col(i));
    }
    s += len;
  }
  knots.push_back(s);
  J.start.push_back(s);
  Curve2::HPoles H(3, static_cast<Eigen::Index>(hp.size()));
  for (std::size_t i = 0; i < hp.size(); ++i) H.col(static_cast<Eigen::Index>(i)) = hp[i];
  J.curve = Curve2::from_homogeneous(q, knots, H);
  return J;
}

int piece_of(const JoinedOffset& J, double s) {
  const auto it = std::upper_bound(J.start.begin(), J.start.end() - 1, s);
  return std::max(0, static_cast<int>(it - J.start.begin()) - 1);
}

}  // namespace

TrimmedOffset offset_curve(const Curve2& base, double distance, double tol) {
  const RawOffset raw = approximate_raw_offset(base, distance, tol);
  TrimmedOffset out;
  out.distance = distance;
  out.max_error = raw.max_error;
  const double ad = std::abs(distance);
  if (raw.pieces.empty()) {
    out.reason = "the offset has no piece (degenerate base)";
    return out;
  }
  const double domain = base.last_param() - base.first_param();
  const JoinedOffset J = join_pieces(raw, domain);
  const Curve2& R = J.curve;
  const double s_first = R.first_param(), s_last = R.last_param();
  const double eps = 1e-13 * (s_last - s_first);

  // Cut parameters, with the partners of crossing points.
  std::vector<double> cuts{s_first, s_last};
  std::multimap<double, double> partner;
  const SelfIntersections si = self_intersections(R, tol);
  for (const auto& x : si.points) {
    cuts.push_back(x.s1);
    cuts.push_back(x.s2);
    partner.emplace(x.s1, x.s2);
    partner.emplace(x.s2, x.s1);
  }
  for (const auto& o : si.overlaps) cuts.insert(cuts.end(), {o.s0, o.s1, std::min(o.t0, o.t1), std::max(o.t0, o.t1)});
  for (double s : J.start) cuts.push_back(s);
  if (!raw.closed) {
    for (double u : {base.first_param(), base.last_param()}) {
      const Curve2 cap = circular_arc(base.point(u), ad, 0.0, 2 * kPi);
      for (const auto& x : intersect_curves(R, cap, tol).points)
        if (x.s > s_first + eps && x.s < s_last - eps) cuts.push_back(x.s);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> c;
  for (double s : cuts)
    if (s >= s_first && s <= s_last && (c.empty() || s - c.back() > eps)) c.push_back(s);
  if (c.back() < s_last) c.back() = s_last;
  const int n = static_cast<int>(c.size()) - 1;  // sub-arcs [c[k], c[k+1]]

  // Classification by the exact offset point in the middle of each sub-arc.
  ExactOffset exact(base, distance);
  CurveProjector<2> proj(base);
  std::vector<char> keep(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double sm = 0.5 * (c[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k) + 1]);
    const int i = piece_of(J, sm);
    const auto& piece = raw.pieces[static_cast<std::size_t>(i)];
    const Eigen::Vector2d P = piece.kind == RawOffsetPiece::Kind::offset
                                  ? exact.point(std::clamp(sm - J.shift[static_cast<std::size_t>(i)], piece.u0, piece.u1))
                                  : R.point(sm);
    keep[static_cast<std::size_t>(k)] = proj.project(P).distance >= ad - tol;
    if (!keep[static_cast<std::size_t>(k)]) ++out.loops_removed;
  }

  // Successor of a kept sub-arc: across a crossing onto the partner branch, else straight on.
  auto index_at = [&](double s) {  // sub-arc starting at s (-1 if none)
    const auto it = std::lower_bound(c.begin(), c.end(), s - eps);
    if (it == c.end() || std::abs(*it - s) > eps) return -1;
    const int k = static_cast<int>(it - c.begin());
    return k < n ? k : -1;
  };
  std::vector<int> next(static_cast<std::size_t>(n), -1);
  for (int k = 0; k < n; ++k) {
    if (!keep[static_cast<std::size_t>(k)]) continue;
    const double e = c[static_cast<std::size_t>(k) + 1];
    int nk = -1;
    for (auto it = partner.lower_bound(e - eps); it != partner.end() && it->first <= e + eps && nk < 0; ++it) {
      const int j = index_at(it->second);
      if (j >= 0 && keep[static_cast<std::size_t>(j)]) nk = j;
    }
    if (nk < 0) {
      const int j = k + 1 < n ? k + 1 : (raw.closed ? 0 : -1);
      if (j >= 0 && keep[static_cast<std::size_t>(j)]) nk = j;
    }
    next[static_cast<std::size_t>(k)] = nk;
  }

  // Chains: open ones start at a kept sub-arc without predecessor, the rest are cycles.
  std::vector<int> pred_count(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k)
    if (next[static_cast<std::size_t>(k)] >= 0) ++pred_count[static_cast<std::size_t>(next[static_cast<std::size_t>(k)])];
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  auto build = [&](int k0) {
    OffsetChain chain;
    double run_a = c[static_cast<std::size_t>(k0)], run_b = run_a;
    int k = k0;
    while (k >= 0 && !used[static_cast<std::size_t>(k)]) {
      used[static_cast<std::size_t>(k)] = 1;
      const double a = c[static_cast<std::size_t>(k)], b = c[static_cast<std::size_t>(k) + 1];
      if (std::abs(a - run_b) > eps) {  // a jump (crossing or seam): close the current run
        chain.pieces.push_back(segment(R, run_a, run_b));
        run_a = a;
      }
      run_b = b;
      k = next[static_cast<std::size_t>(k)];
    }
    chain.pieces.push_back(segment(R, run_a, run_b));
    chain.closed = (k == k0);
    // A closed chain that started mid-run: merge its last run into the first when contiguous.
    if (chain.closed && chain.pieces.size() > 1 && std::abs(run_b - c[static_cast<std::size_t>(k0)]) <= eps) {
      const double a0 = chain.pieces.back().first_param(), b0 = chain.pieces.front().last_param();
      chain.pieces.front() = segment(R, a0, b0);
      chain.pieces.pop_back();
    }
    out.chains.push_back(std::move(chain));
  };
  for (int k = 0; k < n; ++k)
    if (keep[static_cast<std::size_t>(k)] && !used[static_cast<std::size_t>(k)] && pred_count[static_cast<std::size_t>(k)] == 0)
      build(k);
  for (int k = 0; k < n; ++k)
    if (keep[static_cast<std::size_t>(k)] && !used[static_cast<std::size_t>(k)]) build(k);

  if (out.chains.empty())
    out.reason = "no point of the offset lies at distance |d| = " + format_number(ad) +
                 " from the base curve (e.g. an inward offset beyond the smallest inscribed radius)";
  return out;
}

}  // namespace cg
