// The speed paths of the wall features, checked against the plain ones: WallLines' local ray casters
// (patches near the segment) against a caster of the whole surface, on the built-in blade's periodic
// wall with segments across its seam; and the turbulator / pin / slot chain (verify_solid once on its
// result) still checks every tool's volume, names every face by its feature, and verifies the result.
#define BOOST_TEST_MODULE wall_feature_chain
#include <boost/test/unit_test.hpp>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <random>

#include "boolean_test_shapes.hpp"
#include "features/wall/wall_features.hpp"
#include "features/wall/wall_lines.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

using namespace cg;

namespace {

// Every crossing of a -> b with the whole surface's caster (the restart rule of WallLines).
std::vector<double> full_crossings(RaySurfaceCaster& c, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  std::vector<double> out;
  const double len = (b - a).norm();
  const Eigen::Vector3d d = (b - a) / len;
  double s = 0;
  while (s < len && out.size() <= 64) {
    const RaySurfaceHit h = c.first_hit(a + s * d, d, len - s);
    if (!h.found) break;
    s += h.ray_param;
    out.push_back(s / len);
    s += 1e-9;
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(local_casters_find_the_crossings_of_the_whole_surface) {
  const blade::BladeModel model = config::build_model(config::builtin_example_config());
  const BSplineSurface<3>& wall = model.surface;
  BOOST_REQUIRE(wall.is_periodic_u());
  features::LocalCaster lc(wall);
  features::WallLines lines(wall, wall);
  RaySurfaceCaster full(wall);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, crossings = 0;
  for (int k = 0; k < 400; ++k) {
    // Segments through points near the wall (a quarter of them at the periodic seam u = first_u), of
    // lengths 0.2 .. 40 mm in random directions: short ones inside one patch, long ones across many.
    const double u = k % 4 == 0 ? wall.first_u() + 1e-3 * (unit(rng) - 0.5) * (wall.last_u() - wall.first_u())
                                : wall.first_u() + unit(rng) * (wall.last_u() - wall.first_u());
    const double v = wall.first_v() + unit(rng) * (wall.last_v() - wall.first_v());
    const Eigen::Vector3d p = wall.point(u, v) + Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
    const Eigen::Vector3d d = Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
    const double len = 0.2 * std::pow(200.0, unit(rng));
    const Eigen::Vector3d a = p - 0.5 * len * d, b = p + 0.5 * len * d;
    const std::vector<double> local = full_crossings(lc.for_segment(a, b), a, b), ref = full_crossings(full, a, b);
    BOOST_TEST(lines.outer_crossings(a, b) == local);  // WallLines goes through the same local casters
    BOOST_TEST_REQUIRE(local.size() == ref.size(), "segment " << k << ": " << local.size() << " crossings, the whole "
                                                              "surface has " << ref.size());
    // Same Bézier patches, same Newton tolerance: the crossings agree to rounding; 1e-9 mm is the
    // restart step of WallLines, far below any feature.
    for (std::size_t i = 0; i < ref.size(); ++i) BOOST_TEST(std::abs(local[i] - ref[i]) * len <= 1e-9);
    ++compared;
    crossings += static_cast<int>(ref.size());
  }
  BOOST_TEST(compared == 400);
  // Most segments are answered locally, those across the periodic seam too (by the patches each segment
  // passes through; only a segment through most of the wall's patches would take the whole surface).
  BOOST_TEST_MESSAGE("local " << lc.local_queries << ", whole surface " << lc.full_queries);
  BOOST_TEST(lc.local_queries >= 360);
  BOOST_TEST(crossings > 100);  // the segments do cross the wall (the test compares something)
}

namespace {

// A block part and one tool per group: a turbulator-like box fused on top, a pin-like cylinder fused on
// the side, a slot-like box cut from a corner; expected volumes analytic.
features::WallFeatureBuild block_features(double slot_expected) {
  features::WallFeatureBuild b;
  features::FeatureTool turb;
  turb.feature = "turbulator_2_001";
  turb.shape = test::named_all(BRepPrimAPI_MakeBox(gp_Pnt(2, 2, 9), 3, 1, 2).Shape(), turb.feature);
  turb.expected_volume = 3 * 1 * 1;  // the part above z = 10
  b.turbulators.tools.push_back(turb);
  b.trailing_edge.pin_tools.push_back(
      test::cylinder_tool("pin_fin_001", gp_Pnt(-1, 5, 5), gp_Dir(1, 0, 0), 0.5, 2, test::kPi * 0.25 * 1));
  features::FeatureTool slot;
  slot.feature = "te_slot_01";
  slot.shape = test::named_all(BRepPrimAPI_MakeBox(gp_Pnt(8, 8, -1), 4, 4, 3).Shape(), slot.feature);
  slot.expected_volume = slot_expected;  // the part inside: 2 x 2 x 2
  b.trailing_edge.slot_tools.push_back(slot);
  return b;
}

}  // namespace

BOOST_AUTO_TEST_CASE(chain_names_every_face_and_verifies_the_result) {
  features::WallFeatureBuild b = block_features(8.0);
  features::PassageReport report;
  const brep::NamedShape r = features::apply_wall_feature_tools(test::named_block(10, 10, 10), b, report);
  BOOST_REQUIRE(b.steps.size() == 3u);
  BOOST_TEST(b.steps.back().check.all_passed(), b.steps.back().check.failed_names());
  BOOST_TEST(b.steps.back().check.one_solid.passed);
  for (const auto& f : r.faces) {
    const bool known = f.name.rfind("block_", 0) == 0 || f.name == "turbulator_2_001" || f.name == "pin_fin_001" ||
                       f.name == "te_slot_01";
    BOOST_TEST(known, "face named '" << f.name << "'");
  }
  for (const char* n : {"turbulator_2_001", "pin_fin_001", "te_slot_01"}) BOOST_TEST(test::count_name(r, n) > 0, n);
  BOOST_REQUIRE(report.tools.size() == 3u);
  for (const auto& t : report.tools) BOOST_TEST(t.passed, t.feature);
  GProp_GProps p;
  BRepGProp::VolumeProperties(r.shape, p, 1e-9);
  BOOST_TEST(std::abs(p.Mass() - (1000 + 3 + test::kPi * 0.25 - 8)) <= 1e-6);
}

BOOST_AUTO_TEST_CASE(chain_catches_a_wrong_volume_without_per_step_verification) {
  // The slot's expectation 1 % off: the chain stops with the slot named although verify_solid runs on
  // the chain's result only.
  features::WallFeatureBuild b = block_features(8.08);
  features::PassageReport report;
  BOOST_CHECK_EXCEPTION(features::apply_wall_feature_tools(test::named_block(10, 10, 10), b, report),
                        features::FeatureFailure, [](const features::FeatureFailure& e) {
                          return std::string(e.what()).find("te_slot_01") != std::string::npos;
                        });
}
