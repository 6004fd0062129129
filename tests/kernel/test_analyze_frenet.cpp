// Frenet frame, curvature and torsion against OCCT's GeomLProp_CLProps / Geom2dLProp_CLProps2d on random
// curves, against closed forms on the nine-point circle and on an interpolated helix, and the
// degenerate cases (zero first derivative, zero curvature).
#define BOOST_TEST_MODULE analyze_frenet
#include <Eigen/Geometry>
#include <Geom2dLProp_CLProps2d.hxx>
#include <GeomLProp_CLProps.hxx>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/analyze/frenet.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"
#include "support/eval_scales.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

// Curvature is a ratio of derivative expressions; both sides compute it from derivatives that agree
// to ~1e-13 of their scale, and the ratio amplifies that by its condition number, roughly
// (scale of C' / |C'|) + (scale of C'' / |C'' normal part|), with the (pessimistic) scales of
// support/eval_scales.hpp. Points where that number exceeds 1e4 (|C'| or the normal part of C''
// almost zero) are ill-posed for any implementation and skipped; the rest must agree to 1e-8
// relative (1e-13 x 1e4 x a margin of 10 for the factor 3 in |C'|^3).
template <int Dim, class Vec>
bool well_conditioned(const Vec& d1, const Vec& d2, double s1, double s2) {
  const double n1 = d1.norm();
  const double normal_part = (d2 - d2.dot(d1) / (n1 * n1) * d1).norm();
  return n1 > 1e-4 * s1 && normal_part > 1e-4 * s2;
}

}  // namespace

BOOST_AUTO_TEST_CASE(frame_3d_vs_occt_random) {
  test::Rng r(11);
  int compared = 0, total = 0;
  for (int i = 0; i < 1200; ++i) {
    const auto c = test::random_curve<3>(r, i % 2 == 1);
    const auto oc = occt::to_occt(c);
    for (int s = 0; s < 3; ++s) {
      const double u = r.uniform(c.first_param(), c.last_param());
      ++total;
      const FrenetFrame f = frenet_frame(c, u);
      const auto d = c.derivatives(u, 2);
      GeomLProp_CLProps props(oc, u, 2, 1e-14);
      BOOST_TEST_REQUIRE(props.IsTangentDefined() == (f.status != FrameStatus::Singular));
      if (c.degree() == 1) {  // straight pieces: no curvature
        BOOST_TEST((f.status == FrameStatus::ZeroCurvature && f.curvature == 0.0));
        continue;
      }
      if (!well_conditioned<3>(d[1], d[2], test::deriv_scale(c, 1), test::deriv_scale(c, 2))) continue;
      ++compared;
      BOOST_TEST_REQUIRE((f.status == FrameStatus::Regular));
      gp_Dir T, N;
      props.Tangent(T);
      props.Normal(N);
      const double k = props.Curvature();
      BOOST_TEST(std::abs(f.curvature - k) <= 1e-8 * k);
      BOOST_TEST((f.tangent - Eigen::Vector3d(T.X(), T.Y(), T.Z())).norm() <= 1e-9);
      BOOST_TEST((f.normal - Eigen::Vector3d(N.X(), N.Y(), N.Z())).norm() <= 1e-8);
      // Orthonormal right-handed frame.
      BOOST_TEST(std::abs(f.tangent.cross(f.normal).dot(f.binormal) - 1.0) <= 1e-12);
    }
  }
  BOOST_TEST_MESSAGE("3D: compared " << compared << " of " << total << " points");
  BOOST_TEST(compared >= 1000);
}

BOOST_AUTO_TEST_CASE(frame_2d_vs_occt_random) {
  test::Rng r(12);
  int compared = 0;
  for (int i = 0; i < 1200; ++i) {
    const auto c = test::random_curve<2>(r, i % 2 == 1);
    if (c.degree() == 1) continue;
    const auto oc = occt::to_occt(c);
    for (int sample = 0; sample < 3; ++sample) {
      const double u = r.uniform(c.first_param(), c.last_param());
      const auto d = c.derivatives(u, 2);
      if (!well_conditioned<2>(d[1], d[2], test::deriv_scale(c, 1), test::deriv_scale(c, 2))) continue;
      ++compared;
      const PlanarFrame f = frenet_frame(c, u);
      Geom2dLProp_CLProps2d props(oc, u, 2, 1e-14);
      gp_Dir2d T, N;
      props.Tangent(T);
      props.Normal(N);  // OCCT: towards the centre of curvature, curvature unsigned
      const double k = props.Curvature();
      BOOST_TEST(std::abs(std::abs(f.curvature) - k) <= 1e-8 * k);
      BOOST_TEST((f.tangent - Eigen::Vector2d(T.X(), T.Y())).norm() <= 1e-9);
      const double sign = f.curvature > 0 ? 1.0 : -1.0;  // left normal points to the centre iff turning left
      BOOST_TEST((sign * f.normal - Eigen::Vector2d(N.X(), N.Y())).norm() <= 1e-9);
    }
  }
  BOOST_TEST(compared >= 1000);
}

