// Direct drilling into the cooled example blade (chambers, ribs, fillets): film holes from the outer
// wall into the chambers, checked on the built solid (verify_solid: BRepCheck, free edges, closed
// mesh) and per hole against the independent quadrature (1e-6 relative + edge-tolerance uncertainty).
#define BOOST_TEST_MODULE drill_cooled
#include <boost/test/unit_test.hpp>

#include <TopExp_Explorer.hxx>

#include "features/drilling/drill_holes.hpp"
#include "tests/support/drill_sample_holes.hpp"
#include "passage_fixtures.hpp"

using namespace cg;

BOOST_AUTO_TEST_CASE(film_holes_drilled_into_the_chambers) {
  const test::CooledBlade& c = test::cooled_example("");
  features::FilmFieldOptions fo;
  fo.count = 40;
  const std::vector<features::CylindricalHole> holes = features::film_hole_field(c.model, c.cooled.blade, fo);
  BOOST_TEST_REQUIRE(holes.size() == 40u);
  features::DrillOptions o;
  o.verify_solid = true;
  const features::DrillResult r = features::drill_holes(c.cooled.blade, holes, o);
  BOOST_TEST(r.drilled == 40);
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  double removed = 0;
  for (const auto& h : r.holes) {
    BOOST_TEST(h.entry_face == "blade_wall", h.name);
    BOOST_TEST(h.exit_face.rfind("chamber_", 0) == 0u, h.name << " exits into " << h.exit_face);
    BOOST_TEST(std::abs(h.volume - h.independent_volume) <= 1e-6 * h.independent_volume + h.uncertainty, h.name);
    BOOST_TEST(h.name.rfind("film_row_", 0) == 0u);
    removed += h.volume;
  }
  BOOST_TEST(std::abs(r.check.volume - (c.cooled.check.volume - removed)) <= 1e-6 * c.cooled.check.volume);
  // Every face of the cooled blade keeps its name; each hole adds one face named after it.
  const auto before = brep::count_face_names(c.cooled.blade), after = brep::count_face_names(r.part);
  for (const auto& [name, n] : before) BOOST_TEST(after.at(name) == n, name);
  for (const auto& h : holes) BOOST_TEST(after.at(h.name) == 1, h.name);
}

BOOST_AUTO_TEST_CASE(a_hole_into_a_rib_falls_back) {
  // The same field, one hole moved onto the rib rib_2: it meets the rib (or its
  // fillet), so the direct path does not take it and the verified boolean path cuts it.
  const test::CooledBlade& c = test::cooled_example("");
  features::FilmFieldOptions fo;
  fo.count = 4;
  std::vector<features::CylindricalHole> holes = features::film_hole_field(c.model, c.cooled.blade, fo);
  const std::vector<TopoDS_Face> ribs = test::named_faces(c.cooled.blade, {"rib_2"});
  BOOST_TEST_REQUIRE(!ribs.empty());
  // Aim hole 0 at the rib: start outside the blade along the rib face's outward side.
  const std::vector<gp_Pnt> pts = test::face_points(ribs.front(), 5);
  BOOST_TEST_REQUIRE(!pts.empty());
  const gp_Pnt on_rib = pts[pts.size() / 2];
  const Eigen::Vector3d target(on_rib.X(), on_rib.Y(), on_rib.Z());
  const Eigen::Vector3d dir = (target - holes[0].origin).normalized();
  holes[0].axis = dir;
  holes[0].length = (target - holes[0].origin).norm() + 0.2;
  const features::DrillResult r = features::drill_holes(c.cooled.blade, holes);
  BOOST_TEST(!r.holes[0].drilled);
  BOOST_TEST(!r.holes[0].fallback_reason.empty());
  BOOST_TEST(r.fallback.tool_count == 1);
  BOOST_TEST(r.fallback.check.all_passed(), r.fallback.check.failed_names());
  BOOST_TEST(r.drilled == 3);
}
