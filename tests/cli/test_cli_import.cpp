// blade.import (geomTurbo): round trips of our own blades (built-in rotor, C3X vane as a linear
// cascade) through the geomTurbo writer and back, with the deviation measured at points BETWEEN the
// exported sections; hostile files written here, each refused by `coolinggen validate` with one line
// naming the file, the section and a line, exit 2.
#define BOOST_TEST_MODULE cli_import
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli/run_cli.hpp"
#include "cli/section_tables.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/blade_import/geomturbo_reader.hpp"
#include "src/blade_import/geomturbo_writer.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/report.hpp"

using namespace cg;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct RoundTrip {
  double max_between = 0;   // original wall at spans half-way between exported sections -> imported wall
  double max_record = 0;    // the import's own fidelity figure (report.json import.deviation.max_mm)
  double import_s = 0, parametric_s = 0;
};

// How the exported blade comes back: as the geomTurbo file, or as one 3D section table per exported
// section (written here from the file's points: the outline once around, starting mid pressure side,
// in metres and x r theta for annular rows, mm and x y z for cascades).
enum class Via { GeomTurbo, Tables };

// Exports `c`'s blade, imports it again, measures both ways.
RoundTrip round_trip(const config::Config& c, const std::string& tag, Via via = Via::GeomTurbo) {
  RoundTrip r;
  auto t0 = std::chrono::steady_clock::now();
  const blade::BladeModel original = config::build_model(c);
  r.parametric_s = seconds_since(t0);
  test::TempDir dir("import_" + tag);
  const auto file = dir.path / "blade.geomTurbo";
  blade_import::GeomTurboWriteOptions wo;
  blade_import::write_geomturbo_file(file.string(), original, wo);
  const nlohmann::json doc = via == Via::Tables ? test::tables_import(file, dir.path, c.source.at("flow_path"))
                            : nlohmann::json{{"units", "mm"}, {"blade", {{"import", {{"format", "geomturbo"}, {"file", file.string()}}}}}};
  t0 = std::chrono::steady_clock::now();
  const config::Config ci = config::parse_config(doc, dir.path, tag);
  const blade::BladeModel imported = config::build_model(ci);
  r.import_s = seconds_since(t0);
  BOOST_TEST_REQUIRE(imported.imported.has_value());
  r.max_record = imported.imported->overall.max;
  // Independent of the import's own figures: points of the ORIGINAL wall half-way between the exported
  // sections (and between its chordwise points), projected onto the imported wall.
  SurfaceProjector proj(imported.surface);
  const double ob = original.options.overbuild;
  for (int k = 0; k + 1 < wo.sections; ++k) {
    const double v = -ob + (1 + 2 * ob) * (k + 0.5) / (wo.sections - 1);
    if (v < 0.002 || v > 0.998) continue;  // the imported wall ends at hub and casing
    for (int i = 0; i < 97; ++i) {
      const double u = (i + 0.37) / 97;
      r.max_between = std::max(r.max_between, proj.project(original.surface.point(u, v)).distance);
    }
  }
  return r;
}

// Prints the figures of a round trip and checks both deviations against the 0.01 mm limit.
void expect_close(const RoundTrip& r, const std::string& what) {
  BOOST_TEST_MESSAGE(what << " round trip: between sections " << r.max_between << " mm, record " << r.max_record
                          << " mm; import " << r.import_s << " s / parametric " << r.parametric_s << " s = "
                          << r.import_s / r.parametric_s);
  BOOST_TEST(r.max_between <= 0.01, what);
  BOOST_TEST(r.max_record <= 0.01, what);
}

}  // namespace

BOOST_AUTO_TEST_CASE(round_trip_builtin_rotor_zrth) {
  expect_close(round_trip(config::builtin_example_config(), "builtin"), "built-in rotor geomTurbo");
}

