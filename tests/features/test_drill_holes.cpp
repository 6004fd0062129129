// Direct drilling (features/drilling/drill_holes.hpp) on the hollow example blade, against the verified boolean
// path (BooleanStep) on the same holes, measured on the built solids.
//
// Tolerances: whole-part volumes agree to 1e-6 relative (BRepGProp at 1e-9 on both solids; the
// holes' edges are within 1e-7 mm of the exact loops, OCCT's intersection edges within ~4e-4 mm, so
// the B-reps themselves differ by ~1e-7 relative); per-hole volumes: drilled (divergence theorem over
// the hole's faces) vs BooleanStep (its own measurement on its result) within 1e-6 relative plus both
// sides' edge-tolerance uncertainty; cylinder radius and axis from the faces to 1e-9 (they are
// constructed exactly, a Geom_CylindricalSurface from the hole's frame).
#define BOOST_TEST_MODULE drill_holes
#include <boost/test/unit_test.hpp>

#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <TopExp_Explorer.hxx>

#include <Eigen/Geometry>

#include <map>
#include <set>

#include "brep/step_read_back.hpp"
#include "brep/temp_files.hpp"
#include "export/step_writer.hpp"
#include "tests/support/boolean_sample_part.hpp"
#include "features/drilling/drill_holes.hpp"
#include "tests/support/drill_sample_holes.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/algo/ray_surface.hpp"

using namespace cg;

namespace {

struct Fixture {
  blade::BladeModel model;
  features::HollowBlade hb;
  std::vector<features::CylindricalHole> holes;  // 16 holes of the sample field
  features::DrillResult drilled;                 // drill_holes(hb.part, holes) with verify_solid
};

const Fixture& hollow() {
  static Fixture* f = [] {
    auto* x = new Fixture;
    x->model = config::build_model(config::builtin_example_config());
    features::HollowBladeOptions ho;
    ho.verify = false;
    x->hb = features::make_hollow_blade(x->model, ho);
    features::HoleFieldOptions fo;
    fo.count = 16;
    x->holes = features::holes_of_tools(features::make_hole_tools(x->model, x->hb, fo));
    features::DrillOptions o;
    o.verify_solid = true;
    x->drilled = features::drill_holes(x->hb.part, x->holes, o);
    return x;
  }();
  return *f;
}

double volume(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::VolumeProperties(s, g, 1e-9, true);
  return g.Mass();
}

std::multiset<std::string> names(const brep::NamedShape& s) {
  std::multiset<std::string> n;
  for (const auto& f : s.faces) n.insert(f.name);
  return n;
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopExp_Explorer e(s, type); e.More(); e.Next()) ++n;
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_hole_drilled_and_the_solid_verified) {
  const Fixture& f = hollow();
  const features::DrillResult& r = f.drilled;
  BOOST_TEST(r.drilled == 16);
  BOOST_TEST(r.fallen_back == 0);
  // verify_solid: BRepCheck, no free edges, oriented shells, closed (watertight) mesh, positive volume.
  BOOST_TEST(r.check.all_passed(), r.check.failed_names());
  BOOST_TEST(r.check.brep_valid.passed);
  BOOST_TEST(r.check.closed_mesh.passed);
  BOOST_TEST(count(r.part.shape, TopAbs_SOLID) == 1);
  double removed = 0;
  for (const auto& h : r.holes) {
    BOOST_TEST(h.drilled, h.name << ": " << h.fallback_reason);
    BOOST_TEST(h.entry_face == "blade_wall");
    BOOST_TEST(h.exit_face == "chamber_1_wall");
    BOOST_TEST(std::abs(h.volume - h.independent_volume) <= 1e-6 * h.independent_volume + h.uncertainty, h.name);
    BOOST_TEST(h.edge_tolerance <= 1.5e-7);  // loops fitted within DrillOptions::fit_tolerance = 1e-7 mm
    removed += h.volume;
  }
  BOOST_TEST(std::abs(r.check.volume - (f.hb.volume - removed)) <= 1e-6 * f.hb.volume);
}

