// Film holes and an impingement insert built by the pipeline into the chambers of the real passages
// (features/film/film_cavity.hpp, src/pipeline/cooling.hpp): a short straight blade (the built-in example's
// mid-span section, 16 mm span) with a core of two chambers split by a filleted rib, a 3-row showerhead and a
// 7-7-7 row feeding from them, an insert in the front chamber. Measured on the built solids, independent
// of the feature's own checks: every hole opens into the chamber its row names (its faces touch that
// chamber's wall faces), keeps the ligament from the rib and the other rows (BRepExtrema between the
// named faces), the insert keeps its gap from the rib; the STEP read back holds two valid, closed solids
// (blade, insert_1) with every hole's faces named. Bad input: ConfigError naming the field below
// "cooling" (row over the rib, wrong chamber, beyond the tip cap, insert gap below the fillet, film
// without a core).
#define BOOST_TEST_MODULE film_passages
#include <boost/test/unit_test.hpp>

#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "brep/step_read_back.hpp"
#include "brep/temp_files.hpp"
#include "support/short_blade.hpp"
#include "src/brep/verify.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/cooling.hpp"
#include "src/pipeline/outputs.hpp"

using namespace cg;
using nlohmann::json;

namespace {

json config_doc() {
  json d = test::short_example_blade("film_passages", 16);  // an insert fits its LE chamber
  d["cooling"] = json::parse(R"({
    "showerhead": {"rows": 3, "diameter": 0.3, "row_spacing_d": 4, "pitch_d": 6, "radial_angle_deg": 60,
                   "span_start": 0.25, "span_end": 0.75, "chamber": 1},
    "film_rows": [
      {"shape": "7-7-7", "diameter": 0.3, "chord": -0.45, "span_start": 0.25, "span_end": 0.75, "chamber": 2},
      {"diameter": 0.3, "chord": 0.36, "pitch_d": 5, "inclination_deg": 35, "compound_deg": 20,
       "span_start": 0.25, "span_end": 0.75, "chamber": 2}
    ],
    "inserts": [{"chamber": 1, "gap": 0.6, "sheet_thickness": 0.3, "hub_end": "closed", "tip_end": "closed",
                 "jets": {"diameter": 0.4, "spacing_x_d": 8, "spacing_y_d": 8}}]
  })");
  d["cooling"]["core"] = test::two_chamber_core();
  return d;
}

config::Config parse(const json& d) { return config::parse_config(d, COOLINGGEN_SOURCE_DIR "/data/examples", "test"); }

const pipeline::BuildResult& built() {
  static std::unique_ptr<pipeline::BuildResult> r;
  if (!r) r = std::make_unique<pipeline::BuildResult>(pipeline::run_build(parse(config_doc())));
  return *r;
}

// The passages alone (for the bad-input cases: film input is checked before any film boolean).
struct Cooled {
  config::Config config;
  blade::BladeModel model;
  features::PassagesResult passages;
};
const Cooled& cooled() {
  static std::unique_ptr<Cooled> c;
  if (!c) {
    c = std::make_unique<Cooled>();
    c->config = parse(config_doc());
    c->model = config::build_model(c->config);
    const brep::BladeSolid s = brep::build_blade_solid(c->model);
    c->passages = pipeline::apply_cooling(c->model, pipeline::plan_cooling(c->config.cooling, c->model), {s.solid, s.faces});
  }
  return *c;
}

TopoDS_Compound faces_where(const brep::NamedShape& s, const std::function<bool(const std::string&)>& pick, int* count = nullptr) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  int n = 0;
  for (const auto& f : s.faces)
    if (pick(f.name)) b.Add(c, f.face), ++n;
  if (count) *count = n;
  return c;
}

double distance(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepExtrema_DistShapeShape d(a, b);
  BOOST_TEST_REQUIRE(d.IsDone());
  return d.Value();
}