BOOST_AUTO_TEST_CASE(round_trip_c3x_cascade_xyz) {
  const config::Config c = config::load_config_file(std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples/c3x_vane.json");
  expect_close(round_trip(c, "c3x"), "C3X cascade geomTurbo");
}

BOOST_AUTO_TEST_CASE(round_trip_builtin_rotor_section_tables_xrtheta) {
  expect_close(round_trip(config::builtin_example_config(), "builtin_tables", Via::Tables), "built-in rotor section-table");
}

BOOST_AUTO_TEST_CASE(round_trip_c3x_section_tables_xyz) {
  const config::Config c = config::load_config_file(std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "data/examples/c3x_vane.json");
  expect_close(round_trip(c, "c3x_tables", Via::Tables), "C3X section-table");
}

// ---- hostile input -------------------------------------------------------------------------------

namespace {

// A small valid cascade: 3 sections (z = -2, 10, 22 mm; hub 0, casing 20), an ellipse-like profile of
// 9 points per side. Each hostile case edits the text of one side's points.
struct Profile {
  std::vector<std::array<double, 3>> suction, pressure;  // geomTurbo XYZ: X span, Y pitch, Z axial
};

Profile profile(double span_x) {
  Profile p;
  const int n = 9;
  for (int i = 0; i < n; ++i) {
    const double t = M_PI * i / (n - 1);
    const double a = 20 * (1 - std::cos(t)) / 2;          // axial 0..20
    const double h = 3 * std::sin(t) + 0.3 * (a / 20);    // thickness, blunt-ish
    p.suction.push_back({span_x, h, a});
    p.pressure.push_back({span_x, -0.6 * h, a});
  }
  p.pressure.front() = p.suction.front();
  p.pressure.back() = p.suction.back();
  return p;
}

std::string file_text(const std::vector<Profile>& secs) {
  std::ostringstream o;
  o << "GEOMETRY TURBO\nVERSION 5.5\nUNITS Millimeters\nUNITS-FACTOR 1\ncascade yes\nNI_BEGIN CHANNEL\n";
  for (const char* name : {"hub", "shroud"}) {
    o << "NI_BEGIN basic_curve\nNAME " << name << "\nNI_BEGIN zrcurve\nZR\n2\n-20 " << (name[0] == 'h' ? 0 : 20)
      << "\n40 " << (name[0] == 'h' ? 0 : 20) << "\nNI_END zrcurve\nNI_END basic_curve\n";
  }
  o << "NI_END CHANNEL\nNI_BEGIN nibladegeometry\nnumber_of_blades 30\n";
  for (int side = 0; side < 2; ++side) {
    o << (side == 0 ? "suction" : "pressure") << "\nSECTIONAL\n" << secs.size() << "\n";
    for (const Profile& p : secs) {
      const auto& pts = side == 0 ? p.suction : p.pressure;
      o << "XYZ\n" << pts.size() << "\n";
      for (const auto& q : pts) o << q[0] << " " << q[1] << " " << q[2] << "\n";
    }
  }
  o << "NI_END nibladegeometry\n";
  return o.str();
}

// `coolinggen validate` on a config importing `text`: exit code and stderr.
test::Run validate(const std::string& text, const std::string& tag) {
  static test::TempDir dir("import_hostile");
  const auto file = dir.path / (tag + ".geomTurbo");
  std::ofstream(file) << text;
  const auto cfg = dir.path / (tag + ".json");
  std::ofstream(cfg) << R"({"units": "mm", "blade": {"import": {"format": "geomturbo", "file": ")" << file.filename().string() << "\"}}}";
  return test::run_cli("validate " + test::q(cfg), dir.path);
}

void expect_refused(const test::Run& r, const std::string& tag, const std::string& words) {
  BOOST_TEST(r.exit_code == 2, tag << ": exit " << r.exit_code << " " << r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, tag << ": " << r.err);
  BOOST_TEST(r.err.find("blade.import") != std::string::npos, tag << ": " << r.err);
  BOOST_TEST(r.err.find(tag + ".geomTurbo:") != std::string::npos, tag << ": names the file and line: " << r.err);
  BOOST_TEST(r.err.find(words) != std::string::npos, tag << ": " << r.err);
}

std::vector<Profile> valid() { return {profile(-2), profile(10), profile(22)}; }

}  // namespace

BOOST_AUTO_TEST_CASE(valid_small_cascade_validates) {
  const test::Run r = validate(file_text(valid()), "valid");
  BOOST_TEST(r.exit_code == 0, r.err);
}

BOOST_AUTO_TEST_CASE(open_section) {
  auto s = valid();
  s[1].pressure.back()[1] += 0.5;  // the pressure side misses the TE
  expect_refused(validate(file_text(s), "open"), "open", "section 2: open section");
}

