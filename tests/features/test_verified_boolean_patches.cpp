// Patches (src/brep/face_patches.hpp) and the per-tool measurement's own failure signals.
#define BOOST_TEST_MODULE verified_boolean_patches
#include <boost/test/unit_test.hpp>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "boolean_test_shapes.hpp"
#include "src/brep/face_patches.hpp"
#include "src/brep/boolean/boolean_run.hpp"
#include "src/brep/boolean/boolean_volume.hpp"

using namespace cg;
using namespace cg::features;
using test::cylinder_tool;
using test::kPi;

namespace {

double rel(double a, double b) { return std::abs(a - b) / std::max(1e-300, std::abs(b)); }

// n x n vertical holes of radius r through a 40 x 40 x 2 plate (block_top / block_bottom / block_side).
std::vector<FeatureTool> hole_grid(int n, double r) {
  std::vector<FeatureTool> tools;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      tools.push_back(cylinder_tool("hole_" + std::to_string(i * n + j + 1),
                                    gp_Pnt(2 + 36.0 * (i + 0.5) / n, 2 + 36.0 * (j + 0.5) / n, -1), gp::DZ(), r, 4,
                                    kPi * r * r * 2));
  return tools;
}

}  // namespace

// The top and bottom faces, reached by all 64 holes, are cut into patches along iso-lines in the
// gaps between the holes; every piece keeps its name and the solid stays valid.
BOOST_AUTO_TEST_CASE(patches_keep_names) {
  const brep::NamedShape plate = test::named_block(40, 40, 2);
  std::vector<TopoDS_Shape> shapes;
  for (const FeatureTool& t : hole_grid(8, 0.4)) shapes.push_back(t.shape.shape);
  PatchOptions o;
  o.min_tools = 16;
  o.tools_per_patch = 8;
  const PatchedPart p = patch_faces(plate, shapes, o);
  BOOST_TEST(p.cut_lines > 0);
  BOOST_TEST(p.faces_after > p.faces_before);
  BOOST_TEST(p.warnings.empty());
  const auto names = brep::count_face_names(p.part);
  BOOST_TEST(names.at("block_top") >= 6);  // 64 tools / 8 per patch, in a grid of whole lines
  BOOST_TEST(names.at("block_bottom") == names.at("block_top"));
  BOOST_TEST(names.at("block_side") == 4);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(p.part.shape, TopAbs_FACE, faces);
  BOOST_TEST(faces.Extent() == p.faces_after);
  const brep::SolidCheck c = brep::verify_solid(p.part.shape);
  BOOST_TEST(c.all_passed(), c.failed_names());
  BOOST_TEST(std::abs(c.volume - 3200) < 1e-6 * 3200);
  // Fewer tools than min_tools: nothing to do.
  o.min_tools = 100;
  BOOST_TEST(patch_faces(plate, shapes, o).cut_lines == 0);
}

// A step with enough tools patches the part first and still names and measures everything.
BOOST_AUTO_TEST_CASE(step_with_patches) {
  const brep::NamedShape plate = test::named_block(40, 40, 2);
  BooleanOptions o;
  o.patch_min_tools = 16;
  o.patch_tools_per_patch = 8;
  BooleanStep step(BooleanOperation::Cut, o);
  for (FeatureTool& t : hole_grid(8, 0.4)) step.add(std::move(t));
  const brep::NamedShape result = step.apply(plate);
  const BooleanStepReport& rep = step.report();
  BOOST_TEST(rep.patched_faces > 0);
  BOOST_TEST(rep.boolean_runs == 1);
  BOOST_TEST(rep.check.all_passed(), rep.check.failed_names());
  for (const ToolReport& t : rep.tools) BOOST_TEST(rel(t.measured_volume, kPi * 0.16 * 2) < 1e-6, t.feature);
  const auto names = brep::count_face_names(result);
  BOOST_TEST(names.count("unnamed") == 0u);
  BOOST_TEST(names.at("hole_1") == 1);
  BOOST_TEST(names.at("hole_64") == 1);
  BOOST_TEST(std::abs(rep.check.volume - (3200 - 64 * kPi * 0.16 * 2)) < 1e-6 * 3200);
}

// The measurement's own failure signals. A piece of the part that no listed tool accounts for is
// reported as lost (a boolean that dropped part of the part); a tool whose pieces are not found in
// the result leaves an open boundary, seen as a closure error far above the integration accuracy.
BOOST_AUTO_TEST_CASE(measurement_sees_lost_pieces_and_open_boundaries) {
  const brep::NamedShape block = test::named_block(20, 20, 10);
  const FeatureTool a = cylinder_tool("a", gp_Pnt(5, 5, -1), gp::DZ(), 1, 12, kPi * 10);
  const FeatureTool b = cylinder_tool("b", gp_Pnt(15, 15, -1), gp::DZ(), 2, 12, kPi * 40);
  const BooleanRun run = run_boolean(block.shape, {a.shape.shape, b.shape.shape}, BooleanOperation::Cut, true);
  BOOST_REQUIRE(!run.result.IsNull());
  const VolumeMeasure both = measure_tool_volumes(run, block.shape, {a.shape.shape, b.shape.shape}, BooleanOperation::Cut, true);
  BOOST_TEST(both.lost_pieces == 0);
  BOOST_TEST(rel(both.tools[0].volume, kPi * 10) < 1e-9);
  BOOST_TEST(rel(both.tools[1].volume, kPi * 40) < 1e-9);
  BOOST_TEST(both.tools[1].closure < 1e-9);
  // As if the boolean had dropped b's discs from the top and bottom faces without a tool there.
  const VolumeMeasure only_a = measure_tool_volumes(run, block.shape, {a.shape.shape}, BooleanOperation::Cut, true);
  BOOST_TEST(only_a.lost_pieces == 2);
  BOOST_TEST(rel(only_a.lost_area, 2 * kPi * 4) < 1e-5);
  // A tool whose own pieces are not in the result (here: a copy of the blind hole moved by 1e-3 mm,
  // so none of its faces is a face of the result) leaves only the dropped top disc: the boundary is
  // open, its volume depends on the reference point (closure), and the volume is far off.
  const FeatureTool blind = cylinder_tool("blind", gp_Pnt(10, 10, 6), gp::DZ(), 1, 5, kPi * 4);
  const BooleanRun run2 = run_boolean(block.shape, {blind.shape.shape}, BooleanOperation::Cut, true);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(0, 0, 1e-3));
  const VolumeMeasure open = measure_tool_volumes(run2, block.shape, {blind.shape.shape.Moved(shift)}, BooleanOperation::Cut, true);
  BOOST_TEST(open.lost_pieces == 0);
  BOOST_TEST(open.tools[0].part_pieces == 1);
  BOOST_TEST(open.tools[0].tool_pieces == 0);
  BOOST_TEST(open.tools[0].closure > 0.1);
  BOOST_TEST(std::abs(open.tools[0].volume - kPi * 4) > 1.0);
}
