// The imported example (data/examples/naca_rotor_import.json: a geomTurbo file written by the
// stand-alone script naca_rotor_geomturbo.py, not by our exporter) built and cooled by the CLI; its
// STEP read back by OCCT; the import's figures against what the script wrote; and the run's own
// blade.geomTurbo fed back into blade.import.
#define BOOST_TEST_MODULE acceptance_import
#include <boost/test/unit_test.hpp>

#include <fstream>

#include "acceptance/handoff_checks.hpp"

using namespace cg;

namespace {
const test::ProductBuild& build() { return test::product_build("naca_rotor_import.json"); }

int faces_starting(const std::string& prefix) {
  int n = 0;
  for (const std::string& f : build().face_names) n += f.rfind(prefix, 0) == 0 ? 1 : 0;
  return n;
}
}  // namespace

BOOST_AUTO_TEST_CASE(step_one_valid_named_solid) { test::check_step(build()); }

// The cooling of the config is all there: two ribs, two film rows, tip cap, hub floor, inlets, TE slots.
BOOST_AUTO_TEST_CASE(cooled_with_every_feature) {
  for (const char* f : {"rib_1", "rib_2", "film_row_1_hole", "film_row_2_hole", "tip_cap", "hub_floor", "inlet_", "te_slot_"})
    BOOST_TEST(faces_starting(f) > 0, f);
}

// What the script wrote: 6 ZRTH sections, the lowest (r = 266) below the hub and the highest (r = 340)
// above the casing, 60 blades, a 0.4 mm tip gap (the file is in metres).
BOOST_AUTO_TEST_CASE(import_figures) {
  const auto& im = build().report.at("model").at("import");
  BOOST_TEST(im.at("format").get<std::string>() == "geomturbo");
  BOOST_TEST(im.at("row").get<std::string>() == "annular");
  BOOST_TEST(im.at("number_of_blades").get<int>() == 60);
  BOOST_TEST(std::abs(im.at("tip_gap_mm").at("leading_edge").get<double>() - 0.4) < 1e-9);
  BOOST_TEST(std::abs(im.at("tip_gap_mm").at("trailing_edge").get<double>() - 0.4) < 1e-9);
  BOOST_TEST_REQUIRE(im.at("sections").size() == 6u);
  BOOST_TEST(im.at("sections")[0].at("at_points").at("points").get<int>() == 0, "section 1 lies below the hub");
  BOOST_TEST(im.at("sections")[5].at("at_points").at("points").get<int>() == 0, "section 6 lies above the casing");
  for (int k = 1; k < 5; ++k) BOOST_TEST(im.at("sections")[k].at("at_points").at("points").get<int>() > 0, k);
  BOOST_TEST(im.at("deviation").at("max_mm").get<double>() <= 0.01);
  BOOST_TEST_MESSAGE("naca_rotor_import: deviation max " << im.at("deviation").at("max_mm") << " rms "
                     << im.at("deviation").at("rms_mm") << " mm over " << im.at("deviation").at("points") << " points");
}

// The run's blade.geomTurbo imported again: the same blade within 0.01 mm (the import's own measure,
// at the file's points and between them and its sections), and the blade count written back.
BOOST_AUTO_TEST_CASE(exported_geomturbo_imports_again) {
  const std::string text = test::read_text(build().file("blade.geomTurbo"));
  BOOST_TEST(text.find("number_of_blades 60") != std::string::npos);
  BOOST_TEST(text.find("ZRTH") != std::string::npos);
  test::TempDir dir("acceptance_import_again");
  std::ofstream(dir.path / "again.json") << R"({"units": "mm", "blade": {"import": {"format": "geomturbo", "file": ")"
                                         << build().file("blade.geomTurbo").string() << "\"}}}";
  const test::Run run = test::run_cli("validate " + test::q(dir.path / "again.json"), dir.path);
  BOOST_TEST(run.exit_code == 0, run.err);
}
