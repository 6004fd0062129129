// Bad turbulator, trailing-edge slot and pin-fin input: every case gets an error naming its field below
// "cooling" and the allowed range (or the limit the blade sets, with the span where it fails).
// Range errors come from the config reader, definition errors from validate (no solid), geometry
// errors from building the tools on the example's core (built once; no booleans run).
#define BOOST_TEST_MODULE passages_wall_inputs
#include <boost/test/unit_test.hpp>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomFill.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "features/passages/rib_geometry.hpp"
#include "features/wall/trailing_edge.hpp"
#include "features/wall/turbulators.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/config/cooling_config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/cooling.hpp"

using namespace cg;
using nlohmann::json;

namespace {

// The built-in example with turbulators on both walls of each pass (the example has them on the
// pressure walls only), as the input checks were written for.
json example() {
  json d = json::parse(config::builtin_example_json());
  for (auto& t : d["cooling"]["core"]["turbulators"]) t["walls"] = "both";
  return d;
}
json& core_of(json& d) { return d["cooling"]["core"]; }

const blade::BladeModel& model() {
  static const blade::BladeModel m = config::build_model(config::builtin_example_config());
  return m;
}

// The message starts with the field path and contains every detail.
void check_message(const std::string& m, const std::string& path, const std::vector<std::string>& details) {
  BOOST_TEST_MESSAGE(m);
  BOOST_TEST(m.rfind(path, 0) == 0u, "message does not start with " << path << ": " << m);
  for (const auto& d : details) BOOST_TEST(m.find(d) != std::string::npos, "message lacks \"" << d << "\": " << m);
}

// Config reader and validate (no solid): a ConfigError starting with `path`, containing every detail.
void expect_config_error(const std::function<void(json&)>& edit, const std::string& path,
                         const std::vector<std::string>& details) {
  json doc = example();
  edit(doc);
  try {
    const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
    pipeline::plan_cooling(c.cooling, model());
    BOOST_ERROR("no error for " << path);
  } catch (const config::ConfigError& e) {
    check_message(e.what(), path, details);
  }
}

// Geometry: the tools built on the example's core with an edited definition.
const features::CoreBuild& core_build() {
  static const features::CoreBuild b =
      features::build_core_tools(model(), *config::builtin_example_config().cooling.passages.core);
  return b;
}

// Where a geometry error is found: by the checks before any solid (pipeline::plan_cooling) or only
// by the wall features' build on the core.
enum class RefusedBy { Validate, Build };

void expect_geometry_error(const std::function<void(json&)>& edit, const std::string& path,
                           const std::vector<std::string>& details, RefusedBy by = RefusedBy::Build) {
  json doc = example();
  edit(doc);
  const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
  const features::CoreDefinition& def = *c.cooling.passages.core;
  try {
    pipeline::plan_cooling(c.cooling, model());
    BOOST_TEST((by == RefusedBy::Build), "plan_cooling accepted what it should refuse: " << path);
  } catch (const config::ConfigError& e) {
    BOOST_TEST((by == RefusedBy::Validate), "refused before the build, expected only by it: " << e.what());
    check_message(e.what(), path, details);
    return;
  }
  try {
    features::WallLines lines(model().surface, core_build().inner_wall.surface);
    features::build_turbulators(model(), def, core_build(), lines);
    features::build_trailing_edge(def, features::plan_trailing_edge(model(), def, core_build(), lines), lines);
    BOOST_ERROR("no error for " << path);
  } catch (const features::PassageInputError& e) {
    check_message(config::cooling_error(e).what(), path, details);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(turbulator_sizes_and_angle_out_of_range) {
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["height"] = -0.4; }, "cooling.core.turbulators[0].height",
                      {"(0, 5]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["width"] = 0; }, "cooling.core.turbulators[0].width",
                      {"(0, 10]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][1]["pitch"] = -5; }, "cooling.core.turbulators[1].pitch",
                      {"(0, 100]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["angle_deg"] = 20; },
                      "cooling.core.turbulators[0].angle_deg", {"[30, 90]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["angle_deg"] = 95; },
                      "cooling.core.turbulators[0].angle_deg", {"[30, 90]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["arrangement"] = "zigzag"; },
                      "cooling.core.turbulators[0].arrangement", {"inline", "staggered"});
}

BOOST_AUTO_TEST_CASE(turbulator_pitch_below_width_and_wrong_chamber) {
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["pitch"] = 0.4; }, "cooling.core.turbulators[0].pitch",
                      {"width / sin(angle)", "0.5"});
  // At 60 deg a 0.5 mm wide turbulator covers 0.57735 mm of the axis: the limit printed rounded up.
  expect_config_error([](json& d) { core_of(d)["turbulators"][1]["pitch"] = 0.55; },
                      "cooling.core.turbulators[1].pitch", {"= 0.5774 mm", "got 0.55"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["chamber"] = 1; }, "cooling.core.turbulators[0].chamber",
                      {"[2, 3]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][0]["chamber"] = 4; }, "cooling.core.turbulators[0].chamber",
                      {"[2, 3]"});
  expect_config_error([](json& d) { core_of(d)["turbulators"][1]["chamber"] = 2; }, "cooling.core.turbulators[1].chamber",
                      {"has turbulators already"});
}

BOOST_AUTO_TEST_CASE(slot_and_pin_sizes) {
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["pitch"] = 1.0; }, "cooling.core.trailing_edge.pitch",
                      {"slot_width = 1.2"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["slot_height"] = -0.4; },
                      "cooling.core.trailing_edge.slot_height", {"(0, 10]"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["count"] = 10; }, "cooling.core.trailing_edge",
                      {"exactly one of \"pitch\" and \"count\""});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["land_taper_deg"] = 30; },
                      "cooling.core.trailing_edge.land_taper_deg", {"closes the slots"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["type"] = "centreline"; },
                      "cooling.core.trailing_edge.lip_thickness", {"only for"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["pin_fins"]["diameter"] = -0.8; },
                      "cooling.core.trailing_edge.pin_fins.diameter", {"(0, 10]"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["pin_fins"]["spanwise_pitch"] = 0.5; },
                      "cooling.core.trailing_edge.pin_fins.spanwise_pitch", {"diameter = 0.8"});
  expect_config_error([](json& d) { core_of(d)["trailing_edge"]["pin_fins"]["streamwise_pitch"] = 0.8; },
                      "cooling.core.trailing_edge.pin_fins.streamwise_pitch", {"diameter = 0.8"});
}

BOOST_AUTO_TEST_CASE(turbulator_taller_than_its_chamber) {
  // The plan places the turbulators on the core's walls (features/plan/cooling_plan.hpp): refused by validate.
  expect_geometry_error([](json& d) { core_of(d)["turbulators"][0]["height"] = 2.5; },
                        "cooling.core.turbulators[0].height", {"taller than its chamber", "at span", "must be <"},
                        RefusedBy::Validate);
}

// The rib's mid-surface M(a, s) between the inner-wall feet (rib_geometry.hpp) over spans [s0, s1] as an
// OCCT face: two curves through the feet at the same span parameters, ruled (21 stations over 0.2 of the
// span: the feet lines are smooth, interpolation error well below 1 um).
namespace {

TopoDS_Face rib_sheet(const features::RibMidSurface& mid, double s0, double s1) {
  const int n = 21;
  Handle(TColgp_HArray1OfPnt) a = new TColgp_HArray1OfPnt(1, n), b = new TColgp_HArray1OfPnt(1, n);
  Handle(TColStd_HArray1OfReal) t = new TColStd_HArray1OfReal(1, n);
  for (int i = 1; i <= n; ++i) {
    const double s = s0 + (s1 - s0) * (i - 1) / (n - 1);
    const Eigen::Vector3d pa = mid.suction_point(s), pb = mid.pressure_point(s);
    a->SetValue(i, gp_Pnt(pa.x(), pa.y(), pa.z()));
    b->SetValue(i, gp_Pnt(pb.x(), pb.y(), pb.z()));
    t->SetValue(i, s);
  }
  GeomAPI_Interpolate ia(a, t, false, 1e-9), ib(b, t, false, 1e-9);
  ia.Perform();
  ib.Perform();
  return BRepBuilderAPI_MakeFace(GeomFill::Surface(ia.Curve(), ib.Curve()), 1e-7);
}

}  // namespace

// bench/random_designs.py (full variants, seed 11, variant 104) on the built-in example: a 16 mm wide
// second chamber whose TE-side rib has no fillet, turbulators on both walls. The ends used to be found on
// the wall developed linearly at the chamber's centre, which passes the fillet-less rib's thin clearance
// band between two samples (its x is not the distance along the wall so far out): refused as "no room
// between the rib fillets". Checked against OCCT: every turbulator tool keeps at least thickness / 2 +
// end_gap from its ribs' mid-surfaces (the clearance on the wall and at the top are both at least that)
// and reaches to within 0.5 mm more (their ends lie at the clearance: an end left at the centre is 8 mm off).
BOOST_AUTO_TEST_CASE(turbulators_next_to_a_rib_without_fillet) {
  json doc = example();
  json& c = doc["cooling"];
  c["core"]["ribs"] = json::parse(R"([{"suction_chord": 0.3058, "pressure_chord": -0.2617, "thickness": 1.1651, "fillet_radius": 0.3069},
                                      {"suction_chord": 0.6175, "pressure_chord": -0.6444, "thickness": 1.2113}])");
  c["core"]["turbulators"] = json::parse(R"([{"chamber": 2, "walls": "both", "height": 0.4, "width": 0.5, "pitch": 5.0, "angle_deg": 90}])");
  c["core"]["inlets"] = json::parse(R"([{"chamber": 1, "end": "hub", "diameter": 1.4}, {"chamber": 2, "end": "hub", "diameter": 1.5},
                                        {"chamber": 3, "end": "hub", "diameter": 1.0}])");
  c.erase("showerhead");
  c["film_rows"] = json::array({c["film_rows"][0]});  // the LE row over chamber 1
  const config::Config cfg = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
  const features::CoolingPlan plan = pipeline::plan_cooling(cfg.cooling, model());
  BOOST_TEST(plan.turbulators.size() >= 18u);
  const features::CoreDefinition& def = *cfg.cooling.passages.core;
  features::WallLines lines(model().surface, core_build().inner_wall.surface);
  const features::TurbulatorBuild tb = features::build_turbulators(model(), def, core_build(), lines);
  BOOST_TEST_REQUIRE(tb.tools.size() == plan.turbulators.size());
  const blade::BladeCoordinates coords(model());
  for (std::size_t k = 0; k < tb.tools.size(); ++k) {
    const double s = plan.turbulators[k].span;
    for (const features::RibDefinition& rib : def.ribs) {
      const features::RibMidSurface mid(coords, def.wall_thickness, rib);
      BRepExtrema_DistShapeShape d(tb.tools[k].shape.shape, rib_sheet(mid, std::max(0.0, s - 0.1), std::min(1.0, s + 0.1)));
      BOOST_TEST_REQUIRE(d.IsDone());
      const double clear = 0.5 * rib.thickness + def.turbulators[0].end_gap;
      BOOST_TEST(d.Value() >= clear - 1e-3, tb.tools[k].feature << " to the rib at " << rib.pressure_chord << ": " << d.Value());
      BOOST_TEST(d.Value() <= clear + 0.5 + 2 * rib.fillet_radius, tb.tools[k].feature << ": " << d.Value());
      BOOST_TEST_MESSAGE(tb.tools[k].feature << " span " << s << " rib " << rib.pressure_chord << ": " << d.Value() - clear);
    }
  }
}