bool starts(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

// The ConfigError of building the film input `edit` makes (its plan, then the film stage on the passages
// built from the unedited input), "" when it builds.
std::string film_error(const std::function<void(json&)>& edit) {
  json d = config_doc();
  edit(d["cooling"]);
  try {
    const config::Config c = parse(d);
    pipeline::apply_film(c.cooling, cooled().model, pipeline::plan_cooling(c.cooling, cooled().model), cooled().passages);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_CASE(holes_open_into_their_chambers) {
  const pipeline::BuildResult& r = built();
  BOOST_TEST_REQUIRE(r.valid(), r.failed_checks());
  BOOST_TEST_REQUIRE(r.film.has_value());
  const auto& holes = r.film->holes;
  for (const auto& t : r.timings) BOOST_TEST_MESSAGE("stage " << t.stage << ": " << t.seconds << " s");
  for (const auto& [stage, s] : r.film->seconds) BOOST_TEST_MESSAGE("film " << stage << ": " << s << " s");
  BOOST_TEST_MESSAGE(holes.size() << " holes, " << r.film->inserts.at(0).jet_holes << " jets");
  BOOST_TEST(holes.size() >= 12u);
  const brep::NamedShape& blade = r.part.front().geometry;
  std::set<std::string> rows, checked_rows;
  for (const auto& h : holes) {
    rows.insert(h.row);
    const std::string want = starts(h.name, "showerhead_") ? "chamber_1" : "chamber_2";
    BOOST_TEST(h.chamber == want, h.name);
    BOOST_TEST(h.volume_passed, h.name);
    BOOST_TEST(std::abs(h.measured_volume / h.expected_volume - 1) < 1e-4, h.name << " " << h.measured_volume << " vs " << h.expected_volume);
    // Independent: the hole's faces on the built blade touch its chamber's wall faces and are farther
    // than the ligament from the other chamber's.
    int n = 0;
    const TopoDS_Compound hf = faces_where(blade, [&](const std::string& s) { return s == h.name; }, &n);
    BOOST_TEST_REQUIRE(n > 0, h.name);
    BOOST_TEST(distance(hf, faces_where(blade, [&](const std::string& s) { return s == want + "_wall"; })) < 1e-6, h.name);
    if (rows.size() > checked_rows.size()) {  // first hole of each row: clear of the other chamber
      checked_rows.insert(h.row);
      const std::string other = want == "chamber_1" ? "chamber_2" : "chamber_1";
      BOOST_TEST(distance(hf, faces_where(blade, [&](const std::string& s) { return s == other + "_wall"; })) > 0.3, h.name);
    }
  }
  BOOST_TEST(rows.size() == 5u);  // 3 showerhead rows + 2 film rows
  // Per chamber: total metering area = sum over its holes.
  double a1 = 0;
  for (const auto& h : holes)
    if (h.chamber == "chamber_1") a1 += h.metering_area;
  bool found = false;
  for (const auto& c : r.film->chambers)
    if (c.chamber == "chamber_1") {
      found = true;
      BOOST_TEST(std::abs(c.metering_area - a1) <= 1e-12 * a1);
    }
  BOOST_TEST(found);
}

BOOST_AUTO_TEST_CASE(ligaments_to_rib_and_rows_on_the_built_solid) {
  const pipeline::BuildResult& r = built();
  const brep::NamedShape& blade = r.part.front().geometry;
  const double lig = r.film->configured_min_ligament;
  const TopoDS_Compound rib = faces_where(blade, [](const std::string& s) { return starts(s, "rib_1"); });
  const TopoDS_Compound holes = faces_where(blade, [](const std::string& s) { return has(s, "_hole_"); });
  const double d_rib = distance(holes, rib);
  BOOST_TEST_MESSAGE("least distance hole - rib_1 on the built blade: " << d_rib << " mm");
  BOOST_TEST(d_rib >= lig - 1e-4);  // the rib's faces and fillets were not cut
  // Showerhead row 1 against row 2 (staggered, 4 D apart along the surface).
  const double d_rows = distance(faces_where(blade, [](const std::string& s) { return starts(s, "showerhead_1_hole"); }),
                                 faces_where(blade, [](const std::string& s) { return starts(s, "showerhead_2_hole"); }));
  BOOST_TEST(d_rows >= lig);
  for (const auto& h : r.film->holes) BOOST_TEST(h.ligament >= lig, h.name);
}

BOOST_AUTO_TEST_CASE(insert_in_the_front_chamber) {
  const pipeline::BuildResult& r = built();
  BOOST_TEST_REQUIRE(r.part.size() == 2u);
  BOOST_TEST(r.part[1].name == "insert_1");
  BOOST_TEST(r.checks[1].all_passed(), r.checks[1].failed_names());
  BOOST_TEST_REQUIRE(r.film->inserts.size() == 1u);
  const auto& m = r.film->inserts[0];
  BOOST_TEST(m.chamber == "chamber_1");
  BOOST_TEST(m.measured_gap >= m.gap - 5e-3);  // 5e-3: the offsets are fitted within 1e-3 mm
  BOOST_TEST(std::abs(m.measured_sheet_min - m.sheet_thickness) <= 5e-3);
  BOOST_TEST(std::abs(m.measured_sheet_max - m.sheet_thickness) <= 5e-3);
  BOOST_TEST(m.jet_holes > 0);
  // The rib side of the insert keeps the gap too (its walls follow the rib thickened by Z).
  const brep::NamedShape& blade = r.part.front().geometry;
  const double d = distance(r.part[1].geometry.shape, faces_where(blade, [](const std::string& s) { return starts(s, "rib_1"); }));
  BOOST_TEST_MESSAGE("insert_1 - rib_1: " << d << " mm");
  BOOST_TEST(d >= m.gap - 5e-3);
  BOOST_TEST(d <= m.gap + 0.05);  // it follows the rib, not just somewhere far from it
}

BOOST_AUTO_TEST_CASE(step_read_back_with_bodies_and_hole_names) {
  const pipeline::BuildResult& r = built();
  config::Config c = parse(config_doc());
  c.output.formats = {config::OutputFormat::Step};
  test::TempDir dir("film_step");
  pipeline::write_outputs(c, r, dir.path / "out");
  const test::StepReadBack back = test::read_step_back(dir.path / "out" / "blade.step");
  BOOST_TEST_REQUIRE(back.ok);
  const std::multiset<std::string>& faces = back.face_names;
  const std::map<std::string, TopoDS_Shape>& solids = back.named_solids;
  BOOST_TEST_REQUIRE(solids.size() == 2u);
  for (const char* body : {"blade", "insert_1"}) {
    BOOST_TEST_REQUIRE(solids.count(body) == 1u, body);
    const brep::SolidCheck check = brep::verify_solid(solids.at(body));
    BOOST_TEST(check.all_passed(), body << ": " << check.failed_names());
  }
  std::multiset<std::string> ours;
  for (const auto& b : r.part)
    for (const auto& f : b.geometry.faces) ours.insert(f.name);
  BOOST_TEST(faces == ours);
  for (const auto& h : r.film->holes) BOOST_TEST(faces.count(h.name) > 0u, h.name);
  BOOST_TEST(faces.count("insert_1") > 0u);
  BOOST_TEST(faces.count("insert_1_jet_001") > 0u);
}

// A stop request once the film stage has started ends the build inside that stage, naming it.
BOOST_AUTO_TEST_CASE(film_stage_stops_on_request) {
  struct StopAtFilm : ProgressSink {
    bool stop = false;
    void stage_started(const std::string& stage, const std::string&) override { stop = stop || stage == "film"; }
    bool stop_requested() const override { return stop; }
  } sink;
  try {
    pipeline::run_build(parse(config_doc()), {}, &sink);
    BOOST_ERROR("the build did not stop");
  } catch (const Cancelled& e) {
    BOOST_TEST(has(e.what(), "stage 'film'"), e.what());
  }
}

BOOST_AUTO_TEST_CASE(bad_input_names_the_field) {
  // A row next to the rib: its holes enter chamber 2 too close to rib_1 (its fillet included).
  std::string e = film_error([](json& c) { c["film_rows"][1]["chord"] = 0.35; });
  BOOST_TEST(has(e, "cooling.film_rows[1].chord"), e);
  BOOST_TEST(has(e, "close to rib_1"), e);
  // A row that feeds chamber 2 but names chamber 1 (the plan's definition check says it first).
  e = film_error([](json& c) { c["film_rows"][1]["chamber"] = 1; });
  BOOST_TEST(has(e, "cooling.film_rows[1].chamber"), e);
  BOOST_TEST(has(e, "over chamber_2"), e);
  // A row reaching over the tip cap.
  e = film_error([](json& c) { c["film_rows"][1]["span_end"] = 0.98; });
  BOOST_TEST(has(e, "cooling.film_rows[1].span_end"), e);
  BOOST_TEST(has(e, "tip_cap"), e);
  // An insert gap below the rib's fillet radius (the corners would keep less than Z).
  e = film_error([](json& c) { c["inserts"][0]["gap"] = 0.2; });
  BOOST_TEST(has(e, "cooling.inserts[0].gap"), e);
  BOOST_TEST(has(e, "fillet"), e);
  // An insert in a chamber that does not exist.
  e = film_error([](json& c) { c["inserts"][0]["chamber"] = 3; });
  BOOST_TEST(has(e, "cooling.inserts[0].chamber"), e);
  // `coolinggen validate` (pipeline::validate) places the holes without any solid: a row beyond the TE.
  json v = config_doc();
  v["cooling"]["film_rows"][0].erase("chord");
  v["cooling"]["film_rows"][0]["arc_length"] = -80.0;
  try {
    pipeline::validate(parse(v));
    BOOST_ERROR("validate passed a row beyond the TE");
  } catch (const config::ConfigError& x) {
    BOOST_TEST(has(x.what(), "cooling.film_rows[0].arc_length"), x.what());
    BOOST_TEST(has(x.what(), "beyond the TE"), x.what());
  }
  // Film input without a core: refused by the parser.
  json d = config_doc();
  d["cooling"].erase("core");
  try {
    parse(d);
    BOOST_ERROR("film without a core parsed");
  } catch (const config::ConfigError& x) {
    BOOST_TEST(has(x.what(), "cooling"), x.what());
    BOOST_TEST(has(x.what(), "need \"core\""), x.what());
  }
}

// By default verify_solid runs once, on the final blade (the steps run their other checks); with
// Verification::EachStep it runs after every boolean step. Both give the same solid, and the default run
// neither rebuilt anything nor verified inside the steps.
BOOST_AUTO_TEST_CASE(deferred_and_per_step_verification_agree) {
  const pipeline::BuildResult& deferred = built();
  BOOST_TEST_REQUIRE(deferred.valid(), deferred.failed_checks());
  for (const pipeline::StageTiming& t : deferred.timings) BOOST_TEST(t.stage.find("_rechecked") == std::string::npos, t.stage);
  pipeline::BuildOptions each;
  each.verification = features::Verification::EachStep;
  const pipeline::BuildResult r = pipeline::run_build(parse(config_doc()), each);
  BOOST_TEST_REQUIRE(r.valid(), r.failed_checks());
  BOOST_REQUIRE(r.checks.size() == deferred.checks.size());
  for (std::size_t i = 0; i < r.checks.size(); ++i) {
    BOOST_TEST(std::abs(r.checks[i].volume - deferred.checks[i].volume) <= 1e-9 * r.checks[i].volume);
    BOOST_TEST(r.checks[i].face_count == deferred.checks[i].face_count);
  }
  BOOST_TEST(brep::count_face_names(r.part[0].geometry) == brep::count_face_names(deferred.part[0].geometry));
}