BOOST_AUTO_TEST_CASE(nine_point_circle_curvature_one) {
  const double s = std::sqrt(0.5);
  const std::vector<Eigen::Vector2d> P{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  const std::vector<double> w{1, s, 1, s, 1, s, 1, s, 1};
  const Curve2 circle(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P, w);
  std::vector<Eigen::Vector3d> P3;
  for (const auto& p : P) P3.emplace_back(p.x(), p.y(), 0.0);
  const Curve3 circle3(2, circle.knots(), P3, w);
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    // Exact rational circle: only rounding in the derivative formulas (a few ulps, 1e-14).
    BOOST_TEST(std::abs(signed_curvature(circle, u) - 1.0) <= 1e-14);  // counter-clockwise: turns left
    const FrenetFrame f = frenet_frame(circle3, u);
    BOOST_TEST(std::abs(f.curvature - 1.0) <= 1e-14);
    BOOST_TEST(std::abs(f.torsion) <= 1e-13);
    BOOST_TEST((f.normal + f.point).norm() <= 1e-14);  // the normal points to the centre
    BOOST_TEST((f.binormal - Eigen::Vector3d::UnitZ()).norm() <= 1e-14);
  }
}

BOOST_AUTO_TEST_CASE(helix_torsion_interpolated) {
  // Helix (r cos t, r sin t, c t): curvature r / (r^2 + c^2), torsion c / (r^2 + c^2).
  const double r = 2.0, c = 0.5;
  const int n = 401;
  const double T = 4 * M_PI;
  PointList<3> Q;
  std::vector<double> t;
  for (int k = 0; k < n; ++k) {
    t.push_back(T * k / (n - 1));
    Q.emplace_back(r * std::cos(t.back()), r * std::sin(t.back()), c * t.back());
  }
  const int p = 5;
  const Curve3 h = interpolate<3>(Q, p, t, averaged_knots(t, p));
  const double kappa = r / (r * r + c * c), tau = c / (r * r + c * c);
  double pos_err = 0, kappa_err = 0, tau_err = 0;
  // Interior only: near the ends the not-a-knot-like end conditions of A9.1 lose two orders.
  for (int i = 0; i <= 1000; ++i) {
    const double u = 0.1 * T + 0.8 * T * i / 1000.0;
    const FrenetFrame f = frenet_frame(h, u);
    pos_err = std::max(pos_err, (f.point - Eigen::Vector3d(r * std::cos(u), r * std::sin(u), c * u)).norm());
    kappa_err = std::max(kappa_err, std::abs(f.curvature - kappa) / kappa);
    tau_err = std::max(tau_err, std::abs(f.torsion - tau) / tau);
  }
  BOOST_TEST_MESSAGE("helix interpolation: position " << pos_err << ", curvature " << kappa_err << ", torsion "
                                                      << tau_err);
  // Quintic interpolation with step h = 0.031 on the interior (uniform knots, superconvergent):
  // measured position 1.3e-13, curvature 1.4e-9, torsion 6e-9 relative; bounds 100x above.
  BOOST_TEST(pos_err <= 1e-11);
  BOOST_TEST(kappa_err <= 1e-7);
  BOOST_TEST(tau_err <= 1e-6);
}

BOOST_AUTO_TEST_CASE(degenerate_points) {
  // Cubic with a double first pole: C'(0) = 0.
  const Curve3 cusp(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {2, 0, 1}});
  const FrenetFrame f = frenet_frame(cusp, 0.0);
  BOOST_TEST((f.status == FrameStatus::Singular));
  BOOST_CHECK_THROW(curvature(cusp, 0.0), AlgorithmFailure);
  BOOST_CHECK_THROW(f.require_tangent(), AlgorithmFailure);
  BOOST_TEST((frenet_frame(cusp, 0.5).status == FrameStatus::Regular));
  // Straight cubic: tangent and zero curvature only.
  const Curve3 line(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {4, 4, 4}});
  const FrenetFrame g = frenet_frame(line, 0.3);
  BOOST_TEST((g.status == FrameStatus::ZeroCurvature));
  BOOST_TEST(g.curvature == 0.0);
  BOOST_TEST((g.tangent - Eigen::Vector3d(1, 1, 1).normalized()).norm() <= 1e-15);
  BOOST_CHECK_THROW(torsion(line, 0.3), AlgorithmFailure);
  BOOST_CHECK_THROW(g.require_normal(), AlgorithmFailure);
  const Curve2 cusp2(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {0, 0}, {1, 1}});
  BOOST_CHECK_THROW(signed_curvature(cusp2, 0.0), AlgorithmFailure);
}
