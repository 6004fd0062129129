#include "src/fit/skin.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/core/error.hpp"
#include "src/fit/collocation.hpp"
#include "src/modify/degree_elevation.hpp"
#include "src/modify/knot_insertion.hpp"
#include "src/modify/reparametrize.hpp"
#include "src/core/format.hpp"

namespace cg {

namespace {

// The knots that carry the shape: the full clamped vector of an open curve, one period
// (U[p] .. U[p + n - 1], the seam knot first) of a periodic one.
std::vector<double> own_knots(const BSplineCurve<3>& c) {
  if (!c.is_periodic()) return c.knots();
  const auto& U = c.knots();
  return std::vector<double>(U.begin() + c.degree(), U.begin() + c.degree() + c.num_period_poles());
}

// Multiset union of sorted knot lists: every value with its largest multiplicity.
std::vector<double> knot_union(const std::vector<std::vector<double>>& lists) {
  std::vector<double> out;
  for (const auto& l : lists) {
    std::vector<double> merged;
    std::size_t i = 0, j = 0;
    while (i < out.size() || j < l.size()) {
      if (j == l.size() || (i < out.size() && out[i] < l[j]))
        merged.push_back(out[i++]);
      else if (i == out.size() || l[j] < out[i])
        merged.push_back(l[j++]);
      else {
        merged.push_back(out[i++]);
        ++j;
      }
    }
    out = std::move(merged);
  }
  return out;
}

// Sorted multiset difference a - b (b a sub-multiset of a).
std::vector<double> knot_difference(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(d));
  return d;
}

}  // namespace

std::vector<BSplineCurve<3>> make_compatible(const std::vector<BSplineCurve<3>>& sections) {
  require(!sections.empty(), "make_compatible needs at least one section");
  const bool periodic = sections.front().is_periodic();
  int degree = 0;
  for (std::size_t k = 0; k < sections.size(); ++k) {
    require(sections[k].num_poles() > 0, "section " + std::to_string(k) + " is empty");
    require(sections[k].is_periodic() == periodic, "sections must be all periodic or all non-periodic (section " +
                                                       std::to_string(k) + " differs from section 0)");
    degree = std::max(degree, sections[k].degree());
  }
  std::vector<BSplineCurve<3>> out;
  std::vector<std::vector<double>> knots;
  for (const auto& s : sections) {
    BSplineCurve<3> c = reparametrized(s, 0.0, 1.0);
    if (c.degree() < degree) c = elevate_degree(c, degree - c.degree());
    knots.push_back(own_knots(c));
    out.push_back(std::move(c));
  }
  const std::vector<double> common = knot_union(knots);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::vector<double> missing = knot_difference(common, knots[k]);
    if (!missing.empty()) out[k] = refine_knots(out[k], missing);
  }
  for (std::size_t k = 1; k < out.size(); ++k)
    if (out[k].knots() != out[0].knots())
      throw AlgorithmFailure("make_compatible: section " + std::to_string(k) +
                             " did not reach the common knot vector after refinement");
  return out;
}

SkinResult skin(const std::vector<BSplineCurve<3>>& sections, const SkinOptions& options) {
  const int K = static_cast<int>(sections.size());
  require(K >= 2, "skinning needs at least 2 sections, got " + std::to_string(K));
  require(options.degree_v >= 1 && options.degree_v <= kMaxDegree,
          "degree_v " + std::to_string(options.degree_v) + " out of range [1, " + std::to_string(kMaxDegree) + "]");
  const int q = std::min(options.degree_v, K - 1);
  const std::vector<BSplineCurve<3>> c = make_compatible(sections);
  const int N = c[0].num_poles();
  const int distinct = c[0].num_period_poles();  // wrap poles repeat others: no extra information

  SkinResult res;
  if (!options.v_params.empty()) {
    require(static_cast<int>(options.v_params.size()) == K, "v_params must hold one parameter per section (" +
                                                                std::to_string(K) + "), got " +
                                                                std::to_string(options.v_params.size()));
    for (int k = 0; k < K; ++k) {
      require(std::isfinite(options.v_params[static_cast<std::size_t>(k)]),
              "v parameter " + std::to_string(k) + " is not finite");
      if (k > 0)
        require(options.v_params[static_cast<std::size_t>(k)] > options.v_params[static_cast<std::size_t>(k - 1)],
                "v_params must be strictly increasing (parameter " + std::to_string(k) + ")");
    }
    res.v_params = options.v_params;
  } else {
    // The NURBS Book eq. 10.8: parameters of every pole row across the sections, averaged over the
    // rows; rows whose poles all coincide (a collapsed edge) carry no information and are skipped.
    res.v_params.assign(static_cast<std::size_t>(K), 0.0);
    int rows = 0;
    for (int i = 0; i < distinct; ++i) {
      PointList<3> row;
      double length = 0;
      for (int k = 0; k < K; ++k) {
        row.push_back(c[static_cast<std::size_t>(k)].pole(i));
        if (k > 0) length += (row[static_cast<std::size_t>(k)] - row[static_cast<std::size_t>(k - 1)]).norm();
      }
      if (!(length > 0)) continue;
      std::vector<double> t;
      try {
        t = interpolation_parameters<3>(row, options.method);
      } catch (const InvalidGeometry&) {
        continue;  // two sections share this pole: the other rows decide
      }
      for (int k = 0; k < K; ++k) res.v_params[static_cast<std::size_t>(k)] += t[static_cast<std::size_t>(k)];
      ++rows;
    }
    if (rows == 0) throw InvalidGeometry("consecutive sections coincide: no pole row separates them");
    for (double& v : res.v_params) v /= rows;
    res.v_params.front() = 0.0;
    res.v_params.back() = 1.0;
    for (int k = 1; k < K; ++k)
      require(res.v_params[static_cast<std::size_t>(k)] > res.v_params[static_cast<std::size_t>(k - 1)],
              "sections " + std::to_string(k - 1) + " and " + std::to_string(k) + " coincide");
  }

  // One collocation solve with every homogeneous pole coordinate of every row as a right-hand side.
  const std::vector<double> V = averaged_knots(res.v_params, q);
  Eigen::MatrixXd rhs(K, 4 * N);
  for (int k = 0; k < K; ++k)
    for (int i = 0; i < N; ++i)
      rhs.block<1, 4>(k, 4 * i) = c[static_cast<std::size_t>(k)].homogeneous_poles().col(i).transpose();
  const Eigen::MatrixXd X =
      solve_collocation(q, V, false, res.v_params, std::vector<int>(static_cast<std::size_t>(K), 0), rhs);
  BSplineSurface<3>::HPoles H(4, N * K);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < K; ++j) {
      H.col(i * K + j) = X.block<1, 4>(j, 4 * i).transpose();
      if (!(H(3, i * K + j) > 0))
        throw AlgorithmFailure("skinning rational sections gave the non-positive weight " +
                               format_number(H(3, i * K + j)) + " at pole (" + std::to_string(i) + ", " +
                               std::to_string(j) + "); use sections with compatible weights");
    }
  // Interpolation is linear in the data, so the wrap pole rows of periodic sections stay copies of
  // the first ones and the surface is periodic in u.
  res.surface = BSplineSurface<3>::from_homogeneous(c[0].degree(), q, c[0].knots(), V, N, K, std::move(H),
                                                    c[0].is_periodic(), false);
  return res;
}

}  // namespace cg
