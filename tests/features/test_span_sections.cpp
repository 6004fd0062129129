// Span sections (features/passages/span_sections.hpp: the one routine behind the design checks' cross-sections,
// sections.svg and the passage table) on the real built-in example, built once by the pipeline's own
// cooling and film stages. A light variant: without its turbulators, pin fins and 7-7-7 row (the slow
// booleans), so its chambers' walls are those the design checks measure; its showerhead, four
// cylindrical film rows and pressure-side cutback slots stay, so holes and slots cross the cuts.
//  - every chamber (1 to 4) is a passage at every span of the drawing (0.1 .. 0.9) and of the design
//    checks, once, under its name; no hole or slot is a passage, every opening crossing the cut is closed;
//  - with the holes, the passages equal the design checks' (measured before the holes and slots) at the
//    same spans: area and wetted perimeter within 2e-5 relative (measured up to 7e-6: the walls'
//    loops end at edge crossings, and the edges of the holes' and slots' booleans and of the drilled
//    loops lie up to their tolerance off the walls; tolerance x the 0.1 mm end steps x ~20 crossings
//    per passage stays below 1e-3 mm^2 on passages of 26-72 mm^2);
//  - the holes are the metal the film stage removed: metal area before the holes minus after = the
//    sum of the holes' areas, within 1e-4 mm^2 per hole (the same crossing argument on loops of ~2 mm).
#define BOOST_TEST_MODULE span_sections
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "features/passages/span_sections.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/cooling.hpp"
#include "src/brep/blade_solid.hpp"

using namespace cg;

namespace {

struct Built {
  config::Config config;
  blade::BladeModel model;
  features::PassagesResult passages;  ///< design checks (report) and the blade before the film holes
  features::FilmCoolingResult film;   ///< the blade with its holes
};

const Built& built() {
  static std::unique_ptr<Built> b;
  if (b) return *b;
  const auto t0 = std::chrono::steady_clock::now();
  nlohmann::json d = nlohmann::json::parse(config::builtin_example_json());
  d["cooling"]["core"].erase("turbulators");
  d["cooling"]["core"]["trailing_edge"].erase("pin_fins");
  d["cooling"]["film_rows"].erase(0);  // the 7-7-7 row
  b = std::make_unique<Built>();
  b->config = config::parse_config(d, COOLINGGEN_SOURCE_DIR "/data/examples", "light");
  b->model = config::build_model(b->config);
  const brep::BladeSolid s = brep::build_blade_solid(b->model);
  const features::CoolingPlan plan = pipeline::plan_cooling(b->config.cooling, b->model);
  b->passages = pipeline::apply_cooling(b->model, plan, {s.solid, s.faces}, features::Verification::None);
  b->film = pipeline::apply_film(b->config.cooling, b->model, plan, b->passages, {features::Verification::None, nullptr});
  BOOST_TEST_MESSAGE("light example built in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
                                               << " s");
  return *b;
}

brep::Part holed() { return {{"blade", built().film.blade}}; }

std::vector<double> check_spans() {
  std::vector<double> s;
  for (const auto& c : built().passages.report.passages.front().sections) s.push_back(c.span);
  return s;
}

const std::vector<std::string> kChambers{"chamber_1", "chamber_2", "chamber_3", "chamber_4"};

}  // namespace

