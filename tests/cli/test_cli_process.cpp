// The coolinggen executable run as a process: the built-in example and a straight C3X vane give a
// valid STEP (read back: one valid solid, volume equal to the report's to 1e-6 relative, the
// integration accuracy) and report.json (the built-in example's passage table: every chamber at every
// span, holes as holes); bad configs exit non-zero with one line on stderr naming
// the field, and write nothing (not even the output directory).
#define BOOST_TEST_MODULE cli_process
#include <boost/test/unit_test.hpp>

#include <STEPControl_Reader.hxx>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "brep/temp_files.hpp"
#include "cli/run_cli.hpp"
#include "src/blade/section.hpp"
#include "src/brep/verify.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

using test::read_text;
using test::TempDir;

test::Run run(const std::string& args, const fs::path& dir) { return test::run_cli(args, dir); }
int lines(const std::string& s) { return test::count_lines(s); }

// Reads DIR/blade.step and DIR/report.json and checks them against each other.
void check_outputs(const fs::path& dir, const std::string& expected_name) {
  BOOST_TEST_REQUIRE(fs::exists(dir / "blade.step"));
  BOOST_TEST_REQUIRE(fs::exists(dir / "report.json"));
  const auto report = nlohmann::json::parse(read_text(dir / "report.json"));
  BOOST_TEST(report.at("valid").get<bool>());
  BOOST_TEST(report.at("model").at("name").get<std::string>() == expected_name);
  for (const auto& [name, c] : report.at("checks").items()) BOOST_TEST(c.at("passed").get<bool>(), name);
  STEPControl_Reader reader;
  BOOST_TEST_REQUIRE(reader.ReadFile((dir / "blade.step").string().c_str()) == IFSelect_RetDone);
  reader.TransferRoots();
  const cg::brep::SolidCheck c = cg::brep::verify_solid(reader.OneShape());
  for (const cg::brep::Check* k : c.checks()) BOOST_TEST(k->passed, k->name << ": " << k->message);
  const double v = report.at("solid").at("volume_mm3").get<double>();
  BOOST_TEST(v > 0);
  BOOST_TEST(std::abs(c.volume - v) <= 1e-6 * v, c.volume << " vs " << v);
  BOOST_TEST(c.face_count == report.at("solid").at("face_count").get<int>());
  const std::string step = read_text(dir / "blade.step");
  for (const char* n : {"blade_wall", "hub", "casing"})
    BOOST_TEST(step.find(std::string("ADVANCED_FACE('") + n + "'") != std::string::npos, n);
}

}  // namespace

BOOST_AUTO_TEST_CASE(builtin_example_builds) {
  TempDir dir("cli_example");
  const test::Run r = run("build -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.err.empty(), r.err);
  BOOST_TEST(r.out.find("volume") != std::string::npos, r.out);
  check_outputs(dir.path / "out", "hpt_rotor");
  // The hand-off outputs (README, Outputs) and nothing else, no temporary files; preview.png only
  // when an X display could be had.
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir.path / "out")) files.insert(e.path().filename().string());
  std::set<std::string> expected{"blade.step", "blade.igs",   "blade.brep",  "blade.stl", "blade.vtm", "blade_blade.vtp",
                                 "blade.glb",  "sections.svg", "report.html", "report.json", "report.md",
                                 // the coolant network: the built-in example has a "coolant" section
                                 "network.json", "network.inp", "network_results.json", "film_holes.csv"};
  if (files.count("preview.png")) expected.insert("preview.png");
  BOOST_TEST(files == expected);
  // The passage table (report.json "sections", what sections.svg shows): all four chambers at every
  // span, the film and showerhead holes crossing the cuts as holes, none of them a passage (issue 20).
  const auto report = nlohmann::json::parse(read_text(dir.path / "out" / "report.json"));
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