// A cutback longer than the TE region (1 mm here, where the chamber ends 0.81 mm from the TE): the plan
// thickens the wall toward the TE (cutback_wall.hpp) so that the chamber ends 0.25 mm upstream of the lip,
// and builds on that wall. Checked against the plan's own frame (every slot's lip at least 0.1 mm
// downstream of the chamber's end, the check the given wall failed) and the table: the given 1 mm from
// the LE to beyond the last rib, more only toward the TE, at most twice the wall.
BOOST_AUTO_TEST_CASE(cutback_over_the_chamber_gets_a_thicker_te_wall) {
  json doc = example();
  core_of(doc)["trailing_edge"]["cutback_length"] = 1.0;
  const config::Config c = config::parse_config(doc, COOLINGGEN_SOURCE_DIR "/data/examples", "t");
  const features::CoolingPlan plan = pipeline::plan_cooling(c.cooling, model());
  BOOST_TEST_REQUIRE(plan.notes.size() == 1u);
  BOOST_TEST(plan.notes[0].rfind("cooling.core.wall_thickness: the cutback's lip (cutback_length 1 mm) would lie over", 0) == 0u,
             plan.notes[0]);
  BOOST_TEST(!plan.trailing_edge.slots.empty());
  for (const features::SlotInfo& slot : plan.trailing_edge.slots) {
    BOOST_TEST(std::abs(slot.te_x - slot.x_lip - 1.0) < 1e-12, slot.name);  // x_lip = te_x - cutback_length
    BOOST_TEST(slot.x_lip - slot.crease_x > features::kLipClear, slot.name << " at span " << slot.span);
  }
  const blade::ThicknessField& wall = plan.passages.core->wall_thickness;
  const double rib_s = c.cooling.passages.core->ribs.back().suction_chord, rib_p = c.cooling.passages.core->ribs.back().pressure_chord;
  for (double s = 0; s <= 1.0; s += 0.05) {
    for (double chord : {-0.2, 0.0, 0.3, rib_s + 0.05, rib_p - 0.05}) BOOST_TEST(wall.at(s, chord) == 1.0);
    BOOST_TEST(wall.at(s, 1.0) >= 1.0);
    BOOST_TEST(wall.at(s, -1.0) >= 1.0);
  }
  BOOST_TEST(wall.max_value() > 1.0);
  BOOST_TEST(wall.max_value() <= 2.0);
  // The definition the user gave is unchanged; validate reports the same note.
  BOOST_TEST(c.cooling.passages.core->wall_thickness.is_constant());
  BOOST_TEST(pipeline::validate(c).notes == plan.notes);
  // A refusal of the plan on the thickened wall says so: six pin rows upstream of the moved slot inlets
  // reach the last rib.
  expect_geometry_error(
      [](json& d) {
        core_of(d)["trailing_edge"]["cutback_length"] = 1.0;
        core_of(d)["trailing_edge"]["pin_fins"]["rows"] = 6;
      },
      "cooling.core.trailing_edge.pin_fins.rows", {"reaches rib 3", "planned on the wall thickened toward the TE to at most 1.172 mm"},
      RefusedBy::Validate);
}