BOOST_AUTO_TEST_CASE(same_solid_as_the_verified_boolean_path) {
  const Fixture& f = hollow();
  features::BooleanOptions bo;
  bo.patch_min_tools = 0;
  features::BooleanStep step(features::BooleanOperation::Cut, bo);
  for (const auto& h : f.holes) step.add(features::hole_tool(h));
  const brep::NamedShape ref = step.apply(f.hb.part);
  const features::DrillResult& r = f.drilled;
  const double v_ref = volume(ref.shape), v = volume(r.part.shape);
  BOOST_TEST(std::abs(v - v_ref) <= 1e-6 * v_ref, "drilled " << v << " vs boolean " << v_ref);
  BOOST_TEST(count(r.part.shape, TopAbs_FACE) == count(ref.shape, TopAbs_FACE));
  BOOST_TEST(names(r.part) == names(ref), "face names differ");
  for (std::size_t i = 0; i < f.holes.size(); ++i) {
    const auto& t = step.report().tools[i];
    const auto& h = r.holes[i];
    BOOST_TEST(t.feature == h.name);
    BOOST_TEST(std::abs(h.volume - t.measured_volume) <= 1e-6 * t.measured_volume + h.uncertainty + t.uncertainty,
               h.name << ": drilled " << h.volume << ", boolean " << t.measured_volume);
  }
}

BOOST_AUTO_TEST_CASE(hole_diameter_and_axis_measured_from_the_faces) {
  const Fixture& f = hollow();
  std::map<std::string, const features::CylindricalHole*> by_name;
  for (const auto& h : f.holes) by_name[h.name] = &h;
  int measured = 0;
  for (const auto& nf : f.drilled.part.faces) {
    const auto it = by_name.find(nf.name);
    if (it == by_name.end()) continue;
    const auto cyl = Handle(Geom_CylindricalSurface)::DownCast(BRep_Tool::Surface(nf.face));
    BOOST_TEST_REQUIRE(!cyl.IsNull());
    const features::CylindricalHole& h = *it->second;
    BOOST_TEST(std::abs(2 * cyl->Radius() - h.diameter) <= 1e-9);
    const gp_Ax1 axis = cyl->Axis();
    const Eigen::Vector3d d(axis.Direction().X(), axis.Direction().Y(), axis.Direction().Z());
    BOOST_TEST(d.cross(h.axis.normalized()).norm() <= 1e-9);
    const Eigen::Vector3d p(axis.Location().X(), axis.Location().Y(), axis.Location().Z());
    BOOST_TEST((h.origin - p).cross(d).norm() <= 1e-9);  // the hole's origin lies on the face's axis
    // The face is the material side of the hole: its normal points to the axis (face REVERSED).
    BOOST_TEST(nf.face.Orientation() == TopAbs_REVERSED);
    ++measured;
  }
  BOOST_TEST(measured == 16);
}

BOOST_AUTO_TEST_CASE(holes_that_do_not_qualify_fall_back_to_the_boolean_path) {
  const Fixture& f = hollow();
  std::vector<features::CylindricalHole> holes(f.holes.begin(), f.holes.begin() + 4);
  // Blind: the tool ends inside the wall.
  holes[0].length = 0.5 * holes[0].length;
  // Overlapping: a second hole 0.3 mm beside hole 1 (D 0.5 mm).
  features::CylindricalHole twin = holes[1];
  twin.name = "twin";
  const Eigen::Vector3d side = twin.axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  twin.origin += 0.3 * side;
  holes.push_back(twin);
  // Through the whole blade: enters the wall, crosses the cavity and leaves through the far wall.
  holes[2].length = 40;
  const features::DrillResult r = features::drill_holes(f.hb.part, holes);
  BOOST_TEST(r.drilled == 1);
  BOOST_TEST(r.fallen_back == 4);
  BOOST_TEST(r.holes[3].drilled);
  BOOST_TEST(r.holes[0].fallback_reason.find("does not cross a wall") != std::string::npos, r.holes[0].fallback_reason);
  BOOST_TEST(r.holes[1].fallback_reason.find("within the margin of hole 'twin'") != std::string::npos);
  BOOST_TEST(r.holes[4].fallback_reason.find("within the margin of hole") != std::string::npos);
  BOOST_TEST(r.holes[2].fallback_reason.find("faces, not one wall") != std::string::npos, r.holes[2].fallback_reason);
  // The fallback step applied them, fused the overlapping pair, and verified its result.
  BOOST_TEST(r.fallback.tool_count == 4);
  BOOST_TEST(r.fallback.cluster_count == 1);
  BOOST_TEST(r.fallback.check.all_passed(), r.fallback.check.failed_names());
  for (const auto& t : r.fallback.tools) BOOST_TEST(t.passed, t.feature);
  const std::multiset<std::string> n = names(r.part);
  for (const auto& h : holes) BOOST_TEST(n.count(h.name) >= 1u, h.name);
}

