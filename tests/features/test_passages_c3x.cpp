// The NASA C3X vane with its ten radial cooling passages (NASA CR-168015 Fig. 7), straight through the span
// and open at both ends, and the C3X vane with one large chamber open at the tip.
#define BOOST_TEST_MODULE passages_c3x
#include <boost/test/unit_test.hpp>

#include <BRepTools.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "features/passage_fixtures.hpp"
#include "src/core/constants.hpp"

using namespace cg;

namespace {
using cg::kPi;
const test::CooledBlade& c3x() { return test::cooled_example(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"); }
const test::CooledBlade& open_chamber() {
  return test::cooled_example(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane_open_chamber.json");
}
// Published diameters of Fig. 7, mm: passages 1-7, 8-9, 10.
double published_diameter(int k) { return k <= 7 ? 6.30 : k <= 9 ? 3.10 : 1.98; }

int inner_wires(const TopoDS_Face& f) {
  int n = 0;
  for (TopExp_Explorer e(f, TopAbs_WIRE); e.More(); e.Next()) ++n;
  return n - 1;
}
}  // namespace

BOOST_AUTO_TEST_CASE(ten_passages_with_the_published_cross_sections) {
  const auto& r = c3x().cooled;
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  BOOST_TEST_REQUIRE(r.report.passages.size() == 10u);
  for (std::size_t k = 0; k < 10; ++k) {
    const auto& p = r.report.passages[k];
    BOOST_TEST(p.name == "radial_passage_" + std::to_string(k + 1));
    BOOST_TEST(p.sections.size() >= 10u);
    const double d = published_diameter(static_cast<int>(k) + 1);
    for (const auto& c : p.sections) {
      // Measured on the built solid: the section of the passage's faces by the plane z = span * 144.93 mm.
      BOOST_TEST(std::abs(std::sqrt(4 * c.area / kPi) - d) <= 1e-6 * d, p.name << " at span " << c.span);
      BOOST_TEST(std::abs(c.hydraulic_diameter - d) <= 1e-6 * d, p.name << " at span " << c.span);
      BOOST_TEST(std::abs(c.wetted_perimeter - kPi * d) <= 1e-6 * kPi * d);
    }
  }
}

BOOST_AUTO_TEST_CASE(passages_run_through_and_open_at_both_ends) {
  const auto& b = c3x().cooled.blade;
  const auto hub = test::named_faces(b, {"hub"}), casing = test::named_faces(b, {"casing"});
  BOOST_TEST_REQUIRE(hub.size() == 1u);
  BOOST_TEST_REQUIRE(casing.size() == 1u);
  BOOST_TEST(inner_wires(hub[0]) == 10);
  BOOST_TEST(inner_wires(casing[0]) == 10);
  for (int k = 1; k <= 10; ++k) BOOST_TEST(test::named_faces(b, {"radial_passage_" + std::to_string(k)}).size() == 1u);
  // Removed volume: pi r^2 x span for each passage, against the two solids' volumes.
  double expected = 0;
  for (int k = 1; k <= 10; ++k) expected += kPi * 0.25 * published_diameter(k) * published_diameter(k) * 144.93;
  const double removed = test::volume(c3x().blade.shape) - test::volume(b.shape);
  BOOST_TEST(std::abs(removed - expected) <= 1e-6 * expected);
  for (const auto& t : c3x().cooled.report.tools) BOOST_TEST(std::abs(t.measured - t.expected) <= 1e-6 * t.expected);
}

BOOST_AUTO_TEST_CASE(walls_between_passages_and_the_surface) {
  // The data's README gives a minimum wall of about 1.64 mm (passage 10 near the TE).
  double wall_min = HUGE_VAL;
  for (const auto& t : c3x().cooled.report.thickness) {
    BOOST_TEST(t.passed, t.feature);
    wall_min = std::min(wall_min, t.min);
  }
  BOOST_TEST(std::abs(wall_min - 1.64) < 0.01);
  const double measured = test::min_distance(test::named_faces(c3x().cooled.blade, {"blade_wall"}),
                                             test::named_faces(c3x().cooled.blade, {"radial_passage_10"}));
  BOOST_TEST(std::abs(measured - wall_min) < 1e-6);
}

BOOST_AUTO_TEST_CASE(open_chamber_vane) {
  const auto& r = open_chamber().cooled;
  const auto& core = *open_chamber().config.cooling.passages.core;
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  int shells = 0;
  for (TopExp_Explorer e(r.blade.shape, TopAbs_SHELL); e.More(); e.Next()) ++shells;
  BOOST_TEST(shells == 1);
  // Open at the tip: the casing end face is a ring around the chamber; the hub floor closes the hub.
  BOOST_TEST(inner_wires(test::named_faces(r.blade, {"casing"}).at(0)) == 1);
  BOOST_TEST(inner_wires(test::named_faces(r.blade, {"hub"}).at(0)) == 0);
  const double t = core.wall_thickness.min_value();
  const auto outer = test::named_faces(r.blade, {"blade_wall"});
  const double dmin = test::min_distance(outer, test::named_faces(r.blade, {"chamber_*"}));
  double dmax = 0;
  for (const gp_Pnt& p : test::face_points(test::named_faces(r.blade, {"chamber_1_wall"}).at(0), 6)) {
    BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(p).Vertex(), test::compound(outer));
    dmax = std::max(dmax, d.Value());
  }
  BOOST_TEST(std::abs(dmin - t) <= test::thickness_tolerance(t));
  BOOST_TEST(std::abs(dmax - t) <= test::thickness_tolerance(t));
  const double floor = test::min_distance(test::named_faces(r.blade, {"hub"}), test::named_faces(r.blade, {"hub_floor"}));
  BOOST_TEST(std::abs(floor - core.hub_floor.thickness) <= test::thickness_tolerance(core.hub_floor.thickness));
  BOOST_TEST_REQUIRE(r.report.tools.size() == 1u);  // cut through the open tip: expected = OCCT Common with the blade
  BOOST_TEST(std::abs(r.report.tools[0].measured - r.report.tools[0].expected) <= 1e-6 * r.report.tools[0].expected);
  BOOST_TEST(r.report.passages.at(0).fed_by == "open tip");
}