// The plan places the slots and pins (plan_trailing_edge): all of these are refused by validate.
BOOST_AUTO_TEST_CASE(trailing_edge_that_does_not_fit) {
  // The lip must lie downstream of the last chamber's end (this blade's TE region is ~1 mm long), and
  // a wall thickened toward the TE cannot end the chamber 3.25 mm from the TE (the sections are too thin
  // for such a wall: cutback_wall.hpp).
  expect_geometry_error([](json& d) { core_of(d)["trailing_edge"]["cutback_length"] = 3.0; },
                        "cooling.core.trailing_edge.cutback_length",
                        {"must be <", "at span", "no wall thickened toward the TE", "2 mm"}, RefusedBy::Validate);
  // Slot and lip thicker than the TE region: no suction-side wall left under the cutback.
  expect_geometry_error([](json& d) { core_of(d)["trailing_edge"]["slot_height"] = 3.0; },
                        "cooling.core.trailing_edge.slot_height", {"suction-side wall", "at span"}, RefusedBy::Validate);
  // Too many pin rows reach the last rib's fillet.
  expect_geometry_error([](json& d) { core_of(d)["trailing_edge"]["pin_fins"]["rows"] = 12; },
                        "cooling.core.trailing_edge.pin_fins.rows", {"reaches rib 3"}, RefusedBy::Validate);
}