BOOST_AUTO_TEST_CASE(every_chamber_at_every_span_holes_as_holes) {
  std::vector<double> spans = built().config.output.section_spans;  // the drawing's: 0.1 .. 0.9
  const std::vector<double> checks = check_spans();
  BOOST_TEST_REQUIRE(checks.size() == 10u);
  spans.insert(spans.end(), checks.begin(), checks.end());
  const auto cuts = features::span_sections(holed(), features::span_surfaces(built().model, spans));
  std::set<std::string> kinds;
  std::set<std::string> faces;
  for (const auto& f : built().film.blade.faces) faces.insert(f.name);
  for (const auto& c : cuts) {
    BOOST_TEST(c.unclosed_openings == 0, "span " << c.span);
    std::vector<std::string> names;
    for (const auto& p : c.passages) names.push_back(p.name);
    BOOST_TEST(names == kChambers, "span " << c.span);
    for (const auto& h : c.holes) {
      BOOST_TEST(features::is_opening_face(h.name), h.name);
      BOOST_TEST(faces.count(h.name) == 1u, h.name);
      BOOST_TEST(h.area > 0);
      kinds.insert(brep::feature_kind(h.name));
    }
  }
  // The cuts cross showerhead and film holes (and, at some spans, slots).
  BOOST_TEST(kinds.count("showerhead") == 1u);
  BOOST_TEST(kinds.count("film_row") == 1u);
  for (const auto& k : kinds) BOOST_TEST_MESSAGE("holes of kind " << k << " cross the cuts");
}

BOOST_AUTO_TEST_CASE(passages_with_holes_equal_the_design_checks) {
  const std::vector<double> spans = check_spans();
  const auto cuts = features::span_sections(holed(), features::span_surfaces(built().model, spans));
  double worst = 0;
  std::size_t holes = 0;
  for (const auto& c : cuts) holes += c.holes.size();
  for (const auto& m : built().passages.report.passages) {
    BOOST_TEST_REQUIRE(m.sections.size() == spans.size(), m.name);
    for (std::size_t k = 0; k < spans.size(); ++k) {
      const features::SectionPassage* p = nullptr;
      for (const auto& q : cuts[k].passages)
        if (q.name == m.name) p = &q;
      BOOST_TEST_REQUIRE(p != nullptr, m.name << " at span " << spans[k]);
      const auto& c = m.sections[k];
      const double da = std::abs(p->area - c.area) / c.area, dp = std::abs(p->wetted_perimeter - c.wetted_perimeter) / c.wetted_perimeter;
      worst = std::max({worst, da, dp});
      BOOST_TEST(da <= 2e-5, m.name << " at span " << c.span << ": area " << p->area << " vs " << c.area);
      BOOST_TEST(dp <= 2e-5, m.name << " at span " << c.span << ": perimeter " << p->wetted_perimeter << " vs " << c.wetted_perimeter);
    }
  }
  BOOST_TEST(holes > 10u);  // the comparison is over holes
  BOOST_TEST_MESSAGE("passages with holes vs the design checks: worst relative difference " << worst << " over " << holes
                                                                                              << " holes in the cuts");
}

BOOST_AUTO_TEST_CASE(holes_are_the_metal_the_film_stage_removed) {
  const std::vector<double> spans = built().config.output.section_spans;
  const auto surfaces = features::span_surfaces(built().model, spans);
  const auto before = features::span_sections({{"blade", built().passages.blade}}, surfaces);
  const auto after = features::span_sections(holed(), surfaces);
  int film_holes = 0;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    double hole_area = 0, slot_area = 0;
    for (const auto& h : after[k].holes) {
      (brep::feature_kind(h.name) == "te_slot" ? slot_area : hole_area) += h.area;
      film_holes += brep::feature_kind(h.name) != "te_slot";
    }
    for (const auto& h : before[k].holes) {
      BOOST_TEST(brep::feature_kind(h.name) == "te_slot", h.name);  // no film holes yet
      slot_area -= h.area;
    }
    const double removed = before[k].metal_area - after[k].metal_area;
    const double tol = 1e-4 * static_cast<double>(after[k].holes.size() + 1);
    BOOST_TEST(std::abs(removed - hole_area) <= tol, "span " << spans[k] << ": metal removed " << removed << " mm^2, holes " << hole_area);
    BOOST_TEST(std::abs(slot_area) <= tol, "span " << spans[k] << ": the slots' area changed by " << slot_area);
    BOOST_TEST_MESSAGE("span " << spans[k] << ": " << after[k].holes.size() << " holes, " << hole_area << " mm^2, metal removed "
                               << removed << " mm^2");
  }
  BOOST_TEST(film_holes > 5);
}
