// `coolinggen grid` as a process: the built-in example (three HPT sections, O-grids) and the C3X example
// (a cascade from its "grid" section) write their files and grid_report.json; a bad grid option exits 2
// with one line naming the field and writes nothing (not even the directory).
#define BOOST_TEST_MODULE grid_cli
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "brep/temp_files.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

struct Run {
  int exit_code;
  std::string out, err;
};

Run coolinggen(const std::string& args, const fs::path& dir) {
  const fs::path binary = fs::path(COOLINGGEN_BINARY_DIR) / "coolinggen";
  BOOST_TEST_REQUIRE(fs::exists(binary), "build the coolinggen target first: " << binary);
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const int status = std::system(("'" + binary.string() + "' " + args + " > '" + out.string() + "' 2> '" + err.string() + "'").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_text(out), test::read_text(err)};
}

}  // namespace

BOOST_AUTO_TEST_CASE(builtin_example_gets_an_o_grid_per_section) {
  const test::TempDir dir("grid_cli_example");
  const Run r = coolinggen("grid -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.out.find("hpt_rotor: 3 section grids") != std::string::npos);
  const auto rep = nlohmann::json::parse(test::read_text(dir.path / "out" / "grid_report.json"));
  BOOST_TEST(rep["sections"].size() == 3u);
  for (const auto& s : rep["sections"]) {
    BOOST_TEST(s["layout"].get<std::string>() == "o_grid");
    BOOST_TEST(s["cells"].get<int>() == 175 * 59);
    BOOST_TEST(s["inverted_cells"].get<int>() == 0);
    BOOST_TEST(s["wall"]["max_angle_deviation_deg"].get<double>() < 1e-6);
  }
  for (const auto& f : rep["outputs"]) BOOST_TEST(fs::exists(dir.path / "out" / f.get<std::string>()));
}

BOOST_AUTO_TEST_CASE(c3x_example_is_a_cascade) {
  const test::TempDir dir("grid_cli_c3x");
  const Run r = coolinggen("grid '" COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json' -q -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.out.empty());
  const auto rep = nlohmann::json::parse(test::read_text(dir.path / "out" / "grid_report.json"));
  BOOST_TEST(rep["sections"][0]["layout"].get<std::string>() == "cascade");
  BOOST_TEST(rep["sections"][0]["cells"].get<int>() == 12806);
}

BOOST_AUTO_TEST_CASE(bad_grid_option_writes_nothing) {
  const test::TempDir dir("grid_cli_bad");
  nlohmann::json cfg = nlohmann::json::parse(test::read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  cfg["sections"][0]["points"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv";
  cfg["cooling"]["radial_passages"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/cooling_holes_fig7_cm.csv";
  cfg["grid"] = {{"cascade", {{"pitch", 50}}}};  // narrower than the vane across its mid-line
  std::ofstream(dir.path / "c3x.json") << cfg.dump(2);
  const Run r = coolinggen("grid '" + (dir.path / "c3x.json").string() + "' -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST(r.exit_code == 2);
  BOOST_TEST(r.err.rfind("coolinggen: error: grid.cascade.pitch: ", 0) == 0, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(!fs::exists(dir.path / "out"));
}
