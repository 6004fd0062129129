// The hand-off files of the C3X film vane (data/examples/c3x_film_vane.json: film rows, a showerhead
// and an impingement insert, so two bodies; STEP AP214), each read back by a reader that is not ours,
// and report.html in headless Chromium (tests/acceptance/report_page_checks.hpp).
#define BOOST_TEST_MODULE acceptance_c3x_film
#include <boost/test/unit_test.hpp>

#include "acceptance/handoff_checks.hpp"
#include "acceptance/report_page_checks.hpp"
#include "acceptance/network_checks.hpp"

using namespace cg;

namespace {
const test::ProductBuild& build() { return test::product_build("c3x_film_vane.json"); }
}  // namespace

BOOST_AUTO_TEST_CASE(two_bodies) { BOOST_TEST(build().bodies == (std::vector<std::string>{"blade", "insert_1"})); }
BOOST_AUTO_TEST_CASE(step_ap214_valid_named_solids) { test::check_step(build()); }
BOOST_AUTO_TEST_CASE(iges_sews_into_closed_shells) { test::check_iges(build()); }
BOOST_AUTO_TEST_CASE(stl_closed_and_outward) { test::check_stl(build()); }
BOOST_AUTO_TEST_CASE(vtk_closed_outward_normals_out) { test::check_vtk(build()); }

namespace utf = boost::unit_test;

BOOST_AUTO_TEST_CASE(glb_passes_the_khronos_validator, *utf::precondition(test::BrowserTools())) {
  test::check_glb_validates(build());
}
// 160 faces of both bodies (blade.step read by OCCT), 83 film and showerhead holes.
BOOST_AUTO_TEST_CASE(report_html_in_a_browser, *utf::precondition(test::BrowserTools())) {
  test::check_report_page(build(), 160, 83, "casing", "report_c3x_film");
}
// The coolant network ("coolant" in the example): 83 film and showerhead holes, no turnaround, two
// chambers of at least 9 segments each (chamber_1 is fed by the insert's jets at its middle and its
// ends beyond the last showerhead holes carry no flow: the network measures extra stations there);
// every segment end station's area against OCCT's plane section of blade.step (span 76.2 mm).
BOOST_AUTO_TEST_CASE(network_deck_converges_in_ccx_and_conserves_mass) {
  test::check_network_deck(build(), {83, 0, {"chamber_1", "chamber_2"}});
}
BOOST_AUTO_TEST_CASE(film_holes_csv_on_the_outer_wall_along_the_cylinders) { test::check_film_holes_csv(build(), 83); }
BOOST_AUTO_TEST_CASE(network_station_areas_equal_occt_plane_sections) { test::check_straight_station_areas(build(), 76.2); }
