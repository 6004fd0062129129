#include "src/blade/wall_fit.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "src/core/format.hpp"
#include "src/core/basis.hpp"
#include "src/core/error.hpp"
#include "src/fit/skin.hpp"

namespace cg::blade::detail {
namespace {

constexpr int kDegree = 3;
constexpr int kMaxPoles = 4000;
constexpr std::size_t kMaxSections = 257;

// Parameters: m per knot span at fractions j / m (the knot itself first); the even ones are the fit
// data, all are checked.
std::vector<double> sample_params(const std::vector<double>& knots, int m) {
  std::vector<double> u;
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double a = knots[i], b = i + 1 < knots.size() ? knots[i + 1] : 1.0;
    for (int j = 0; j < m; ++j) u.push_back(a + (b - a) * j / m);
  }
  return u;
}

// Periodic cubic least squares on fixed knots for many sections at once: the normal matrix is the same
// for all of them and is factored once.
class PeriodicLeastSquares {
 public:
  PeriodicLeastSquares(const std::vector<double>& knots, const std::vector<double>& params) : knots_(knots) {
    n_ = static_cast<int>(knots.size());
    U_ = unwrap_periodic_knots(kDegree, knots, 1.0);
    std::vector<Eigen::Triplet<double>> trip;
    double N[kMaxDegree + 1];
    for (std::size_t k = 0; k < params.size(); ++k) {
      const int s = find_span(U_.data(), n_ + kDegree - 1, kDegree, params[k]);
      basis_funs(s, params[k], kDegree, U_.data(), N);
      for (int j = 0; j <= kDegree; ++j) trip.emplace_back(static_cast<int>(k), (s - kDegree + j) % n_, N[j]);
    }
    A_.resize(static_cast<Eigen::Index>(params.size()), n_);
    A_.setFromTriplets(trip.begin(), trip.end());  // duplicates (wrapped basis functions) are summed
    const Eigen::SparseMatrix<double> AtA = A_.transpose() * A_;
    llt_.compute(AtA);
    require(llt_.info() == Eigen::Success, "wall fit: the least-squares system is singular");
  }
  BSplineCurve<3> fit(const std::vector<Eigen::Vector3d>& pts) const {
    Eigen::MatrixXd Q(static_cast<Eigen::Index>(pts.size()), 3);
    for (std::size_t k = 0; k < pts.size(); ++k) Q.row(static_cast<Eigen::Index>(k)) = pts[k].transpose();
    const Eigen::MatrixXd AtQ = A_.transpose() * Q;
    const Eigen::MatrixXd X = llt_.solve(AtQ);
    std::vector<Eigen::Vector3d> P(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) P[static_cast<std::size_t>(i)] = X.row(i).transpose();
    return BSplineCurve<3>::periodic(kDegree, knots_, 1.0, P);
  }

 private:
  std::vector<double> knots_, U_;
  int n_ = 0;
  Eigen::SparseMatrix<double> A_;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt_;
};

// Linear extrapolation of two compatible sections, pole by pole in homogeneous form.
BSplineCurve<3> extrapolated(const BSplineCurve<3>& A, double sa, const BSplineCurve<3>& B, double sb, double s) {
  const double w = (s - sa) / (sb - sa);
  auto h = ((1 - w) * A.homogeneous_poles() + w * B.homogeneous_poles()).eval();
  return BSplineCurve<3>::from_homogeneous(A.degree(), A.knots(), std::move(h), A.is_periodic());
}

}  // namespace