BOOST_AUTO_TEST_CASE(centreline_slots_that_do_not_fit) {
  // Centreline slots on the example's core (the TE region is ~1.6 mm thick at the crease, the TE ~1.1 mm
  // downstream of it): each error names the field and the limit the blade sets there.
  auto centreline = [](json& d) -> json& {
    core_of(d)["trailing_edge"] = {{"type", "centreline"}, {"slot_height", 0.4}, {"slot_width", 1.0}, {"pitch", 2.5}};
    return core_of(d)["trailing_edge"];
  };
  // Taller than the TE region allows (0.1 mm of wall left on each side at the crease).
  expect_geometry_error([&](json& d) { centreline(d)["slot_height"] = 3.0; }, "cooling.core.trailing_edge.slot_height",
                        {"less than 0.1 mm of wall", "at span", "must be <="}, RefusedBy::Validate);
  expect_geometry_error([&](json& d) { centreline(d)["slot_height"] = 1.5; }, "cooling.core.trailing_edge.slot_height",
                        {"must be <="}, RefusedBy::Validate);
  // A taper that closes the slots before they leave the blade.
  expect_geometry_error([&](json& d) { centreline(d)["land_taper_deg"] = 30.0; },
                        "cooling.core.trailing_edge.land_taper_deg", {"closes the slot", "must be <"}, RefusedBy::Validate);
  // A taper that widens the inlets (upstream of the crease) into their neighbours.
  expect_geometry_error(
      [&](json& d) {
        json& te = centreline(d);
        te["pitch"] = 1.1;
        te["land_taper_deg"] = 5.0;
      },
      "cooling.core.trailing_edge.land_taper_deg", {"touch their neighbours", "must be <"}, RefusedBy::Validate);
  // Cutback-only fields.
  expect_config_error([&](json& d) { centreline(d)["cutback_length"] = 0.5; }, "cooling.core.trailing_edge.cutback_length",
                      {"only for"});
}
