// The hand-off files of the C3X film vane (data/examples/c3x_film_vane.json: film rows, a showerhead
// and an impingement insert, so two bodies; STEP AP214), each read back by a reader that is not ours.
#define BOOST_TEST_MODULE acceptance_c3x_film
#include <boost/test/unit_test.hpp>

#include "acceptance/handoff_checks.hpp"

using namespace cg;

namespace {
const test::ProductBuild& build() { return test::product_build("c3x_film_vane.json"); }
}  // namespace

BOOST_AUTO_TEST_CASE(two_bodies) { BOOST_TEST(build().bodies == (std::vector<std::string>{"blade", "insert_1"})); }
BOOST_AUTO_TEST_CASE(step_ap214_valid_named_solids) { test::check_step(build()); }
BOOST_AUTO_TEST_CASE(iges_sews_into_closed_shells) { test::check_iges(build()); }
BOOST_AUTO_TEST_CASE(stl_closed_and_outward) { test::check_stl(build()); }
BOOST_AUTO_TEST_CASE(vtk_closed_outward_normals_out) { test::check_vtk(build()); }