WallFit fit_wall(const SectionFamily& family, const WallFitOptions& opt) {
  require(opt.tolerance > 0, "wall fit: the tolerance must be > 0");
  WallFit out;
  std::vector<double> spans{0.0, 1.0};
  for (double s : family.defined_spans())
    if (s > 0 && s < 1) spans.push_back(s);
  std::sort(spans.begin(), spans.end());
  // Slices and their points at the current sample parameters, built once per span and knot vector
  // (every outer round refits and rechecks with the same points unless the knots changed).
  struct Cached {
    FamilySlice slice;
    int version = -1;
    std::vector<Eigen::Vector3d> points;
  };
  std::map<double, Cached> slices;
  int version = 0;
  std::vector<double> params;
  auto points_at = [&](double s) -> const std::vector<Eigen::Vector3d>& {
    auto it = slices.find(s);
    if (it == slices.end()) it = slices.emplace(s, Cached{family.slice(s), -1, {}}).first;
    if (it->second.version != version) {
      it->second.points = it->second.slice.points_3d(params);
      it->second.version = version;
    }
    return it->second.points;
  };
  auto exact_at = [&](double s) -> const BSplineCurve<3>& {
    auto it = slices.find(s);
    if (it == slices.end()) it = slices.emplace(s, Cached{family.slice(s), -1, {}}).first;
    return *it->second.slice.exact_3d();
  };
  const bool exact = family.straight() && !family.common_knots().empty();
  out.exact_sections = exact;
  // Seed knots: a single profile's own knots (its data points: the fit then needs few more); otherwise
  // a few uniform spans, refined where needed (a parametric family's 2n interpolation knots would be
  // ~3x more poles than 1 um needs).
  std::vector<double> knots = exact || family.kind() == SectionFamily::Kind::Single ? family.common_knots()
                                                                                    : std::vector<double>{};
  if (knots.empty()) {
    const int n0 = 16;
    for (int i = 0; i < n0; ++i) knots.push_back(static_cast<double>(i) / n0);
  }
  const double tol_u = 0.5 * opt.tolerance;
  std::vector<BSplineCurve<3>> sections;
  int sampled_knots = -1;
  for (;;) {
    // Chordwise: fit every section on the common knots, halving spans that miss tol_u.
    double fit_error = 0;
    for (;;) {
      const int nspans = static_cast<int>(knots.size());
      int m = 8;
      while (m * nspans < 2 * opt.min_samples_per_side) m += 2;
      if (static_cast<int>(knots.size()) != sampled_knots) {  // knots only grow: the size identifies them
        params = sample_params(knots, m);
        sampled_knots = static_cast<int>(knots.size());
        ++version;
      }
      sections.clear();
      std::vector<double> span_error(knots.size(), 0.0);
      fit_error = 0;
      if (exact) {
        for (double s : spans) sections.push_back(exact_at(s));
        break;
      }
      std::vector<double> fit_params;
      for (std::size_t k = 0; k < params.size(); k += 2) fit_params.push_back(params[k]);
      const PeriodicLeastSquares lsq(knots, fit_params);
      for (double s : spans) {
        const std::vector<Eigen::Vector3d>& pts = points_at(s);
        std::vector<Eigen::Vector3d> data;
        for (std::size_t k = 0; k < pts.size(); k += 2) data.push_back(pts[k]);
        sections.push_back(lsq.fit(data));
        for (std::size_t k = 0; k < params.size(); ++k) {
          const double e = (sections.back().point(params[k]) - pts[k]).norm();
          span_error[k / static_cast<std::size_t>(m)] = std::max(span_error[k / static_cast<std::size_t>(m)], e);
          fit_error = std::max(fit_error, e);
        }
        out.checked_points += static_cast<long>(params.size());
      }
      if (fit_error <= tol_u) break;
      std::vector<double> refined;
      for (std::size_t i = 0; i < knots.size(); ++i) {
        refined.push_back(knots[i]);
        if (span_error[i] > tol_u) refined.push_back(0.5 * (knots[i] + (i + 1 < knots.size() ? knots[i + 1] : 1.0)));
      }
      knots = std::move(refined);
      if (static_cast<int>(knots.size()) > kMaxPoles)
        throw AlgorithmFailure("blade surface: the sections cannot be fitted to surface_tolerance " +
                               format_number(opt.tolerance) + " mm with " + std::to_string(kMaxPoles) +
                               " poles chordwise (smallest error reached " + format_number(fit_error) + " mm)");
    }

    // Spanwise: skin and compare with the family inside every interval.
    std::vector<BSplineCurve<3>> rows;
    const std::size_t ns = sections.size();
    rows.push_back(extrapolated(sections[0], spans[0], sections[1], spans[1], -opt.overbuild));
    rows.insert(rows.end(), sections.begin(), sections.end());
    rows.push_back(extrapolated(sections[ns - 2], spans[ns - 2], sections[ns - 1], spans[ns - 1], 1 + opt.overbuild));
    SkinOptions so;
    so.degree_v = kDegree;
    so.v_params = {-opt.overbuild};
    so.v_params.insert(so.v_params.end(), spans.begin(), spans.end());
    so.v_params.push_back(1 + opt.overbuild);
    out.surface = skin(rows, so).surface;

    double worst = fit_error;
    std::vector<double> added;
    for (std::size_t i = 0; i + 1 < spans.size(); ++i) {
      bool split = false;
      for (double f : {0.25, 0.5, 0.75}) {
        const double s = spans[i] + f * (spans[i + 1] - spans[i]);
        const std::vector<Eigen::Vector3d>& pts = points_at(s);
        for (std::size_t k = 0; k < params.size(); ++k) {
          const double e = (out.surface.point(params[k], s) - pts[k]).norm();
          worst = std::max(worst, e);
          split = split || e > opt.tolerance;
        }
        out.checked_points += static_cast<long>(params.size());
      }
      if (split) added.push_back(0.5 * (spans[i] + spans[i + 1]));
    }
    out.max_deviation = worst;
    if (added.empty()) break;
    spans.insert(spans.end(), added.begin(), added.end());
    std::sort(spans.begin(), spans.end());
    if (spans.size() > kMaxSections)
      throw AlgorithmFailure("blade surface: surface_tolerance " + format_number(opt.tolerance) + " mm is not met with " +
                             std::to_string(kMaxSections) + " sections along the span (error " + format_number(worst) + " mm)");
  }
  out.spans = spans;
  return out;
}

}  // namespace cg::blade::detail
