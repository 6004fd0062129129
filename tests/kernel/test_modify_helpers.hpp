#pragma once
// Helpers shared by the test_modify_* tests: random test curves, OCCT handle types per dimension,
// representation and shape comparisons.
//
// Tolerances (used throughout): poles and points agree to 1e-12 relative to the pole scale max|P|. Both
// sides compute each pole / point as a sum of O(p) convex-combination steps of the same poles in a
// different order, so they differ by a few ulps (2.2e-16) of the largest term; rational data divides by
// weights whose ratio is at most 25 (weights in [0.2, 5]). 1e-12 leaves a margin of ~100x over that
// worst case and still catches any algorithmic error (wrong alpha, wrong index), which is O(1) relative.
// Knot values are copied or shifted by one addition, so they agree to 1e-14 of the knot magnitude.
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <sstream>
#include <string>
#include <type_traits>

#include "src/core/bspline_curve.hpp"
#include "support/random_geometry.hpp"
#include "support/random_periodic.hpp"

namespace cg::test {

constexpr double kPoleTol = 1e-12;
constexpr double kKnotTol = 1e-14;

template <int Dim>
using OcctCurve = std::conditional_t<Dim == 3, Geom_BSplineCurve, Geom2d_BSplineCurve>;

/// Random curve for case i: alternating polynomial/rational, one case in four periodic.
template <int Dim>
BSplineCurve<Dim> random_case_curve(Rng& r, int i) {
  const bool rational = i % 2 == 1;
  if ((i / 2) % 4 == 3) return random_periodic_bspline<Dim>(r, rational);
  return random_curve<Dim>(r, rational);
}

inline double knot_scale(const std::vector<double>& U) {
  double s = 1.0;
  for (double k : U) s = std::max(s, std::abs(k));
  return s;
}

/// Empty string when a and b have the same degree, periodicity, knots (kKnotTol relative), poles and
/// weights (kPoleTol relative to the pole scale); otherwise a description of the first difference.
template <int Dim>
std::string representation_difference(const BSplineCurve<Dim>& a, const BSplineCurve<Dim>& b) {
  std::ostringstream os;
  if (a.degree() != b.degree()) os << "degree " << a.degree() << " vs " << b.degree();
  else if (a.is_periodic() != b.is_periodic()) os << "periodic " << a.is_periodic() << " vs " << b.is_periodic();
  else if (a.num_poles() != b.num_poles()) os << "poles " << a.num_poles() << " vs " << b.num_poles();
  if (!os.str().empty()) return os.str();
  const double ks = knot_scale(b.knots());
  for (std::size_t i = 0; i < a.knots().size(); ++i)
    if (std::abs(a.knots()[i] - b.knots()[i]) > kKnotTol * ks) {
      os << "knot " << i << ": " << a.knots()[i] << " vs " << b.knots()[i];
      return os.str();
    }
  const double ps = pole_scale(b);
  double wmax = 0;
  for (int i = 0; i < b.num_poles(); ++i) wmax = std::max(wmax, b.weight(i));
  for (int i = 0; i < a.num_poles(); ++i) {
    const double dp = (a.pole(i) - b.pole(i)).norm(), dw = std::abs(a.weight(i) - b.weight(i));
    if (dp > kPoleTol * ps || dw > kPoleTol * wmax) {
      os << "pole " << i << " differs by " << dp / ps << " (relative), weight by " << dw / wmax;
      return os.str();
    }
  }
  return "";
}

/// Largest |f(u) - g(map(u))| over `samples` parameters spread over [a, b] (ends included), relative to
/// `scale`.
template <class F, class G>
double max_relative_deviation(F f, G g, double a, double b, double scale, int samples = 21) {
  double e = 0;
  for (int k = 0; k < samples; ++k) {
    const double u = k + 1 == samples ? b : a + (b - a) * k / (samples - 1);
    e = std::max(e, (f(u) - g(u)).norm() / scale);
  }
  return e;
}

}  // namespace cg::test
