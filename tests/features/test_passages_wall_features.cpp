// Turbulators, trailing-edge cutback slots and pin fins of the built-in example (HPT rotor: turbulators
// in the serpentine passes 2 and 3, a pressure-side cutback with two staggered pin-fin rows from the last
// chamber), measured on the built solid against the configuration: turbulator height and pitch, slot
// height and lip thickness, pin diameter, added / removed volumes against the independent quadrature,
// face names in the STEP file read back with OCCT.
#define BOOST_TEST_MODULE passages_wall_features
#include <boost/test/unit_test.hpp>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cstdio>

#include "features/passage_fixtures.hpp"

using namespace cg;

namespace {

// The built-in example with fewer turbulators, slots and pins (larger pitches, a tapered cutback, two
// staggered pin rows), so the test stays under a minute (bench_cooled_build builds the full example).
// The example's turbulators sit on the pressure walls only (its film rows use the suction walls of
// those passes); here both walls carry them: inline 90 deg in chamber 2, staggered 60 deg in chamber 3.
const test::CooledBlade& rotor() {
  return test::cooled_builtin_variant("lighter wall features", [](nlohmann::json& d) {
    auto& c = d["cooling"]["core"];
    for (auto& t : c["turbulators"]) t["pitch"] = 12.0, t["walls"] = "both";
    c["turbulators"][0]["arrangement"] = "inline";
    c["turbulators"][1]["arrangement"] = "staggered";
    c["trailing_edge"]["pitch"] = 6.0;
    c["trailing_edge"]["pin_fins"]["spanwise_pitch"] = 6.0;
  });
}
const features::CoreDefinition& core() { return *rotor().config.cooling.passages.core; }

std::vector<std::string> names_with(const std::string& prefix) {
  std::set<std::string> out;
  for (const auto& f : rotor().cooled.blade.faces)
    if (f.name.rfind(prefix, 0) == 0) out.insert(f.name);
  return {out.begin(), out.end()};
}

gp_Pnt centroid(const std::vector<TopoDS_Face>& faces) {
  GProp_GProps p;
  for (const auto& f : faces) {
    GProp_GProps q;
    BRepGProp::SurfaceProperties(f, q, 1e-9);
    p.Add(q);
  }
  return p.CentreOfMass();
}

// Points where a line crosses the built solid (OCCT's intersector, independent of our construction),
// as parameters along the line, sorted.
std::vector<double> crossings(const gp_Pnt& p, const gp_Dir& d) {
  IntCurvesFace_ShapeIntersector in;
  in.Load(rotor().cooled.blade.shape, 1e-9);
  in.Perform(gp_Lin(p, d), -50, 50);
  std::vector<double> out;
  for (int i = 1; i <= in.NbPnt(); ++i) out.push_back(in.WParameter(i));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_tool_is_applied_and_named) {
  const auto& r = rotor().cooled;
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  for (const auto& [stage, seconds] : r.report.seconds) BOOST_TEST_MESSAGE("  " << stage << " " << seconds << " s");
  int turbulators = 0, slots = 0, pins = 0;
  for (const auto& t : r.report.tools) {
    turbulators += t.feature.rfind("turbulator_", 0) == 0;
    slots += t.feature.rfind("te_slot_", 0) == 0;
    pins += t.feature.rfind("pin_fin_", 0) == 0;
  }
  BOOST_TEST_MESSAGE(turbulators << " turbulators, " << slots << " slots, " << pins << " pins");
  BOOST_TEST(turbulators >= 10);
  BOOST_TEST(slots >= 6);
  BOOST_TEST(pins >= 10);
  // Every tool left named faces in the result, under its own name.
  BOOST_TEST(static_cast<int>(names_with("turbulator_").size()) == turbulators);
  BOOST_TEST(static_cast<int>(names_with("te_slot_").size()) == slots);
  BOOST_TEST(static_cast<int>(names_with("pin_fin_").size()) == pins);
  for (const auto& n : names_with("turbulator_2_")) BOOST_TEST(n.size() == std::string("turbulator_2_001").size(), n);
  for (const auto& n : names_with("te_slot_")) BOOST_TEST(n.size() == std::string("te_slot_01").size(), n);
  for (const auto& n : names_with("pin_fin_")) BOOST_TEST(n.size() == std::string("pin_fin_001").size(), n);
}

BOOST_AUTO_TEST_CASE(added_and_removed_volumes_against_the_quadrature) {
  const auto& r = rotor().cooled;
  int checked = 0;
  for (const auto& t : r.report.tools) {
    const bool mine = t.feature.rfind("turbulator_", 0) == 0 || t.feature.rfind("te_slot_", 0) == 0 ||
                      t.feature.rfind("pin_fin_", 0) == 0;
    if (!mine) continue;
    ++checked;
    BOOST_TEST(t.passed, t.feature);
    BOOST_TEST(t.how == (t.feature.rfind("te_slot_", 0) == 0 ? "cut" : "fuse"), t.feature);
    BOOST_TEST(std::abs(t.measured - t.expected) <= 1e-6 * t.expected, t.feature << ": " << t.measured << " vs " << t.expected);
  }
  BOOST_TEST(checked > 0);
  // Plausibility of the independent values against the nominal shapes (not the check itself):
  // turbulator ~ e x w x length, pin ~ pi D^2 / 4 x its span across the chamber.
  const auto& tb = core().turbulators.front();
  for (const auto& t : r.report.tools)
    if (t.feature == "turbulator_2_001") BOOST_TEST(std::abs(t.expected / (tb.height * tb.width) - 9.0) < 1.0);
}

BOOST_AUTO_TEST_CASE(turbulator_height_on_the_built_solid) {
  // Height = distance of the turbulator's faces from the outer wall minus the wall thickness: the top
  // face is the farthest, at t + e (the inner wall is within its 1 um fit of t).
  const auto& b = rotor().cooled.blade;
  const auto outer = test::compound(test::named_faces(b, {"blade_wall"}));
  const double t = core().wall_thickness.min_value();
  for (const char* name : {"turbulator_2_001", "turbulator_2_006", "turbulator_3_002", "turbulator_3_005"}) {
    double top = 0;
    for (const auto& f : test::named_faces(b, {name}))
      for (const gp_Pnt& p : test::face_points(f, 5)) {
        BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(p).Vertex(), outer);
        top = std::max(top, d.Value() - t);
      }
    const double e = core().turbulators[name[11] == '2' ? 0 : 1].height;
    BOOST_TEST_MESSAGE(name << ": height " << top << " mm, configured " << e);
    BOOST_TEST(std::abs(top - e) <= test::thickness_tolerance(e), name << ": " << top);
  }
}