// data/examples/c3x_vane.json: a straight vane from the C3X points (file path relative to the config).
BOOST_AUTO_TEST_CASE(straight_c3x_vane_builds) {
  TempDir dir("cli_c3x");
  const std::string cfg = COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json";
  const test::Run v = run("validate '" + cfg + "'", dir.path);
  BOOST_TEST(v.exit_code == 0, v.err);
  const test::Run r = run("build '" + cfg + "' -q -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.out.empty());
  check_outputs(dir.path / "out", "c3x_vane");
  // Prismatic vane: volume = (section area - passage areas) x span. The area of the interpolated C3X profile (Green's
  // theorem in our kernel) differs from the blade surface's section only by the surface's
  // re-interpolation at its chordwise samples: 1e-4 relative.
  const double span = nlohmann::json::parse(read_text(cfg)).at("flow_path").at("span").get<double>();
  const auto report = nlohmann::json::parse(read_text(dir.path / "out" / "report.json"));
  const double volume = report.at("solid").at("volume_mm3").get<double>();
  cg::blade::PointSectionDefinition def;
  def.points = cg::blade::read_section_points(COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv", cg::blade::LengthUnit::Centimetre);
  double area = std::abs(cg::blade::section_properties(cg::blade::section_from_points(def).curve).area);
  // Minus the ten radial passages (NASA CR-168015 Fig. 7: diameters 6.30 mm x 7, 3.10 mm x 2, 1.98 mm).
  const double pi = 3.14159265358979323846;
  area -= 0.25 * pi * (7 * 6.30 * 6.30 + 2 * 3.10 * 3.10 + 1.98 * 1.98);
  BOOST_TEST(std::abs(volume / span - area) < 1e-4 * area, volume / span << " vs " << area);
  BOOST_TEST(std::abs(report.at("solid").at("bbox_mm").at("size").at(2).get<double>() - span) < 1e-6);
}

// The AP242 schema option reaches the file.
BOOST_AUTO_TEST_CASE(ap242_option) {
  TempDir dir("cli_ap242");
  nlohmann::json cfg = nlohmann::json::parse(read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  cfg["sections"][0]["points"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv";
  cfg.erase("cooling");
  cfg["output"]["step_schema"] = "AP242";
  cfg["flow_path"]["span"] = 20.0;
  std::ofstream(dir.path / "c3x.json") << cfg.dump(2);
  const test::Run r = run("build '" + (dir.path / "c3x.json").string() + "' -q -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(read_text(dir.path / "out" / "blade.step").find("AP242") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_config_fails_without_output) {
  TempDir dir("cli_bad");
  // Take the built-in example (printed by `coolinggen example`) and break one field.
  nlohmann::json cfg;
  {
    TempDir ex("cli_example_json");
    const test::Run e = run("example", ex.path);
    BOOST_TEST_REQUIRE(e.exit_code == 0);
    cfg = nlohmann::json::parse(e.out);
  }
  cfg["sections"][2]["parametric"]["max_thickness"] = -2.0;
  std::ofstream(dir.path / "bad.json") << cfg.dump(2);
  const fs::path out = dir.path / "out";
  const test::Run b = run("build '" + (dir.path / "bad.json").string() + "' -o '" + out.string() + "'", dir.path);
  BOOST_TEST(b.exit_code == 2);
  BOOST_TEST(lines(b.err) == 1, b.err);
  BOOST_TEST(b.err.find("sections[2].parametric.max_thickness") != std::string::npos, b.err);
  BOOST_TEST(b.out.empty());
  BOOST_TEST(!fs::exists(out));

  const test::Run v = run("validate '" + (dir.path / "bad.json").string() + "'", dir.path);
  BOOST_TEST(v.exit_code == 2);
  BOOST_TEST(lines(v.err) == 1, v.err);

  const test::Run missing = run("validate '" + (dir.path / "none.json").string() + "'", dir.path);
  BOOST_TEST(missing.exit_code != 0);
  BOOST_TEST(lines(missing.err) == 1, missing.err);

  const test::Run usage = run("build", dir.path);  // -o missing
  BOOST_TEST(usage.exit_code == 1);
  BOOST_TEST(lines(usage.err) == 1, usage.err);
  const test::Run nothing = run("", dir.path);
  BOOST_TEST(nothing.exit_code != 0);
}

BOOST_AUTO_TEST_CASE(help_lists_commands) {
  TempDir dir("cli_help");
  const test::Run h = run("--help", dir.path);
  BOOST_TEST(h.exit_code == 0);
  for (const char* cmd : {"build", "validate", "example"}) BOOST_TEST(h.out.find(cmd) != std::string::npos, cmd);
}
