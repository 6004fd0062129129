// Issue 8 item 7, as a user meets it: no silent wrong input, no stale output. Each bad input makes the
// coolinggen binary exit with the documented code and one line on stderr that names the field (or the
// file line) and says what to do; no message carries the JSON library's exception ids.
#define BOOST_TEST_MODULE cli_inputs
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"
#include "cli/star_profile.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;
using test::q;
using test::read_text;
using test::TempDir;

namespace {

json c3x_config() {
  json d = json::parse(read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  d["sections"][0]["points"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv";
  d.erase("cooling");  // these tests are about the section input
  return d;
}

// Exit code `code`, one line on stderr starting "coolinggen: error: " and containing every `parts`.
void expect_failure(const test::Run& r, int code, std::initializer_list<const char*> parts) {
  BOOST_TEST(r.exit_code == code, r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, r.err);
  BOOST_TEST(r.err.rfind("coolinggen: error: ", 0) == 0u, r.err);
  BOOST_TEST(r.err.find("json.exception") == std::string::npos, r.err);
  for (const char* p : parts) BOOST_TEST(r.err.find(p) != std::string::npos, "expected '" << p << "' in " << r.err);
}

}  // namespace

// A three-column CSV without a header: an index column is recognised; (x, y, z) is refused.
BOOST_AUTO_TEST_CASE(three_column_point_files) {
  TempDir dir("cli_csv3");
  std::ifstream in(COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv");
  std::ofstream idx(dir.path / "idx.csv"), xyz(dir.path / "xyz.csv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'p') continue;  // comment and header
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1), c3 = line.find(',', c2 + 1);
    idx << line.substr(0, c3) << "\n";                                            // point, x, y
    xyz << line.substr(c1 + 1, c3 - c1 - 1) << ",0\n";                            // x, y, z
  }
  idx.close();
  xyz.close();
  json d = c3x_config();
  d["sections"][0]["points"]["file"] = "idx.csv";
  std::ofstream(dir.path / "idx.json") << d.dump();
  d["sections"][0]["points"]["file"] = "xyz.csv";
  std::ofstream(dir.path / "xyz.json") << d.dump();
  // The indexed file builds the same vane as the original table: compare the volumes.
  const test::Run a = test::run_cli("build " + q(dir.path / "idx.json") + " -q -o " + q(dir.path / "a"), dir.path);
  BOOST_TEST_REQUIRE(a.exit_code == 0, a.err);
  std::ofstream(dir.path / "orig.json") << c3x_config().dump();
  const test::Run b = test::run_cli("build " + q(dir.path / "orig.json") + " -q -o " + q(dir.path / "b"), dir.path);
  BOOST_TEST_REQUIRE(b.exit_code == 0, b.err);
  const auto volume = [&](const char* sub) {
    return json::parse(read_text(dir.path / sub / "report.json")).at("solid").at("volume_mm3").get<double>();
  };
  BOOST_TEST(volume("a") == volume("b"));
  expect_failure(test::run_cli("validate " + q(dir.path / "xyz.json"), dir.path), 2,
                 {"sections[0].points.file:", "3 columns and no header", "ambiguous", "header line"});
}

// "unit": "cm", "unit": "mm" would give a vane 10x too small: refused naming the key path.
BOOST_AUTO_TEST_CASE(duplicate_keys) {
  TempDir dir("cli_dupkey");
  std::string text = c3x_config().dump(1);
  text.replace(text.find("\"unit\": \"cm\""), 12, "\"unit\": \"cm\", \"unit\": \"mm\"");
  std::ofstream(dir.path / "dup.json") << text;
  expect_failure(test::run_cli("validate " + q(dir.path / "dup.json"), dir.path), 2,
                 {"sections[0].points.unit: duplicate key"});
}

// Text errors: a number beyond a double is a config error (exit 2, not 5) at its line and column; a
// directory or a missing file given as config says so.
BOOST_AUTO_TEST_CASE(text_and_file_errors) {
  TempDir dir("cli_text");
  std::ofstream(dir.path / "big.json") << "{\n  \"units\": \"mm\",\n  \"flow_path\": {\"type\": \"straight\", \"span\": 1e99999}\n}\n";
  expect_failure(test::run_cli("build " + q(dir.path / "big.json") + " -o " + q(dir.path / "out"), dir.path), 2,
                 {"big.json line 3, column 45: number out of range", "1e99999"});
  std::ofstream(dir.path / "syntax.json") << "{\"units\": \"mm\",\n \"flow_path\": }";
  expect_failure(test::run_cli("validate " + q(dir.path / "syntax.json"), dir.path), 2,
                 {"syntax.json line 2, column 15: syntax error"});
  fs::create_directories(dir.path / "configs");
  expect_failure(test::run_cli("validate " + q(dir.path / "configs"), dir.path), 2, {"is a directory, not a config file"});
  expect_failure(test::run_cli("validate " + q(dir.path / "none.json"), dir.path), 2, {"none.json does not exist"});
  BOOST_TEST(!fs::exists(dir.path / "out"));
}

// A misspelt subcommand gets a suggestion, not "A subcommand is required".
BOOST_AUTO_TEST_CASE(misspelt_command) {
  TempDir dir("cli_biuld");
  expect_failure(test::run_cli("biuld -o x", dir.path), 1, {"unknown command 'biuld' (did you mean build?)"});
  expect_failure(test::run_cli("valdate x.json", dir.path), 1, {"(did you mean validate?)"});
  const test::Run far = test::run_cli("plot", dir.path);
  expect_failure(far, 1, {"unknown command 'plot'", "commands: build, mesh, validate, example, grid"});
  BOOST_TEST(far.err.find("did you mean") == std::string::npos);
}

// LE/TE detection failure: exit 2 with the section's path and the le_index/te_index remedy (which works).
BOOST_AUTO_TEST_CASE(le_te_detection_failure) {
  TempDir dir("cli_star");
  test::write_star_csv(dir.path / "star.csv");
  json d = c3x_config();
  d["sections"][0]["points"] = {{"file", "star.csv"}};
  std::ofstream(dir.path / "star.json") << d.dump();
  expect_failure(test::run_cli("build " + q(dir.path / "star.json") + " -o " + q(dir.path / "out"), dir.path), 2,
                 {"sections[0].points: LE/TE detection", "\"le_index\" and \"te_index\"", "index 0 is line 2"});
  d["sections"][0]["points"]["le_index"] = 0;
  d["sections"][0]["points"]["te_index"] = 5;
  std::ofstream(dir.path / "star2.json") << d.dump();
  BOOST_TEST(test::run_cli("validate " + q(dir.path / "star2.json"), dir.path).exit_code == 0);
}

// JSON Schema integers: 97.0 is accepted.
BOOST_AUTO_TEST_CASE(integral_floats_are_integers) {
  TempDir dir("cli_int");
  json d = c3x_config();
  d["blade"]["chordwise_samples"] = 97.0;
  std::ofstream(dir.path / "a.json") << d.dump();
  const test::Run r = test::run_cli("validate " + q(dir.path / "a.json"), dir.path);
  BOOST_TEST(r.exit_code == 0, r.err);
  d["blade"]["chordwise_samples"] = 97.5;
  std::ofstream(dir.path / "b.json") << d.dump();
  expect_failure(test::run_cli("validate " + q(dir.path / "b.json"), dir.path), 2,
                 {"blade.chordwise_samples: must be an integer, got number 97.5"});
}

// The output directory never holds files of two runs: a run that writes fewer files removes the
// earlier run's extra ones, and report.json lists exactly the files beside it.
BOOST_AUTO_TEST_CASE(no_stale_outputs) {
  TempDir dir("cli_stale");
  json d = c3x_config();
  d["flow_path"]["span"] = 20.0;
  std::ofstream(dir.path / "a.json") << d.dump();
  const fs::path out = dir.path / "out";
  BOOST_TEST_REQUIRE(test::run_cli("build " + q(dir.path / "a.json") + " -q -o " + q(out), dir.path).exit_code == 0);
  BOOST_TEST(fs::exists(out / "blade.step"));
  std::ofstream(out / "mine.txt") << "a file of the user";
  d["output"]["formats"] = json::array();
  std::ofstream(dir.path / "b.json") << d.dump();
  const test::Run r = test::run_cli("build " + q(dir.path / "b.json") + " -q -o " + q(out), dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(!fs::exists(out / "blade.step"));
  BOOST_TEST(fs::exists(out / "mine.txt"));
  BOOST_TEST((json::parse(read_text(out / "report.json")).at("outputs") == json{"report.json"}));
  // An unknown format is a config error naming the entry, and touches nothing.
  d["output"]["formats"] = {"step", "igs"};
  std::ofstream(dir.path / "c.json") << d.dump();
  expect_failure(test::run_cli("build " + q(dir.path / "c.json") + " -q -o " + q(out), dir.path), 2,
                 {"output.formats[1]: unknown output format \"igs\" (allowed: \"step\", \"iges\""});
  BOOST_TEST(fs::exists(out / "report.json"));
}

// The schema allows spans up to 100 m: a slender blade (3.8 mm chord) at 2 m and at 100 m span passes
// every check (the closed-mesh check used to fail from ~500 chords of span on).
BOOST_AUTO_TEST_CASE(span_range_of_the_schema) {
  TempDir dir("cli_span");
  json d = json::parse(read_text(COOLINGGEN_SOURCE_DIR "/data/examples/hpt_rotor.json"));
  d.erase("cooling");  // a 1 mm wall does not fit the blade scaled to 1/10
  for (auto& s : d["sections"])
    for (const char* k : {"chord", "max_thickness", "le_radius", "te_radius"}) s["parametric"][k] = s["parametric"][k].get<double>() / 10;
  for (const double span : {2000.0, 100000.0}) {
    d["flow_path"] = {{"type", "straight"}, {"span", span}};
    std::ofstream(dir.path / "a.json") << d.dump();
    const test::Run r = test::run_cli("build " + q(dir.path / "a.json") + " -q -o " + q(dir.path / "out"), dir.path);
    BOOST_TEST(r.exit_code == 0, "span " << span << ": " << r.err);
    const json report = json::parse(read_text(dir.path / "out" / "report.json"));
    BOOST_TEST(report.at("checks").at("closed_mesh").at("passed").get<bool>(), report.at("checks").at("closed_mesh").dump());
    BOOST_TEST(std::abs(report.at("solid").at("bbox_mm").at("size").at(2).get<double>() - span) < 1e-6 * span);
  }
}

// report.json's chord is the built one (the rotor's sections are scaled between the LE and TE lines):
// the distance of the reported LE and TE points, not the configured 38 mm.
BOOST_AUTO_TEST_CASE(report_chord_is_built) {
  TempDir dir("cli_chord");
  const test::Run r = test::run_cli("build -q -o " + q(dir.path / "out"), dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  const json report = json::parse(read_text(dir.path / "out" / "report.json"));
  for (const auto& s : report.at("model").at("sections")) {
    const auto le = s.at("leading_edge_mm").get<std::vector<double>>(), te = s.at("trailing_edge_mm").get<std::vector<double>>();
    const double d = std::hypot(le[0] - te[0], le[1] - te[1], le[2] - te[2]);
    BOOST_TEST(std::abs(s.at("chord_mm").get<double>() - d) < 1e-9);
    BOOST_TEST(std::abs(d - 38.0) > 0.5, d);  // fitted between the LE and TE lines, not the input chord
    BOOST_TEST(std::abs(s.at("profile").at("chord_mm").get<double>() - 38.0) < 1e-9);
  }
}