BOOST_AUTO_TEST_CASE(duplicated_point) {
  auto s = valid();
  s[0].suction.insert(s[0].suction.begin() + 4, s[0].suction[4]);
  expect_refused(validate(file_text(s), "duplicated"), "duplicated", "section 1: duplicated point");
}

BOOST_AUTO_TEST_CASE(unordered_points) {
  auto s = valid();
  std::swap(s[2].pressure[3], s[2].pressure[4]);
  expect_refused(validate(file_text(s), "unordered"), "unordered", "section 3: points out of order");
}

BOOST_AUTO_TEST_CASE(crossing_outline) {
  auto s = valid();
  s[1].pressure[4][1] = 5;  // the pressure side's middle point beyond the suction side
  expect_refused(validate(file_text(s), "crossing"), "crossing", "section 2: the outline crosses itself");
}

BOOST_AUTO_TEST_CASE(sections_not_reaching_the_hub) {
  auto s = valid();
  s[0] = profile(3);  // the lowest section starts 3 mm above the hub
  expect_refused(validate(file_text(s), "short"), "short", "section 1 does not reach the hub");
}

BOOST_AUTO_TEST_CASE(point_line_not_three_numbers) {
  std::string t = file_text(valid());
  t.replace(t.find("\n-2 "), 4, "\n-2 x");
  expect_refused(validate(t, "garbled"), "garbled", "expected");
}

// The config reader reads the file (syntax) only; its geometry is checked where the blade model is
// built (build_model, which `coolinggen validate` runs), naming the same field.
BOOST_AUTO_TEST_CASE(geometry_checked_by_the_model_build_not_the_reader) {
  auto s = valid();
  s[0] = profile(3);
  test::TempDir dir("import_stage");
  std::ofstream(dir.path / "short.geomTurbo") << file_text(s);
  const nlohmann::json doc = {{"units", "mm"}, {"blade", {{"import", {{"format", "geomturbo"}, {"file", "short.geomTurbo"}}}}}};
  const config::Config c = config::parse_config(doc, dir.path, "short");  // no cut, no geometry check
  BOOST_TEST(config::section_count(c) == 11u);
  try {
    config::build_model(c);
    BOOST_ERROR("build_model accepted a blade that does not reach the hub");
  } catch (const config::ConfigError& e) {
    const std::string what = e.what();
    BOOST_TEST(what.rfind("blade.import.file: ", 0) == 0, what);
    BOOST_TEST(what.find("does not reach the hub") != std::string::npos, what);
  }
}

// ---- hostile section tables (format "sections", a straight flow path of span 20 mm) ----------------

namespace {

// One table per profile: the outline once around (suction LE -> TE, pressure back), x y z in mm.
std::vector<std::vector<std::array<double, 3>>> tables_of(const std::vector<Profile>& secs) {
  std::vector<std::vector<std::array<double, 3>>> out;
  for (const Profile& p : secs) {
    std::vector<std::array<double, 3>> t;
    for (const auto& q : p.suction) t.push_back({q[2], q[1], q[0]});
    for (std::size_t i = p.pressure.size() - 2; i >= 1; --i) t.push_back({p.pressure[i][2], p.pressure[i][1], p.pressure[i][0]});
    out.push_back(t);
  }
  return out;
}

test::Run validate_tables(const std::vector<std::vector<std::array<double, 3>>>& tables, const std::string& tag,
                          bool with_flow_path = true) {
  static test::TempDir dir("import_tables");
  nlohmann::json files = nlohmann::json::array();
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const std::string name = tag + "_" + std::to_string(k) + ".txt";
    std::ofstream out(dir.path / name);
    out << "x y z\n";
    for (const auto& p : tables[k]) out << p[0] << " " << p[1] << " " << p[2] << "\n";
    files.push_back(name);
  }
  nlohmann::json doc = {{"units", "mm"}, {"blade", {{"import", {{"format", "sections"}, {"files", files}, {"frame", "xyz"}}}}}};
  if (with_flow_path) doc["flow_path"] = {{"type", "straight"}, {"span", 20}};
  const auto cfg = dir.path / (tag + ".json");
  std::ofstream(cfg) << doc.dump();
  return test::run_cli("validate " + test::q(cfg), dir.path);
}