BOOST_AUTO_TEST_CASE(a_tool_starting_inside_the_wall_is_not_drilled_across_the_cavity) {
  // From 0.3 mm before the exit into the cavity, across it, 0.3 mm into the far wall: the axis meets
  // two faces (the near and the far chamber wall) but the tool passes through material, then cavity,
  // then material -- not a hole through one wall. It must fall back, and the boolean path cuts it.
  const Fixture& f = hollow();
  features::CylindricalHole h = f.holes[5];
  RaySurfaceCaster core(f.hb.core_surface);
  const Eigen::Vector3d d = h.axis.normalized();
  const RaySurfaceHit near = core.first_hit(h.origin, d, 30);
  BOOST_TEST_REQUIRE(near.found);
  const RaySurfaceHit far = core.first_hit(h.origin + (near.ray_param + 1e-3) * d, d, 30);
  BOOST_TEST_REQUIRE(far.found);
  h.origin += (near.ray_param - 0.3) * d;
  h.length = 0.3 + 1e-3 + far.ray_param + 0.3;
  h.name = "inside_start";
  const features::DrillResult r = features::drill_holes(f.hb.part, {h});
  BOOST_TEST(r.drilled == 0);
  BOOST_TEST(r.holes[0].fallback_reason.find("starts inside the part") != std::string::npos, r.holes[0].fallback_reason);
  BOOST_TEST(r.fallback.check.all_passed(), r.fallback.check.failed_names());
}

BOOST_AUTO_TEST_CASE(each_precondition_decides_by_its_option) {
  // The sample holes meet the walls at 30 deg (entry) and are >= ~1 mm apart: they qualify with the
  // defaults, not with a minimum incidence of 40 deg.
  const Fixture& f = hollow();
  const std::vector<features::CylindricalHole> holes(f.holes.begin(), f.holes.begin() + 6);
  for (const std::string& reason : features::drill_fallback_reasons(f.hb.part, holes)) BOOST_TEST(reason.empty(), reason);
  features::DrillOptions steep;
  steep.min_incidence_deg = 40;
  for (const std::string& reason : features::drill_fallback_reasons(f.hb.part, holes, steep))
    BOOST_TEST(reason.find("minimum incidence angle") != std::string::npos, reason);
  // Two holes 0.6 mm apart (D 0.5 mm: a 0.1 mm ligament) qualify with the default 0.02 mm margin and
  // fall back together with a 0.2 mm margin.
  features::CylindricalHole twin = holes[1];
  twin.name = "twin";
  twin.origin += 0.6 * twin.axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  const std::vector<features::CylindricalHole> pair{holes[1], twin};
  for (const std::string& reason : features::drill_fallback_reasons(f.hb.part, pair)) BOOST_TEST(reason.empty(), reason);
  features::DrillOptions wide;
  wide.margin = 0.2;
  for (const std::string& reason : features::drill_fallback_reasons(f.hb.part, pair, wide))
    BOOST_TEST(reason.find("within the margin of hole") != std::string::npos, reason);
}

BOOST_AUTO_TEST_CASE(bad_holes_are_rejected) {
  const Fixture& f = hollow();
  auto with = [&](auto change) {
    std::vector<features::CylindricalHole> holes(f.holes.begin(), f.holes.begin() + 2);
    change(holes);
    return holes;
  };
  BOOST_CHECK_THROW(features::drill_holes(f.hb.part, with([](auto& h) { h[0].axis.setZero(); })), InvalidGeometry);
  BOOST_CHECK_THROW(features::drill_holes(f.hb.part, with([](auto& h) { h[0].diameter = 0; })), InvalidGeometry);
  BOOST_CHECK_THROW(features::drill_holes(f.hb.part, with([](auto& h) { h[0].length = -1; })), InvalidGeometry);
  BOOST_CHECK_THROW(features::drill_holes(f.hb.part, with([](auto& h) { h[1].name = h[0].name; })), InvalidGeometry);
  BOOST_CHECK_THROW(features::drill_holes(f.hb.part, with([](auto& h) { h[0].origin.x() = NAN; })), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(step_round_trip_keeps_the_solid_and_every_name) {
  const Fixture& f = hollow();
  const brep::NamedShape& part = f.drilled.part;
  test::TempDir dir("drill_step");
  const auto file = dir.path / "drilled.step";
  io::write_step(file, part.shape, part.faces, {io::StepSchema::AP214, "drilled"});
  const test::StepReadBack back = test::read_step_back(file);
  BOOST_TEST_REQUIRE(back.ok);
  BOOST_TEST_REQUIRE(back.free_shapes.size() == 1u);
  BOOST_TEST(back.names == names(part));
  BOOST_TEST(count(back.free_shapes[0], TopAbs_SOLID) == 1);
  BOOST_TEST(std::abs(volume(back.free_shapes[0]) - volume(part.shape)) <= 1e-6 * volume(part.shape));
}
