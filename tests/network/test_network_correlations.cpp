// The correlations the network applies where CalculiX has no element (src/network/network_correlations.hpp,
// docs/network.md), against numbers calculated by hand from the published forms, step by step below:
//  - rib turbulators, Han's rib roughness function (Han, Park & Lei 1985; Han 1988):
//      R(e+) = [12.31 - 27.07 a + 17.86 a^2] (P/e / 10)^0.35, a = angle / 90 deg,
//      sqrt(2 / f_r) = R - 2.5 ln(2 e/D_h * 2W/(W+H)) - 2.5 (fully rough);
//  - pin fins, Metzger's staggered short pins: f = 0.317 Re_D^-0.132, loss per row K = 4 f at the
//    minimum gap (Re_D 1e3-1e5).
#define BOOST_TEST_MODULE network_correlations
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "src/network/network_correlations.hpp"

using namespace cg;
using namespace cg::network;

namespace {

features::TurbulatorDefinition ribs(double angle, features::TurbulatorWalls walls) {
  features::TurbulatorDefinition t;
  t.height = 0.4;  // e
  t.pitch = 5.0;   // P: P/e = 12.5
  t.angle_deg = angle;
  t.walls = walls;
  return t;
}

bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }

}  // namespace

// The bracket of R at P/e = 10 from its three published coefficients, by hand:
//   90 deg (a = 1):   12.31 - 27.07 + 17.86             = 3.10
//   60 deg (a = 2/3): 12.31 - 18.0467 + 7.9378          = 2.2011
//   45 deg (a = 1/2): 12.31 - 13.535 + 4.465            = 3.24
//   30 deg (a = 1/3): 12.31 - 9.0233 + 1.9844           = 5.2711
// so with e/D_h = 0.1 and W = H (2 e/D_h * 2W/(W+H) = 0.2, -2.5 ln 0.2 = 4.0236) and P/e = 10 (no
// pitch factor), sqrt(2 / f_r) = R + 4.0236 - 2.5.
BOOST_AUTO_TEST_CASE(han_rib_roughness_function_at_p_e_10) {
  const double expect_r[] = {3.10, 2.2011111, 3.24, 5.2711111};
  const double angles[] = {90, 60, 45, 30};
  for (int k = 0; k < 4; ++k) {
    features::TurbulatorDefinition t = ribs(angles[k], features::TurbulatorWalls::Pressure);
    t.pitch = 4.0;  // P/e = 10
    const Turbulation r = turbulation(t, 4.0, 1.0, 40.0);
    const double g = expect_r[k] + 4.0235948 - 2.5;
    BOOST_TEST(close(r.friction_factor, 2 / (g * g), 1e-6), angles[k] << " deg: f_r " << r.friction_factor << ", by hand " << 2 / (g * g));
  }
}

// e 0.4 mm, P 5 mm (P/e 12.5), 90 deg, one ribbed wall, D_h 4 mm, W/H 1, over 40 mm:
//   R = 3.10 * 1.25^0.35 = 3.10 * 1.081231 = 3.351816
//   sqrt(2 / f_r) = 3.351816 + 4.023595 - 2.5 = 4.875411  ->  f_r = 2 / 23.769633 = 0.0841410
//   ribbed share of the perimeter W / (2 (W + H)) = 0.25; smooth walls 0.046 * (2e4)^-0.2 = 0.00634670
//   segment Fanning f = 0.25 * 0.0841410 + 0.75 * 0.00634670 = 0.0257953, Darcy 0.103181
//   fully rough Colebrook: k_s = 3.7 D_h 10^(-1 / (2 sqrt(0.103181))) = 14.8 * 0.0277605 = 0.410855 mm
//   turbulators: floor(40 / 5) = 8 on one wall.
BOOST_AUTO_TEST_CASE(han_turbulated_segment_by_hand) {
  const Turbulation r = turbulation(ribs(90, features::TurbulatorWalls::Pressure), 4.0, 1.0, 40.0);
  BOOST_TEST(close(r.e_dh, 0.1, 1e-12));
  BOOST_TEST(close(r.p_e, 12.5, 1e-12));
  BOOST_TEST(r.count == 8);
  BOOST_TEST(close(r.friction_factor, 0.0841410, 1e-5), r.friction_factor);
  BOOST_TEST(close(r.ribbed_fraction, 0.25, 1e-12));
  BOOST_TEST(close(equivalent_roughness(r, 4.0), 0.410855, 1e-5), equivalent_roughness(r, 4.0));
  // 60 deg ribs on both walls of a 2:1 channel (D_h 4, P/e 12.5): R = 2.201111 * 1.081231 = 2.379910,
  // 2 e/D_h * 2W/(W+H) = 0.2 * 4/3 = 0.266667, -2.5 ln(0.266667) = 3.304389,
  // sqrt(2 / f_r) = 2.379910 + 3.304389 - 2.5 = 3.184299 -> f_r = 0.197243; ribbed share 2 * 2/6 = 2/3;
  // f = 2/3 * 0.197243 + 1/3 * 0.0063467 = 0.133611.
  const Turbulation b = turbulation(ribs(60, features::TurbulatorWalls::Both), 4.0, 2.0, 40.0);
  BOOST_TEST(close(b.friction_factor, 0.197243, 1e-5), b.friction_factor);
  BOOST_TEST(close(b.ribbed_fraction, 2.0 / 3, 1e-12));
  BOOST_TEST(b.count == 16);
}

// Metzger: K = 4 * 0.317 * Re^-0.132 per row; at Re_D 1e4: 1e4^-0.132 = 10^-0.528 = 0.296483,
// K = 1.268 * 0.296483 = 0.375941; at 1e3 (10^-0.396 = 0.401791) 0.509471; below and above the
// correlation's range the ends' values.
BOOST_AUTO_TEST_CASE(metzger_pin_row_loss_by_hand) {
  BOOST_TEST(close(pin_row_loss(1e4), 0.375941, 1e-5), pin_row_loss(1e4));
  BOOST_TEST(close(pin_row_loss(1e3), 0.509471, 1e-5), pin_row_loss(1e3));
  BOOST_TEST(pin_row_loss(10) == pin_row_loss(1e3));
  BOOST_TEST(pin_row_loss(1e7) == pin_row_loss(1e5));
  features::PinFinDefinition p;
  p.diameter = 0.8;
  p.spanwise_pitch = 2.0;
  p.streamwise_pitch = 1.6;
  p.rows = 2;
  const PinBank b = pin_bank(p, 40);
  BOOST_TEST(close(b.s_d, 2.5, 1e-12));
  BOOST_TEST(close(b.x_d, 2.0, 1e-12));
  BOOST_TEST(close(b.loss_per_row, 0.375941, 1e-5));
}
