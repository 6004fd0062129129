// Blade-relative coordinates (issue 8, item 3): chord = arc-length fraction of the side on the section
// at that span, TE at +-1 exactly, span = the stream-surface span fraction; one definition shared by
// the 2D profiles and the 3D sections of the wall. Arc lengths are checked against an independent
// quadrature (composite 5-point Gauss-Legendre on 4000 panels of |dS/du|), round trips at random spans.
#define BOOST_TEST_MODULE blade_coordinates
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "blade/blade_fixtures.hpp"
#include "src/algo/project_point_curve.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/blade/span_section.hpp"
#include "src/core/error.hpp"

using namespace cg;
using namespace cg::blade;
using namespace cg::blade::test;

namespace {

// Length of the iso-curve v = s from u = a forward to u = b (b < a wraps once), by 5-point Gauss-
// Legendre on 4000 equal panels (not the code under test's adaptive tables).
double length_along(const BSplineSurface<3>& S, double s, double a, double b) {
  if (b < a) b += 1;
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  const int panels = 4000;
  const double h = (b - a) / panels;
  double L = 0;
  for (int i = 0; i < panels; ++i)
    for (int k = 0; k < 5; ++k) {
      Eigen::Vector3d d[4];
      S.derivatives(std::fmod(a + h * (i + 0.5 + 0.5 * x[k]), 1.0), s, 1, d);
      L += w[k] * 0.5 * h * d[2].norm();
    }
  return L;
}

// Arc-length property at random spans and chords: the length from the LE to point(span, c) over the
// side's length is |c| (1e-7: the quadrature's own accuracy on these curves is ~1e-9 and the
// C0 knots of arc sections limit it).
double worst_arc_fraction(const BladeModel& m, unsigned seed, int n) {
  BladeCoordinates bc(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> span(0.0, 1.0), chord(-1.0, 1.0);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const double s = span(rng), c = chord(rng);
    const BladeFrame f = bc.frame(s, c);
    const double side = c >= 0 ? length_along(m.surface, s, m.u_le, m.u_te) : length_along(m.surface, s, m.u_te, m.u_le);
    const double along = c >= 0 ? length_along(m.surface, s, m.u_le, f.u) : length_along(m.surface, s, f.u, m.u_le);
    worst = std::max(worst, std::abs(along / side - std::abs(c)));
    // The section at this span agrees: its lengths and point.
    const SpanSection& sec = bc.section(s);
    BOOST_TEST(std::abs((c >= 0 ? sec.suction_length() : sec.pressure_length()) - side) < 1e-7 * side);
    BOOST_TEST((sec.point(c) - f.point).norm() < 1e-12);
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(arc_length_property_meridional_and_straight) {
  const BladeModel rotor = build_blade(hpt_rotor());
  const double wr = worst_arc_fraction(rotor, 21, 12);
  BOOST_TEST_MESSAGE("rotor: worst |arc fraction - |c||: " << wr);
  BOOST_TEST(wr < 1e-7);
  const BladeModel vane = build_blade(c3x_vane());
  const double wv = worst_arc_fraction(vane, 22, 12);
  BOOST_TEST_MESSAGE("C3X: worst |arc fraction - |c||: " << wv);
  BOOST_TEST(wv < 1e-7);
}

// LE at c = 0 and TE at c = +-1 exactly (the same surface point for +1 and -1, at u_te), at any span.
BOOST_AUTO_TEST_CASE(te_at_plus_minus_one_exactly) {
  const BladeModel m = build_blade(hpt_rotor());
  BladeCoordinates bc(m);
  for (double s : {0.0, 0.137, 0.5, 0.81, 1.0}) {
    // Exactly the surface parameters u_te and u_le (points: the frame evaluates through derivatives, a
    // different summation order than point(), so they agree to rounding).
    BOOST_TEST(bc.frame(s, 1).u == m.u_te);
    BOOST_TEST(bc.frame(s, -1).u == m.u_te);
    BOOST_TEST(bc.frame(s, 0).u == m.u_le);
    const Eigen::Vector3d te = m.surface.point(m.u_te, s);
    BOOST_TEST((bc.frame(s, 1).point - te).norm() < 1e-12);
    BOOST_TEST((bc.frame(s, -1).point - bc.frame(s, 1).point).norm() == 0.0);
    BOOST_TEST(bc.seam_chordwise(s) == 1.0);  // default seam: the TE
    // A point on the TE locates to chord +1 (or -1: the same point).
    const BladeLocateResult r = bc.locate(te);
    BOOST_TEST_REQUIRE(r.found);
    BOOST_TEST(std::abs(std::abs(r.coordinate.chord) - 1) < 1e-9);
  }
}

// span = stream-surface span fraction: point(span, c) lies on the stream surface at that span (within
// the surface tolerance) at random spans between the defined sections; LE and TE on the LE/TE lines.
BOOST_AUTO_TEST_CASE(span_is_the_stream_surface_fraction) {
  const BladeModel m = build_blade(hpt_rotor());
  BladeCoordinates bc(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> span(0.0, 1.0), chord(-1.0, 1.0);
  CurveProjector<2> on_le(m.net->leading_edge()->curve), on_te(m.net->trailing_edge()->curve);
  double worst = 0, worst_edges = 0;
  for (int k = 0; k < 30; ++k) {
    const double s = span(rng);
    const Streamline line = m.net->streamline_at(s);
    CurveProjector<2> on_line(line.curve());
    auto xr = [](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z())); };
    for (int j = 0; j < 10; ++j) worst = std::max(worst, on_line.project(xr(bc.frame(s, chord(rng)).point)).distance);
    worst_edges = std::max({worst_edges, on_le.project(xr(bc.frame(s, 0).point)).distance,
                            on_te.project(xr(bc.frame(s, 1).point)).distance});
  }
  BOOST_TEST_MESSAGE("distance from the stream surface " << worst << " mm, LE/TE from their lines " << worst_edges);
  BOOST_TEST(worst < m.surface_tolerance);
  BOOST_TEST(worst_edges < m.surface_tolerance);
}

// Round trips point -> locate at random spans, chords and depths (below half the local thickness).
BOOST_AUTO_TEST_CASE(round_trips_at_random_spans) {
  const BladeModel m = build_blade(hpt_rotor());
  BladeCoordinates bc(m);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> span(0.0, 1.0), chord(-0.95, 0.95), depth(0.0, 0.25);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const BladeCoordinate c{span(rng), chord(rng), depth(rng)};
    const BladeLocateResult r = bc.locate(bc.point(c));
    BOOST_TEST_REQUIRE(r.found);
    worst = std::max({worst, std::abs(r.coordinate.span - c.span), std::abs(r.coordinate.chord - c.chord),
                      std::abs(r.coordinate.depth - c.depth)});
  }
  BOOST_TEST_MESSAGE("round trip worst " << worst);
  BOOST_TEST(worst < 1e-9);
}

// One definition: on a straight vane (isometric placement) the 3D section's chordwise coordinate is the
// 2D profile's (SectionProfile::param_at_chordwise), to rounding.
BOOST_AUTO_TEST_CASE(profile_and_wall_share_the_definition) {
  const BladeModel m = build_blade(c3x_vane());
  const SectionProfile& p = m.profiles[0];
  const SpanSection sec(m, 0.4);
  for (double c = -0.99; c < 1; c += 0.0371) {
    const Eigen::Vector2d q = p.curve.point(p.param_at_chordwise(c));
    BOOST_TEST((sec.point(c).head<2>() - q).norm() < 1e-9);
    BOOST_TEST(std::abs(sec.chordwise_at_u(sec.u_at_chordwise(c)) - c) < 1e-11);
  }
}

// A configured seam: at the mid-span section's chordwise coordinate 0.5 (suction side).
BOOST_AUTO_TEST_CASE(configured_seam) {
  BladeDefinition d = hpt_rotor();
  d.options.seam = 0.5;
  const BladeModel m = build_blade(d);
  BladeCoordinates bc(m);
  BOOST_TEST(std::abs(bc.seam_chordwise(0.5) - 0.5) < 1e-3);
  for (double s : {0.0, 1.0}) BOOST_TEST(std::abs(bc.seam_chordwise(s) - 0.5) < 0.05);
  BOOST_TEST((bc.frame(0.5, bc.seam_chordwise(0.5)).point - m.surface.point(0.0, 0.5)).norm() < 1e-9);
}

// The per-span section cache: frames from one object that alternates between many spans (more than the
// cache holds, so entries are evicted and rebuilt) are bit-identical to frames from a fresh object per
// call, and a section reference stays valid while fewer than kSectionCacheSize other spans are used.
BOOST_AUTO_TEST_CASE(section_cache_gives_the_frames_of_fresh_objects) {
  const BladeModel m = build_blade(hpt_rotor());
  const BladeCoordinates cached(m);
  const int nspans = static_cast<int>(BladeCoordinates::kSectionCacheSize) + 7;
  std::vector<double> spans;
  for (int k = 0; k < nspans; ++k) spans.push_back(-0.02 + 1.04 * k / (nspans - 1));
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> pick(0, nspans - 1);
  std::uniform_real_distribution<double> chord(-1.0, 1.0);
  int mismatches = 0;
  for (int k = 0; k < 400; ++k) {
    // Alternate: a pair of nearby spans (the typical difference quotient), then a random one.
    const double s = k % 3 == 2 ? spans[static_cast<std::size_t>(pick(rng))] : 0.4 + 1e-6 * (k % 2);
    const double c = chord(rng);
    const BladeFrame a = cached.frame(s, c);
    const BladeFrame b = BladeCoordinates(m).frame(s, c);
    mismatches += !(a.point == b.point && a.normal == b.normal && a.span_tangent == b.span_tangent &&
                    a.chord_tangent == b.chord_tangent && a.u == b.u && a.v == b.v);
  }
  BOOST_TEST(mismatches == 0);
  // A reference survives the use of kSectionCacheSize - 1 other spans.
  const SpanSection& first = cached.section(0.123);
  const double u = first.u_at_chordwise(0.3);
  for (std::size_t k = 1; k < BladeCoordinates::kSectionCacheSize; ++k) cached.section(0.5 + 1e-3 * k);
  BOOST_TEST(first.span() == 0.123);
  BOOST_TEST(first.u_at_chordwise(0.3) == u);
  BOOST_TEST(&cached.section(0.123) == &first);
  // A span outside the surface's domain throws and leaves the cache usable.
  BOOST_CHECK_THROW(cached.section(5.0), InvalidGeometry);
  BOOST_TEST(cached.frame(0.4, 0.2).point == BladeCoordinates(m).frame(0.4, 0.2).point);
}
