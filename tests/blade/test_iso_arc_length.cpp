// Arc-length tables of the wall's iso-curves with shared Gauss nodes (src/blade/iso_arc_length.hpp)
// against ArcLength<3> (src/analyze/arc_length.hpp, the adaptive rule they shortcut) on the same
// curves: both aim at rel_tol = 1e-12 of the length, so totals, lengths and inverses agree to 2e-12 of
// the length (both errors plus rounding). Curves: the iso-curves of both example blades at random spans,
// a rational periodic curve (random weights), and a near-cusp span that the 10-point rule cannot accept
// (the adaptive fallback).
#define BOOST_TEST_MODULE iso_arc_length
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "blade/blade_fixtures.hpp"
#include "src/analyze/arc_length.hpp"
#include "src/blade/iso_arc_length.hpp"
#include "src/blade/surface_iso.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::blade;
using namespace cg::blade::test;

namespace {

// Worst disagreement with ArcLength<3> over random queries, relative to the total length.
double worst_against_arc_length(const BSplineCurve<3>& c, const IsoArcLength& iso, std::mt19937& rng) {
  const ArcLength<3> ref(c);
  const double L = ref.total();
  double worst = std::abs(iso.total() - L) / L;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double u = c.first_param() + u01(rng) * c.period();
    worst = std::max(worst, std::abs(iso.length_to(u) - ref.length_to(u)) / L);
    const double s = u01(rng) * L;
    // The inverse: the reference length at our parameter is s.
    worst = std::max(worst, std::abs(ref.length_to(iso.param_at(s)) - s) / L);
  }
  worst = std::max(worst, std::abs(iso.length_to(c.last_param()) - L) / L);
  BOOST_TEST(iso.param_at(0.0) == c.first_param());
  BOOST_TEST(iso.param_at(iso.total()) == c.last_param());
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(wall_iso_curves_agree_with_arc_length) {
  std::mt19937 rng(5);
  for (const BladeDefinition& def : {hpt_rotor(), c3x_vane()}) {
    const BladeModel m = build_blade(def);
    const auto nodes = std::make_shared<const IsoArcLengthNodes>(detail::iso_curve_v(m.surface, 0.5));
    std::uniform_real_distribution<double> span(m.surface.first_v(), m.surface.last_v());
    double worst = 0;
    int adaptive = 0;
    for (int k = 0; k < 8; ++k) {
      const BSplineCurve<3> c = detail::iso_curve_v(m.surface, span(rng));
      const IsoArcLength iso(c, nodes);
      adaptive += iso.adaptive_spans();
      worst = std::max(worst, worst_against_arc_length(c, iso, rng));
    }
    BOOST_TEST_MESSAGE("worst relative disagreement " << worst << ", adaptive spans " << adaptive);
    BOOST_TEST(worst < 2e-12);
  }
}

// param_near (the Hermite guess param_at polishes): within 1e-4 of the length on the examples' wall
// iso-curves (worst of 4000 random queries: 1.4e-5 rotor, 7.9e-5 C3X, where a cell's speed varies most,
// round the LE and TE), exact at the ends.
BOOST_AUTO_TEST_CASE(near_inverse_of_the_wall_iso_curves) {
  std::mt19937 rng(7);
  for (const BladeDefinition& def : {hpt_rotor(), c3x_vane()}) {
    const BladeModel m = build_blade(def);
    const auto nodes = std::make_shared<const IsoArcLengthNodes>(detail::iso_curve_v(m.surface, 0.5));
    std::uniform_real_distribution<double> span(m.surface.first_v(), m.surface.last_v()), u01(0.0, 1.0);
    double worst = 0;
    for (int k = 0; k < 8; ++k) {
      const BSplineCurve<3> c = detail::iso_curve_v(m.surface, span(rng));
      const IsoArcLength iso(c, nodes);
      for (int q = 0; q < 500; ++q) {
        const double s = u01(rng) * iso.total();
        worst = std::max(worst, std::abs(iso.length_to(iso.param_near(s)) - s) / iso.total());
      }
      BOOST_TEST(iso.param_near(0.0) == c.first_param());
      BOOST_TEST(iso.param_near(iso.total()) == c.last_param());
    }
    BOOST_TEST_MESSAGE("worst relative error of param_near " << worst);
    BOOST_TEST(worst < 1e-4);
    BOOST_TEST(worst > 1e-12);  // an interpolant, not the polished inverse
  }
}

BOOST_AUTO_TEST_CASE(rational_periodic_curve) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> w(0.5, 2.0), r(0.8, 1.2);
  const int n = 11;
  std::vector<double> knots;
  for (int i = 0; i < n; ++i) knots.push_back(i / double(n));
  knots[3] = knots[4];  // a double knot (C1 there) among uniform ones
  std::vector<Eigen::Vector3d> poles;
  std::vector<double> weights;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / n;
    poles.emplace_back(r(rng) * std::cos(a), r(rng) * std::sin(a), 0.1 * r(rng));
    weights.push_back(w(rng));
  }
  const BSplineCurve<3> c = BSplineCurve<3>::periodic(3, knots, 1.0, poles, weights);
  BOOST_REQUIRE(c.is_rational());
  const IsoArcLength iso(c);
  const double worst = worst_against_arc_length(c, iso, rng);
  BOOST_TEST_MESSAGE("rational: worst relative disagreement " << worst);
  BOOST_TEST(worst < 2e-12);
}

// Three nearly coincident poles: the speed almost vanishes inside a span, the 10-point rule and its
// halves disagree there, and that span is integrated adaptively (same answers as ArcLength).
BOOST_AUTO_TEST_CASE(near_cusp_span_falls_back_to_the_adaptive_rule) {
  std::vector<Eigen::Vector3d> poles{{0, 0, 0}, {1, 0, 0}, {2, 1e-3, 0}, {2 + 1e-6, 1e-3, 0}, {2, 1e-3 + 1e-6, 0},
                                     {2, 2, 0}, {0, 2, 0}};
  std::vector<double> knots;
  for (int i = 0; i < 7; ++i) knots.push_back(i / 7.0);
  const BSplineCurve<3> c = BSplineCurve<3>::periodic(3, knots, 1.0, poles);
  const IsoArcLength iso(c);
  BOOST_TEST(iso.adaptive_spans() > 0);
  std::mt19937 rng(3);
  const double worst = worst_against_arc_length(c, iso, rng);
  BOOST_TEST_MESSAGE("near cusp: worst relative disagreement " << worst);
  BOOST_TEST(worst < 2e-12);
}

BOOST_AUTO_TEST_CASE(nodes_of_other_knots_are_refused) {
  const BladeModel m = build_blade(hpt_rotor());
  const BSplineCurve<3> c = detail::iso_curve_v(m.surface, 0.3);
  std::vector<Eigen::Vector3d> poles{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}};
  const BSplineCurve<3> other = BSplineCurve<3>::periodic(3, {0, 0.2, 0.4, 0.6, 0.8}, 1.0, poles);
  const auto nodes = std::make_shared<const IsoArcLengthNodes>(other);
  BOOST_CHECK_THROW(IsoArcLength(c, nodes), InvalidGeometry);
  BOOST_CHECK_THROW(IsoArcLength(c).param_at(-1.0), InvalidGeometry);
}
