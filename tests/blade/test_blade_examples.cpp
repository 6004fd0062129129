// The example configurations in data/examples parse (src/config) and build valid blade models.
#define BOOST_TEST_MODULE blade_examples
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "src/blade/blade_coordinates.hpp"
#include "src/config/config.hpp"

using namespace cg;

namespace {
const std::string kExamples = std::string(COOLINGGEN_SOURCE_DIR) + "/data/examples/";
}

BOOST_AUTO_TEST_CASE(c3x_vane_example) {
  const config::Config c = config::load_config_file(kExamples + "c3x_vane.json");
  const blade::BladeModel m = config::build_model(c);
  BOOST_TEST(m.trim.straight);
  BOOST_TEST(m.trim.casing_z == 144.93);
  // The profile is the published one in mm: true chord 144.93 mm to 0.5 % (see test_sections).
  BOOST_TEST(std::abs(m.profiles[0].chord() - 144.93) < 5e-3 * 144.93);
  BOOST_TEST(m.surface.is_periodic_u());
}

BOOST_AUTO_TEST_CASE(hpt_rotor_example) {
  const config::Config c = config::load_config_file(kExamples + "hpt_rotor.json");
  const blade::BladeModel m = config::build_model(c);
  BOOST_TEST(!m.trim.straight);
  BOOST_TEST_REQUIRE(m.net.has_value());
  BOOST_TEST(m.net->streamlines().size() == 5u);  // hub, 3 interpolated, casing
  // Engine-scale numbers the example claims: hub radius ~275 mm, span ~55 mm, axial chord ~36 mm.
  const auto& le = m.net->leading_edge()->cuts;
  BOOST_TEST(std::abs(le.front().point.y() - 275) < 1.0);
  BOOST_TEST(m.span_length > 50);
  BOOST_TEST(m.span_length < 60);
  double xmin = 1e9, xmax = -1e9;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3d p = m.surface.point(i / 400.0, 0.0);
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
  }
  BOOST_TEST(xmax - xmin > 33);
  BOOST_TEST(xmax - xmin < 40);
  blade::BladeCoordinates bc(m);
  const blade::BladeCoordinate q{0.5, 0.2, 0.5};
  const auto r = bc.locate(bc.point(q));
  BOOST_TEST_REQUIRE(r.found);
  BOOST_TEST(std::abs(r.coordinate.chord - 0.2) < 1e-9);
}
