// The hand-off files of the rotor with centreline TE slots (data/examples/hpt_rotor_centreline.json;
// STEP AP214), each read back by a reader that is not ours.
#define BOOST_TEST_MODULE acceptance_centreline
#include <boost/test/unit_test.hpp>

#include <fstream>

#include "acceptance/handoff_checks.hpp"
#include "acceptance/import_round_trip.hpp"

using namespace cg;

namespace {
const test::ProductBuild& build() { return test::product_build("hpt_rotor_centreline.json"); }
}  // namespace

BOOST_AUTO_TEST_CASE(step_ap214_one_valid_named_solid) { test::check_step(build()); }
BOOST_AUTO_TEST_CASE(iges_sews_into_a_closed_shell) { test::check_iges(build()); }
BOOST_AUTO_TEST_CASE(stl_closed_and_outward) { test::check_stl(build()); }
BOOST_AUTO_TEST_CASE(vtk_closed_outward_normals_out) { test::check_vtk(build()); }

// "output": {"iges_mode": "brep", "formats": ["iges", "brep"]}: MSBO solids that OCCT's reader takes
// as valid closed solids of the part's volumes, without sewing.
BOOST_AUTO_TEST_CASE(iges_brep_mode_reads_as_solids) {
  test::TempDir dir("acceptance_iges_brep");
  auto cfg = nlohmann::json::parse(
      test::read_text(std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples/hpt_rotor_centreline.json"));
  cfg["output"]["iges_mode"] = "brep";
  cfg["output"]["formats"] = {"iges"};
  const auto file = dir.path / "brep_mode.json";
  std::ofstream(file) << cfg.dump();
  const test::Run run = test::run_cli("build " + test::q(file) + " -o " + test::q(dir.path / "out") + " -q", dir.path);
  BOOST_TEST_REQUIRE(run.exit_code == 0, run.err);
  const std::string text = test::read_text(dir.path / "out" / "blade.igs");
  BOOST_TEST(text.find("     186") != std::string::npos, "an MSBO entity in the directory");
  const test::IgesSolids r = test::read_iges_solids(dir.path / "out" / "blade.igs");
  BOOST_TEST(r.solids == static_cast<int>(build().bodies.size()));
  BOOST_TEST(r.invalid == 0);
  BOOST_TEST(r.free_edges == 0);
  test::check_volumes(r.volumes, build(), "IGES brep mode");
}

// Round trip with cooling through section tables (acceptance/import_round_trip.hpp): x r theta tables
// without sides, the LE and TE found on the camber line as the parametric sections put them (with the
// centre-line rule the TE slots left the blade early at span 0.71: the TE sits 0.3-0.5 mm round its circle).
BOOST_AUTO_TEST_CASE(section_tables_round_trip_cools_the_same) {
  test::expect_round_trip_cools_the_same(build(), "hpt_rotor_centreline.json", test::ImportVia::Tables, "camber_line");
}