BOOST_AUTO_TEST_CASE(turbulator_pitch_on_the_built_solid) {
  // Neighbouring suction-side turbulators of chamber 2 (numbered hub to tip): their face centroids are
  // one pitch apart (measured along the span direction of the wall between them).
  const auto& b = rotor().cooled.blade;
  const double pitch = core().turbulators.front().pitch;
  std::vector<gp_Pnt> c;
  for (int k = 1; k <= 3; ++k) {
    char n[32];
    std::snprintf(n, sizeof n, "turbulator_2_%03d", k);
    c.push_back(centroid(test::named_faces(b, {n})));
  }
  for (std::size_t k = 1; k < c.size(); ++k) {
    const double d = c[k].Distance(c[k - 1]);
    BOOST_TEST_MESSAGE("pitch " << k << ": " << d << " mm, configured " << pitch);
    BOOST_TEST(std::abs(d - pitch) <= 0.01 * pitch);
  }
}

BOOST_AUTO_TEST_CASE(slot_height_and_lip_on_the_built_solid) {
  // A line across the slot just upstream of the lip, along the slot frame's y (OCCT's intersector on the
  // built solid): suction surface, slot floor, slot ceiling, pressure surface; floor to ceiling = H,
  // ceiling to surface = the lip thickness (+ the surfaces' slope over the 2 um step).
  const auto& te = *core().trailing_edge;
  const auto& slots = rotor().cooled.wall_features.trailing_edge.slots;
  BOOST_TEST_REQUIRE(slots.size() >= 2u);
  for (const auto& s : {slots.front(), slots[slots.size() / 2]}) {
    const Eigen::Vector3d p = s.origin + (s.x_lip - 0.002) * s.x - 4.0 * s.y;
    const std::vector<double> w = crossings(gp_Pnt(p.x(), p.y(), p.z()), gp_Dir(s.y.x(), s.y.y(), s.y.z()));
    BOOST_TEST_REQUIRE(w.size() == 4u, s.name << ": " << w.size() << " crossings");
    const double h = w[2] - w[1], lip = w[3] - w[2];
    BOOST_TEST_MESSAGE(s.name << ": slot height " << h << " mm, lip " << lip << " mm");
    BOOST_TEST(std::abs(h - te.slot_height) <= test::thickness_tolerance(te.slot_height), s.name << ": " << h);
    BOOST_TEST(std::abs(lip - te.lip_thickness) <= test::thickness_tolerance(te.lip_thickness), s.name << ": " << lip);
    // Between two slots (on a land) the same line crosses the blade only twice: no slot there.
    const Eigen::Vector3d q = p + 0.5 * te.pitch * s.z;
    BOOST_TEST(crossings(gp_Pnt(q.x(), q.y(), q.z()), gp_Dir(s.y.x(), s.y.y(), s.y.z())).size() == 2u, s.name);
  }
}

BOOST_AUTO_TEST_CASE(pin_diameter_on_the_built_solid) {
  const auto& b = rotor().cooled.blade;
  const double d = core().trailing_edge->pin_fins->diameter;
  int cylinders = 0;
  for (const auto& n : names_with("pin_fin_"))
    for (const auto& f : test::named_faces(b, {n})) {
      BRepAdaptor_Surface s(f);
      if (s.GetType() != GeomAbs_Cylinder) continue;
      ++cylinders;
      BOOST_TEST(std::abs(2 * s.Cylinder().Radius() - d) <= 1e-9, n);
    }
  BOOST_TEST(cylinders >= static_cast<int>(names_with("pin_fin_").size()));
}

BOOST_AUTO_TEST_CASE(feature_names_in_the_step_file) {
  const auto& r = rotor().cooled;
  const test::StepReadBack rb = test::step_round_trip(r.blade, "wall_features_step");
  BOOST_TEST_REQUIRE(rb.ok);
  for (const char* prefix : {"turbulator_", "te_slot_", "pin_fin_"}) {
    std::set<std::string> in_step, ours;
    for (const auto& n : rb.names)
      if (n.rfind(prefix, 0) == 0) in_step.insert(n);
    for (const auto& n : names_with(prefix)) ours.insert(n);
    BOOST_TEST(!ours.empty());
    BOOST_TEST((in_step == ours), prefix);
  }
}
