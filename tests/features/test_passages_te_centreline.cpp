// Trailing-edge slots through the TE centreline (data/examples/hpt_rotor_centreline.json: a two-pass
// core, slots H = 0.4 mm, 1.0 mm wide at the crease, pitch 4 mm, lands tapered 2 deg, two pin rows),
// measured on the built solid against the configuration with OCCT's line intersector: slot height,
// width and pitch; removed volumes against the independent quadrature (1e-6 relative); the crease's
// false seam repaired; face names in the STEP file read back. One build for the whole file.
#define BOOST_TEST_MODULE passages_te_centreline
#include <boost/test/unit_test.hpp>

#include <IntCurvesFace_ShapeIntersector.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/brep/boolean/false_seams.hpp"
#include "features/passage_fixtures.hpp"

using namespace cg;

namespace {

const test::CooledBlade& vane() { return test::cooled_example(COOLINGGEN_SOURCE_DIR "/data/examples/hpt_rotor_centreline.json"); }
const features::TrailingEdgeDefinition& te() { return *vane().config.cooling.passages.core->trailing_edge; }
const std::vector<features::SlotInfo>& slots() { return vane().cooled.wall_features.trailing_edge.slots; }

std::set<std::string> names_with(const brep::NamedShape& s, const std::string& prefix) {
  std::set<std::string> out;
  for (const auto& f : s.faces)
    if (f.name.rfind(prefix, 0) == 0) out.insert(f.name);
  return out;
}


// Parameters where the line p + t d (|d| = 1) crosses the built solid, sorted (OCCT's intersector).
std::vector<double> crossings(const Eigen::Vector3d& p, const Eigen::Vector3d& d, double t0, double t1) {
  IntCurvesFace_ShapeIntersector in;
  in.Load(vane().cooled.blade.shape, 1e-9);
  in.Perform(gp_Lin(occt::to_pnt(p), gp_Dir(d.x(), d.y(), d.z())), t0, t1);
  std::vector<double> out;
  for (int i = 1; i <= in.NbPnt(); ++i) out.push_back(in.WParameter(i));
  std::sort(out.begin(), out.end());
  return out;
}

// Station between the crease (x = 0) and the TE where the probes run: the slot is there H high and
// w - 2 x tan(taper) wide.
double probe_x(const features::SlotInfo& s) { return 0.4 * (s.x_end - 1.0); }
double width_at(double x) { return te().slot_width - 2 * x * std::tan(te().land_taper_deg * M_PI / 180); }

}  // namespace

BOOST_AUTO_TEST_CASE(one_valid_solid_and_every_slot_verified) {
  const auto& r = vane().cooled;
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  for (const auto& [stage, seconds] : r.report.seconds) BOOST_TEST_MESSAGE("  " << stage << " " << seconds << " s");
  int n = 0;
  for (const auto& t : r.report.tools) {
    if (t.feature.rfind("te_slot_", 0) != 0) continue;
    ++n;
    BOOST_TEST(t.passed, t.feature);
    BOOST_TEST(t.how == "cut");
    // The step's own check, restated: removed volume against the quadrature of the ruled channel.
    BOOST_TEST(std::abs(t.measured - t.expected) <= 1e-6 * t.expected, t.feature << ": " << t.measured << " vs " << t.expected);
    BOOST_TEST_MESSAGE(t.feature << " removed " << t.measured << " mm^3, expected " << t.expected);
  }
  // Count: from the pitch, between the end walls; the same on the solid and in the report.
  BOOST_TEST(n == static_cast<int>(slots().size()));
  BOOST_TEST(n >= 10);
  BOOST_TEST(names_with(r.blade, "te_slot_").size() == slots().size());
  BOOST_TEST(!names_with(r.blade, "pin_fin_").empty());
  // The crease is no longer a false seam of the part (src/brep/boolean/false_seams.hpp).
  BOOST_TEST(features::repair_false_seams(r.blade).repaired_edges == 0);
}

