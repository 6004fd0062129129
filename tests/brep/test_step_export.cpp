// STEP round trip of the synthetic blade solid (AP214 and AP242): read back with STEPControl_Reader
// -> one valid solid of the same volume (1e-6 relative: STEP stores the B-spline data as decimal
// text with 15+ significant digits, so only the integration accuracy remains) and the face names
// present (read back through XCAF and in the file text). Also the atomic writing and report.json.
#define BOOST_TEST_MODULE step_export
#include <boost/test/unit_test.hpp>

#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "brep/step_read_back.hpp"
#include "brep/synthetic_blade.hpp"
#include "brep/temp_files.hpp"
#include "export/atomic_file.hpp"
#include "export/report.hpp"
#include "export/step_writer.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/brep/verify.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

brep::BladeSolid sample_solid() {
  const test::EllipticBlade e;
  const std::vector<double> U{0, 0, 1, 1};
  const BSplineCurve<2> hub(1, U, {Eigen::Vector2d(-40, 90), Eigen::Vector2d(40, 92)});
  const BSplineCurve<2> casing(1, U, {Eigen::Vector2d(-40, 121), Eigen::Vector2d(40, 119)});
  return brep::build_blade_solid(test::elliptic_blade_surface(e), brep::RevolvedTrim{hub}, brep::RevolvedTrim{casing});
}

// Face names found on the sub-shape labels of the free shapes of a STEP file read through XCAF.
std::multiset<std::string> xcaf_face_names(const fs::path& file) { return test::read_step_back(file).names; }

void round_trip(io::StepSchema schema) {
  const auto solid = sample_solid();
  const brep::SolidCheck before = brep::verify_solid(solid.solid);
  BOOST_TEST_REQUIRE(before.all_passed());
  test::TempDir dir(std::string("step_") + io::step_schema_name(schema));
  const fs::path file = dir.path / "blade.step";
  io::write_step(file, solid.solid, solid.faces, {schema, "synthetic_blade"});
  BOOST_TEST(dir.entries() == std::vector<std::string>{"blade.step"});  // no temporary file left

  STEPControl_Reader reader;
  BOOST_TEST_REQUIRE(reader.ReadFile(file.string().c_str()) == IFSelect_RetDone);
  BOOST_TEST_REQUIRE(reader.TransferRoots() >= 1);
  const TopoDS_Shape back = reader.OneShape();
  const brep::SolidCheck after = brep::verify_solid(back);
  for (const brep::Check* c : after.checks()) BOOST_TEST(c->passed, c->name << ": " << c->message);
  BOOST_TEST(std::abs(after.volume - before.volume) <= 1e-6 * before.volume);
  BOOST_TEST(after.face_count == before.face_count);

  const std::string text = test::read_text(file);
  BOOST_TEST(text.find(schema == io::StepSchema::AP242 ? "AP242" : "AUTOMOTIVE_DESIGN") != std::string::npos);
  BOOST_TEST(text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos);
  for (const char* n : {brep::kWallFaceName, brep::kHubFaceName, brep::kCasingFaceName})
    BOOST_TEST(text.find(std::string("ADVANCED_FACE('") + n + "'") != std::string::npos, n);
  const auto names = xcaf_face_names(file);
  BOOST_TEST(names.count(brep::kWallFaceName) == 1u);
  BOOST_TEST(names.count(brep::kHubFaceName) == 1u);
  BOOST_TEST(names.count(brep::kCasingFaceName) == 1u);
}

}  // namespace

BOOST_AUTO_TEST_CASE(step_round_trip_ap214) { round_trip(io::StepSchema::AP214); }
BOOST_AUTO_TEST_CASE(step_round_trip_ap242) { round_trip(io::StepSchema::AP242); }

BOOST_AUTO_TEST_CASE(schema_names) {
  BOOST_TEST(std::string(io::step_schema_name(io::parse_step_schema("ap242"))) == "AP242");
  BOOST_TEST(std::string(io::step_schema_name(io::parse_step_schema("AP214"))) == "AP214");
  BOOST_CHECK_THROW(io::parse_step_schema("AP203"), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(atomic_write_leaves_nothing_on_failure) {
  test::TempDir dir("atomic");
  const fs::path target = dir.path / "out.txt";
  {
    std::ofstream(target) << "old";
  }
  // The writer writes part of the file, then fails: the old target stays, no temporary remains.
  BOOST_CHECK_THROW(io::write_atomically(target,
                                         [](const fs::path& tmp) {
                                           std::ofstream(tmp) << "half";
                                           throw std::runtime_error("disk full");
                                         }),
                    io::ExportError);
  BOOST_TEST(test::read_text(target) == "old");
  BOOST_TEST(dir.entries() == std::vector<std::string>{"out.txt"});
  // A writer producing nothing is an error too.
  BOOST_CHECK_THROW(io::write_atomically(target, [](const fs::path&) {}), io::ExportError);
  BOOST_TEST(dir.entries() == std::vector<std::string>{"out.txt"});
  io::write_atomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "new"; });
  BOOST_TEST(test::read_text(target) == "new");
  BOOST_CHECK_THROW(io::write_atomically(dir.path / "missing" / "x.txt", [](const fs::path& tmp) { std::ofstream(tmp) << "x"; }),
                    io::ExportError);
  // A null shape is refused before anything is written.
  BOOST_CHECK_THROW(io::write_step(dir.path / "null.step", TopoDS_Shape(), {}), io::ExportError);
  BOOST_TEST(dir.entries() == std::vector<std::string>{"out.txt"});
}

BOOST_AUTO_TEST_CASE(report_json_content) {
  const auto solid = sample_solid();
  io::ReportContent rc;
  rc.check = brep::verify_solid(solid.solid);
  for (const auto& f : solid.faces) ++rc.face_names[f.name];
  rc.model = {{"name", "synthetic"}};
  rc.timings_s = {{"solid", 0.1}};
  test::TempDir dir("report");
  io::write_report(dir.path / "report.json", rc);
  const auto j = nlohmann::json::parse(test::read_text(dir.path / "report.json"));
  BOOST_TEST(j.at("valid").get<bool>());
  BOOST_TEST(j.at("model").at("name").get<std::string>() == "synthetic");
  BOOST_TEST(j.at("solid").at("volume_mm3").get<double>() == rc.check.volume);
  BOOST_TEST(j.at("solid").at("surface_area_mm2").get<double>() == rc.check.area());
  BOOST_TEST(j.at("solid").at("face_count").get<int>() == 3);
  BOOST_TEST(j.at("solid").at("faces").at(brep::kWallFaceName).get<int>() == 1);
  BOOST_TEST(j.at("solid").at("bbox_mm").at("max").at(2).get<double>() == rc.check.bbox_max[2]);
  for (const brep::Check* c : rc.check.checks()) BOOST_TEST(j.at("checks").at(c->name).at("passed").get<bool>());
  // A failed check makes the report invalid.
  rc.check.closed_mesh.passed = false;
  BOOST_TEST(!io::report_json(rc).at("valid").get<bool>());
  BOOST_TEST(!io::report_json(rc).at("checks").at("closed_mesh").at("passed").get<bool>());
}
