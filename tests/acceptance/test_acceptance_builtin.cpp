// The hand-off files of the built-in example (`coolinggen build -o DIR`: the cooled HPT rotor blade with
// chambers, ribs, fillets, turbulators, pins, TE slots, 153 film holes and a showerhead; STEP AP242),
// each read back by a reader that is not ours (tests/acceptance/handoff_checks.hpp), and report.html in
// headless Chromium (tests/acceptance/report_page_checks.hpp).
#define BOOST_TEST_MODULE acceptance_builtin
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "acceptance/handoff_checks.hpp"
#include "acceptance/import_round_trip.hpp"
#include "acceptance/report_page_checks.hpp"
#include "acceptance/network_checks.hpp"

using namespace cg;

namespace {
const test::ProductBuild& build() { return test::product_build(""); }
}  // namespace

BOOST_AUTO_TEST_CASE(step_ap242_one_valid_named_solid) { test::check_step(build()); }

// The hand-off outputs (README, Outputs) and nothing else, no temporary files (preview.png only when an
// X display could be had); every check of report.json passed; the passage table (report.json
// "sections", what sections.svg shows): all four chambers at every span, the film and showerhead holes
// and TE slots crossing the cuts as holes, none of them a passage (issue 20).
BOOST_AUTO_TEST_CASE(outputs_report_checks_and_passage_table) {
  std::set<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(build().dir)) files.insert(e.path().filename().string());
  std::set<std::string> expected{"blade.step", "blade.igs",   "blade.brep",  "blade.stl", "blade.vtm", "blade_blade.vtp",
                                 "blade.glb",  "sections.svg", "report.html", "report.json", "report.md",
                                 // the coolant network: the built-in example has a "coolant" section
                                 "network.json", "network.inp", "network_results.json", "film_holes.csv"};
  if (files.count("preview.png")) expected.insert("preview.png");
  BOOST_TEST(files == expected);
  const nlohmann::json& report = build().report;
  BOOST_TEST(report.at("valid").get<bool>());
  BOOST_TEST(report.at("model").at("name").get<std::string>() == "hpt_rotor");
  for (const auto& [name, c] : report.at("checks").items()) BOOST_TEST(c.at("passed").get<bool>(), name);
  std::size_t holes = 0;
  for (const auto& s : report.at("sections")) {
    std::vector<std::string> names;
    for (const auto& p : s.at("passages")) names.push_back(p.at("name").get<std::string>());
    BOOST_TEST((names == std::vector<std::string>{"chamber_1", "chamber_2", "chamber_3", "chamber_4"}), "span " << s.at("span"));
    for (const auto& h : s.at("holes")) {
      const std::string n = h.at("name").get<std::string>();
      BOOST_TEST((n.rfind("showerhead_", 0) == 0 || n.rfind("film_row_", 0) == 0 || n.rfind("te_slot_", 0) == 0), n);
    }
    holes += s.at("holes").size();
  }
  BOOST_TEST(report.at("sections").size() == 5u);
  BOOST_TEST(holes >= 15u);  // 18 at the five default spans
}
BOOST_AUTO_TEST_CASE(iges_sews_into_a_closed_shell) { test::check_iges(build()); }
BOOST_AUTO_TEST_CASE(stl_closed_and_outward) { test::check_stl(build()); }
BOOST_AUTO_TEST_CASE(vtk_closed_outward_normals_out) { test::check_vtk(build()); }

namespace utf = boost::unit_test;

BOOST_AUTO_TEST_CASE(glb_passes_the_khronos_validator, *utf::precondition(test::BrowserTools())) {
  test::check_glb_validates(build());
}
// 652 faces (blade.step read by OCCT), 153 film and showerhead holes; the tip end face is seen from the
// page's default view.
BOOST_AUTO_TEST_CASE(report_html_in_a_browser, *utf::precondition(test::BrowserTools())) {
  test::check_report_page(build(), 652, 153, "casing", "report_builtin");
}
BOOST_AUTO_TEST_CASE(report_html_with_a_truncated_model_says_broken, *utf::precondition(test::BrowserTools())) {
  test::check_truncated_model_is_broken(build());
}
// The coolant network (the built-in example has a "coolant" section, so "network" is a default format):
// 153 film and showerhead holes, two turnarounds (ribs 2 and 3), four chambers.
BOOST_AUTO_TEST_CASE(network_deck_converges_in_ccx_and_conserves_mass) {
  test::check_network_deck(build(), {153, 2, {"chamber_1", "chamber_2", "chamber_3", "chamber_4"}});
}
// One pin bank in front of each of the 18 slots, its loss against Metzger's correlation by hand.
BOOST_AUTO_TEST_CASE(pin_banks_in_the_deck_follow_metzger) { test::check_pin_banks(build(), 18); }
// The example's slots are 0.4 mm high (cooling.core.trailing_edge.slot_height).
BOOST_AUTO_TEST_CASE(film_holes_csv_on_the_outer_wall_along_the_cylinders) { test::check_film_holes_csv(build(), 153, 0.4); }

// Round trip with cooling through the uncooled blade's named STEP file (acceptance/import_round_trip.hpp;
// data/examples/hpt_rotor.json is the built-in example): the 15 cuts' LE and TE found on the camber line;
// the part's feature names are the built-in build's.
BOOST_AUTO_TEST_CASE(step_round_trip_cools_the_same) {
  test::expect_round_trip_cools_the_same(build(), "hpt_rotor.json", test::ImportVia::Step, "camber_line");
}