BOOST_AUTO_TEST_CASE(slot_height_on_the_built_solid) {
  // A line along each probed slot's y (normal to its floor and ceiling) through its middle between the
  // crease and the TE: suction surface, slot floor, slot ceiling, pressure surface. The floor and ceiling
  // are planes y = -+H/2, so floor to ceiling is H to rounding (1e-9 mm).
  for (std::size_t k : {std::size_t{0}, slots().size() / 2, slots().size() - 1}) {
    const auto& s = slots()[k];
    const Eigen::Vector3d p = s.origin + probe_x(s) * s.x;
    const std::vector<double> t = crossings(p, s.y, -5, 5);
    BOOST_TEST_REQUIRE(t.size() == 4u, s.name << ": " << t.size() << " crossings");
    BOOST_TEST_MESSAGE(s.name << ": slot height " << t[2] - t[1] << " mm, walls " << t[1] - t[0] << " / " << t[3] - t[2]);
    BOOST_TEST(std::abs((t[2] - t[1]) - te().slot_height) <= 1e-9, s.name << ": " << t[2] - t[1]);
    BOOST_TEST(std::abs(t[1] + 0.5 * te().slot_height) <= 1e-9);  // centred on the centreline
    BOOST_TEST(t[1] - t[0] > 0.1);  // wall left on both sides
    BOOST_TEST(t[3] - t[2] > 0.1);
  }
}

BOOST_AUTO_TEST_CASE(slot_width_and_pitch_on_the_built_solid) {
  // Width: a line along the slot's z (normal to the mid-plane of its side faces) through its middle
  // between the crease and the TE crosses the two side planes z = -+(w - 2 x tan(taper)) / 2: exact to
  // rounding. Pitch: a line from the middle of slot k to that of slot k + 1, extended by a slot width at
  // both ends (four crossings: the sides of both slots); the slots' centres on it are `pitch` apart in
  // arc length along the crease, 0.45 mm upstream of which the probes run along the two slots' frames
  // (they turn by ~1e-3 rad between neighbours): 2e-3 mm.
  int pairs = 0;
  for (std::size_t k = 0; k + 1 < slots().size(); k += 3) {
    const auto& a = slots()[k];
    const auto& b = slots()[k + 1];
    const Eigen::Vector3d pa = a.origin + probe_x(a) * a.x, pb = b.origin + probe_x(b) * b.x;
    const std::vector<double> across = crossings(pa, a.z, -te().slot_width, te().slot_width);
    BOOST_TEST_REQUIRE(across.size() == 2u, a.name << ": " << across.size() << " crossings");
    const double w = width_at(probe_x(a));
    BOOST_TEST(std::abs((across[1] - across[0]) - w) <= 1e-9, a.name << ": " << across[1] - across[0] << " vs " << w);
    BOOST_TEST(std::abs(across[1] + across[0]) <= 1e-9);  // centred on the slot's mid-plane
    const Eigen::Vector3d d = (pb - pa).normalized();
    const double len = (pb - pa).norm();
    const std::vector<double> t = crossings(pa, d, -te().slot_width, len + te().slot_width);
    BOOST_TEST_REQUIRE(t.size() == 4u, a.name << " - " << b.name << ": " << t.size() << " crossings");
    const double pitch = 0.5 * (t[2] + t[3]) - 0.5 * (t[0] + t[1]);
    BOOST_TEST_MESSAGE(a.name << ": width " << across[1] - across[0] << " (" << w << "), land " << t[2] - t[1]
                              << " along the line between the slots, pitch " << pitch);
    BOOST_TEST(std::abs(pitch - te().pitch) <= 2e-3, a.name << ": " << pitch);
    ++pairs;
  }
  BOOST_TEST(pairs >= 3);
}

BOOST_AUTO_TEST_CASE(feature_names_in_the_step_file) {
  const auto& r = vane().cooled;
  const test::StepReadBack rb = test::step_round_trip(r.blade, "te_centreline_step");
  BOOST_TEST_REQUIRE(rb.ok);
  BOOST_TEST(rb.free_shapes.size() == 1u);
  for (const char* prefix : {"te_slot_", "pin_fin_", "chamber_"}) {
    std::set<std::string> in_step;
    for (const auto& n : rb.names)
      if (n.rfind(prefix, 0) == 0) in_step.insert(n);
    BOOST_TEST((in_step == names_with(r.blade, prefix)), prefix);
  }
}
