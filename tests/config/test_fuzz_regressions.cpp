// Inputs the fuzzers (fuzz/, scripts/run-fuzz.sh) found or that their harnesses' promises call for,
// kept as ordinary tests: tests/fuzz_regressions/config/*.json go through the config reader
// (load_config_file: JSON, fields, the files they name), tests/fuzz_regressions/point_file/* through
// the section point-file reader. Each must give its one-line error naming the field (or file line), not
// a crash, an infinite coordinate or a multi-line message. The same directories seed the fuzzers.
#define BOOST_TEST_MODULE fuzz_regressions
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "brep/temp_files.hpp"
#include "src/blade/section.hpp"
#include "src/config/config.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

const fs::path kDir = fs::path(COOLINGGEN_SOURCE_DIR) / "tests" / "fuzz_regressions";

struct Expected {
  std::string prefix;  // the message starts with this (the field's path)
  std::string detail;  // and contains this
};

// Every config regression input and the error it must give.
const std::map<std::string, Expected>& config_cases() {
  static const std::map<std::string, Expected> cases = {
      // An unknown key with a control character used to print a raw line break inside the message.
      {"key_with_newline.json", {"\\nits: unknown key", "allowed here"}},
      // Finite in inches, infinite in mm: the model got an infinite point.
      {"inch_values_overflow.json", {"sections[0].points.values[1]: must be at most", "in magnitude in this unit"}},
      {"inch_centre_overflow.json", {"sections[0].points.le_centre: must be at most", "finite in mm"}},
      // Passage tables: "inf" became an infinite passage position, "1abc" was read as 1.
      {"passage_table_nan.json", {"cooling.radial_passages.file:", "line 3: x, y and d must be finite numbers"}},
      {"passage_table_trailing_text.json", {"cooling.radial_passages.file:", "got '10', '5', '1abc'"}},
      // Nesting is limited (deeper documents overflowed the stack when copied; see deep_nesting below).
      {"nested_65_levels.json", {"", "nested more than 64 levels deep (in name"}},
  };
  return cases;
}

std::string config_error(const fs::path& file) {
  try {
    config::load_config_file(file);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_config_input_gives_its_one_line_error) {
  int seen = 0;
  for (const auto& e : fs::directory_iterator(kDir / "config")) {
    if (e.path().extension() != ".json") continue;
    ++seen;
    const std::string name = e.path().filename().string();
    const auto it = config_cases().find(name);
    BOOST_TEST_REQUIRE((it != config_cases().end()), name << " has no expected error in this test");
    const std::string msg = config_error(e.path());
    BOOST_TEST(msg.rfind(it->second.prefix, 0) == 0, name << ": expected a message starting with '"
                                                           << it->second.prefix << "', got: " << msg);
    BOOST_TEST(msg.find(it->second.detail) != std::string::npos, name << ": expected '" << it->second.detail
                                                                       << "' in: " << msg);
    BOOST_TEST(msg.find('\n') == std::string::npos, name << ": a multi-line message: " << msg);
  }
  BOOST_TEST(seen == static_cast<int>(config_cases().size()));
}

// A million nested arrays (2 MB of text): refused while parsing, before anything recurses over the
// document (its copy into Config::source overflowed the stack).
BOOST_AUTO_TEST_CASE(deep_nesting_is_refused_not_a_stack_overflow) {
  const std::size_t depth = 1000000;
  const std::string text = "{\"units\": \"mm\", \"sections\": " + std::string(depth, '[') + std::string(depth, ']') + "}";
  std::string msg;
  try {
    config::parse_config_text(text, ".", "deep", "deep.json");
  } catch (const config::ConfigError& e) {
    msg = e.what();
  }
  BOOST_TEST(msg == "deep.json: objects and arrays nested more than 64 levels deep (in sections; the examples nest at "
                    "most 6 levels)");
  // 64 levels are still read (the limit is not off by one): the error is then a field's.
  const std::string ok = "{\"units\": \"mm\", \"name\": " + std::string(63, '[') + std::string(63, ']') + "}";
  try {
    config::parse_config_text(ok, ".", "deep", "deep.json");
  } catch (const config::ConfigError& e) {
    msg = e.what();
  }
  BOOST_TEST(msg.rfind("name: must be a string", 0) == 0, msg);
}

// 1e308 cm is finite in the file and infinite in mm: refused with the file line, read in mm.
BOOST_AUTO_TEST_CASE(point_file_coordinates_must_be_finite_in_mm) {
  const std::string text = test::read_text(kDir / "point_file" / "cm_overflow.dat");
  std::istringstream cm(text);
  std::string msg;
  try {
    blade::parse_section_points(cm, blade::LengthUnit::Centimetre, "cm_overflow.dat");
  } catch (const InvalidGeometry& e) {
    msg = e.what();
  }
  BOOST_TEST(msg == "cm_overflow.dat line 2: x and y must be finite (also in mm), got '1e308,0'");
  std::istringstream mm(text);
  const auto pts = blade::parse_section_points(mm, blade::LengthUnit::Millimetre, "cm_overflow.dat");
  BOOST_TEST_REQUIRE(pts.size() == 4u);
  BOOST_TEST(pts[1].x() == 1e308);
}