void expect_table_refused(const test::Run& r, const std::string& tag, const std::string& file, const std::string& words) {
  BOOST_TEST(r.exit_code == 2, tag << ": exit " << r.exit_code << " " << r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, tag << ": " << r.err);
  BOOST_TEST(r.err.find("blade.import.files") != std::string::npos, tag << ": " << r.err);
  BOOST_TEST(r.err.find(file + ":") != std::string::npos, tag << ": names the file and line: " << r.err);
  BOOST_TEST(r.err.find(words) != std::string::npos, tag << ": " << r.err);
}

}  // namespace

BOOST_AUTO_TEST_CASE(tables_valid_small_cascade_validates) {
  const test::Run r = validate_tables(tables_of(valid()), "tvalid");
  BOOST_TEST(r.exit_code == 0, r.err);
}

BOOST_AUTO_TEST_CASE(tables_need_a_flow_path) {
  const test::Run r = validate_tables(tables_of(valid()), "tnoflow", false);
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(r.err.find("error: flow_path: is required with blade.import format \"sections\"") != std::string::npos, r.err);
}

BOOST_AUTO_TEST_CASE(tables_hostile) {
  auto t = tables_of(valid());
  auto open = t;
  open[1].resize(9);  // the suction side only
  expect_table_refused(validate_tables(open, "topen"), "open", "topen_1.txt", "section 2: open section");
  auto dup = t;
  dup[0].insert(dup[0].begin() + 3, dup[0][3]);
  expect_table_refused(validate_tables(dup, "tdup"), "duplicated", "tdup_0.txt", "section 1: duplicated point");
  auto unordered = t;
  std::swap(unordered[2][12], unordered[2][13]);
  expect_table_refused(validate_tables(unordered, "tunord"), "unordered", "tunord_2.txt", "section 3: points out of order");
  auto crossing = t;
  crossing[1][12][1] = 5;  // a pressure-side point beyond the suction side
  expect_table_refused(validate_tables(crossing, "tcross"), "crossing", "tcross_1.txt", "section 2: the outline crosses itself");
  auto short_hub = t;
  short_hub[0] = tables_of({profile(3)})[0];
  expect_table_refused(validate_tables(short_hub, "tshort"), "short", "tshort_0.txt", "section 1 does not reach the hub");
  const test::Run r = [&] {
    static test::TempDir dir("import_tables_garbled");
    std::ofstream(dir.path / "g.txt") << "x y z\n1 2 3\n1 2 x\n";
    const auto cfg = dir.path / "g.json";
    std::ofstream(cfg) << R"({"units": "mm", "flow_path": {"type": "straight", "span": 20}, "blade": {"import":
      {"format": "sections", "files": ["g.txt", "g.txt"], "frame": "xyz"}}})";
    return test::run_cli("validate " + test::q(cfg), dir.path);
  }();
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(r.err.find("error: blade.import.files[0]: ") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("g.txt:3: expected three numbers (x y z)") != std::string::npos, r.err);
}

// Every table's bytes enter the input hash (a study's stage cache must not reuse a blade from an older table).
BOOST_AUTO_TEST_CASE(tables_bytes_enter_the_input_hash) {
  test::TempDir dir("import_tables_hash");
  const auto t = tables_of(valid());
  nlohmann::json files = nlohmann::json::array();
  auto write = [&](double last_y) {
    for (std::size_t k = 0; k < t.size(); ++k) {
      std::ofstream out(dir.path / ("h" + std::to_string(k) + ".txt"));
      for (std::size_t i = 0; i < t[k].size(); ++i)
        out << t[k][i][0] << " " << (k == 2 && i == 5 ? last_y : t[k][i][1]) << " " << t[k][i][2] << "\n";
    }
  };
  for (std::size_t k = 0; k < t.size(); ++k) files.push_back("h" + std::to_string(k) + ".txt");
  const nlohmann::json doc = {{"units", "mm"}, {"flow_path", {{"type", "straight"}, {"span", 20}}},
                              {"blade", {{"import", {{"format", "sections"}, {"files", files}, {"frame", "xyz"}}}}}};
  write(t[2][5][1]);
  const std::string before = pipeline::input_hash(config::parse_config(doc, dir.path, "h"));
  write(t[2][5][1] + 0.001);
  const std::string after = pipeline::input_hash(config::parse_config(doc, dir.path, "h"));
  BOOST_TEST(before != after);
}
