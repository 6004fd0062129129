#pragma once
// Shared kernel of the modification operations: a B-spline whose poles are the columns of a dynamic
// matrix. A curve is one bundle of Dim + 1 homogeneous rows; a surface along u (or v) is a bundle whose
// columns stack all homogeneous poles of one pole row (column). The NURBS Book A5.3 applies a curve
// algorithm "row-wise" to a surface; stacking the rows lets one kernel do both, with the same alphas
// for every row.
//
// Periodic bundles use the stored unwrapped form of bspline_curve.hpp (n + p poles, the last p repeat
// the first p; knots continue by the period). Operations on them go through a clamped extension over
// three periods (see periodic_extension), so every algorithm below is written for non-periodic data only.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "src/core/bspline_curve.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg {

struct PoleBundle {
  int degree = 0;
  std::vector<double> knots;  // full (flat) knot vector, unwrapped when periodic
  Eigen::MatrixXd poles;      // one column per pole
  bool periodic = false;

  int num_poles() const { return static_cast<int>(poles.cols()); }
  int num_period_poles() const { return periodic ? num_poles() - degree : num_poles(); }
  double first() const { return knots[static_cast<std::size_t>(degree)]; }
  double last() const { return knots[static_cast<std::size_t>(num_poles())]; }
  double period() const { return last() - first(); }
};

/// Parametric direction of a surface operation.
enum class SurfaceDirection { U, V };

namespace bundle {

/// Maps u into the domain (wrapping periodic bundles); throws InvalidGeometry naming `what` when u lies
/// outside [first, last] by more than 1e-12 of the domain length (as BSplineCurve::check_param).
double checked_param(const PoleBundle& b, double u, const char* what);

/// Inserts u `times` times (The NURBS Book A5.1; periodic: in the unwrapped form with all copies u + kT,
/// staying periodic as OCCT's InsertKnot). Throws when times < 1, u is outside the domain or the
/// resulting multiplicity exceeds the degree.
PoleBundle insert_knot(const PoleBundle& b, double u, int times);

/// Inserts the non-decreasing knots X (The NURBS Book A5.4), with the checks of insert_knot.
PoleBundle refine_knots(const PoleBundle& b, const std::vector<double>& X);

/// Raises the degree by t >= 1: the result of The NURBS Book A5.9 (every distinct knot's multiplicity
/// grows by t), computed by blossoming for accuracy (see pole_bundle.cpp). Periodic stays periodic;
/// unclamped non-periodic data is clamped first.
PoleBundle elevate_degree(const PoleBundle& b, int t);

/// Clamped non-periodic bundle on [a, b] describing the same curve there (The NURBS Book A5.4 to bring
/// a and b to multiplicity p, then the poles in between). a < b inside the domain; for periodic bundles
/// a may be anywhere and b - a <= period (the piece may cross the seam).
PoleBundle segment(const PoleBundle& b, double a, double c);

/// The two clamped halves on [first, u] and [u, last], sharing the pole at u exactly.
std::pair<PoleBundle, PoleBundle> split(const PoleBundle& b, double u);

/// Same curve with clamped ends (periodic: seam knot at full multiplicity, wrap poles dropped).
/// Returns b unchanged when it is already clamped and non-periodic.
PoleBundle clamped(const PoleBundle& b);

/// C(first + last - u): knots reflected, poles reversed (periodic stays periodic, as OCCT's Reverse).
PoleBundle reversed(const PoleBundle& b);

// ---- conversion from/to curves and surfaces ----------------------------------------------------------

template <int Dim>
PoleBundle from_curve(const BSplineCurve<Dim>& c) {
  return PoleBundle{c.degree(), c.knots(), c.homogeneous_poles(), c.is_periodic()};
}

template <int Dim>
BSplineCurve<Dim> to_curve(PoleBundle b) {
  return BSplineCurve<Dim>::from_homogeneous(b.degree, std::move(b.knots), std::move(b.poles), b.periodic);
}

/// Bundle along `dir`: for U, column i stacks the homogeneous poles (i, 0..nv-1) (which is the
/// surface's own storage, reinterpreted); for V, column j stacks (0..nu-1, j).
template <int Dim>
PoleBundle from_surface(const BSplineSurface<Dim>& s, SurfaceDirection dir) {
  constexpr int H = Dim + 1;
  const int nu = s.num_poles_u(), nv = s.num_poles_v();
  const auto& h = s.homogeneous_poles();
  PoleBundle b;
  if (dir == SurfaceDirection::U) {
    b = PoleBundle{s.degree_u(), s.knots_u(), Eigen::Map<const Eigen::MatrixXd>(h.data(), H * nv, nu),
                   s.is_periodic_u()};
  } else {
    Eigen::MatrixXd m(H * nu, nv);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) m.block(H * i, j, H, 1) = h.col(i * nv + j);
    b = PoleBundle{s.degree_v(), s.knots_v(), std::move(m), s.is_periodic_v()};
  }
  return b;
}

/// Surface with direction `dir` taken from b and the other direction from s.
template <int Dim>
BSplineSurface<Dim> to_surface(const PoleBundle& b, const BSplineSurface<Dim>& s, SurfaceDirection dir) {
  constexpr int H = Dim + 1;
  typename BSplineSurface<Dim>::HPoles h(H, b.poles.size() / H);
  if (dir == SurfaceDirection::U) {
    const int nv = s.num_poles_v(), nu = b.num_poles();
    Eigen::Map<Eigen::MatrixXd>(h.data(), H * nv, nu) = b.poles;
    return BSplineSurface<Dim>::from_homogeneous(b.degree, s.degree_v(), b.knots, s.knots_v(), nu, nv, std::move(h),
                                                 b.periodic, s.is_periodic_v());
  }
  const int nu = s.num_poles_u(), nv = b.num_poles();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) h.col(i * nv + j) = b.poles.block(H * i, j, H, 1);
  return BSplineSurface<Dim>::from_homogeneous(s.degree_u(), b.degree, s.knots_u(), b.knots, nu, nv, std::move(h),
                                               s.is_periodic_u(), b.periodic);
}

}  // namespace bundle
}  // namespace cg
