#pragma once
// A real browser and the Khronos glTF validator as readers of the HTML reports and blade.glb:
// headless Chromium (Debian `chromium`, WebGL through SwiftShader) opens a page the CLI wrote and
// dumps the DOM after the page's scripts ran (the page writes its verdict there: #cg-verdict), or takes
// a screenshot; node runs tests/tools/validate_gltf.js (npm gltf-validator, installed by
// scripts/install-deps.sh into tests/tools/node_modules).
//
// Outside CI a missing Chromium, node or validator skips the browser tests with a line saying which
// (browser_tools precondition); with CI=true in the environment (.ci/run) the tests run and fail.
// Screenshots go to <build>/tests/screenshots/.
#include <boost/test/unit_test.hpp>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include "brep/temp_files.hpp"

namespace cg::test {

inline const std::filesystem::path kTestTools = std::filesystem::path(COOLINGGEN_SOURCE_DIR) / "tests/tools";
inline const std::filesystem::path kScreenshots = std::filesystem::path(COOLINGGEN_BINARY_DIR) / "tests/screenshots";

inline bool on_path(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

/// What the browser tests lack ("" when nothing).
inline std::string missing_browser_tools() {
  std::string missing;
  if (!on_path("chromium")) missing += " chromium (Debian package chromium)";
  if (!on_path("node")) missing += " node (Debian package nodejs)";
  if (!std::filesystem::exists(kTestTools / "node_modules/gltf-validator"))
    missing += " gltf-validator (cd tests/tools && npm ci)";
  return missing;
}

/// Boost.Test precondition: skip with a clear line outside CI when a tool is missing; under CI=true run
/// (and fail on the missing tool).
struct BrowserTools {
  boost::test_tools::assertion_result operator()(boost::unit_test::test_unit_id) const {
    const std::string missing = missing_browser_tools();
    const char* ci = std::getenv("CI");
    if (missing.empty() || (ci && std::string(ci) == "true")) return true;
    boost::test_tools::assertion_result r(false);
    r.message() << "browser test skipped, missing:" << missing << " (under CI=true this fails)";
    return r;
  }
};

/// Runs a shell command with stdout to `out`; returns the exit code.
inline int run_to(const std::string& command, const std::filesystem::path& out) {
  const int status = std::system((command + " > '" + out.string() + "' 2> '" + out.string() + ".err'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Headless Chromium on a local file: with `screenshot` empty the DOM after the scripts ran (virtual
/// time lets the page load its model), else a screenshot written there. `fragment`: "#..." or "".
inline std::string chromium(const std::filesystem::path& page, const std::string& fragment,
                            const std::filesystem::path& screenshot = {}) {
  const std::string missing = missing_browser_tools();
  BOOST_TEST_REQUIRE(missing.empty(), "missing:" << missing);
  TempDir profile("chromium_profile");
  const std::string url = "file://" + std::filesystem::absolute(page).string() + fragment;
  const std::string action = screenshot.empty() ? "--dump-dom" : "--screenshot='" + screenshot.string() + "'";
  const std::string command =
      "chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
      "--disable-background-networking --disable-component-update --no-first-run "
      "--user-data-dir='" + profile.path.string() + "/p' --window-size=1200,1000 --virtual-time-budget=15000 " +
      action + " '" + url + "'";
  const std::filesystem::path out = profile.path / "dom.html";
  const int rc = run_to(command, out);
  BOOST_TEST(rc == 0, "chromium exit " << rc << ": " << read_text(out.string() + ".err").substr(0, 2000));
  return read_text(out);
}

/// The attributes of the element with id `id` in a DOM dump (name -> value, entities as written).
inline std::map<std::string, std::string> element_attributes(const std::string& dom, const std::string& id) {
  std::map<std::string, std::string> a;
  const std::size_t at = dom.find("id=\"" + id + "\"");
  if (at == std::string::npos) return a;
  const std::size_t open = dom.rfind('<', at), close = dom.find('>', at);
  const std::string tag = dom.substr(open, close - open);
  for (std::size_t i = tag.find(' '); i != std::string::npos && i < tag.size();) {
    const std::size_t eq = tag.find("=\"", i);
    if (eq == std::string::npos) break;
    const std::size_t end = tag.find('"', eq + 2);
    std::string name = tag.substr(i + 1, eq - i - 1);
    name.erase(0, name.find_first_not_of(' '));
    a[name] = tag.substr(eq + 2, end - eq - 2);
    i = end + 1;
  }
  return a;
}

/// Rows of the table with id `id` in a DOM dump (<tr> in its <tbody>).
inline int table_rows(const std::string& dom, const std::string& id) {
  const std::size_t at = dom.find("<table id=\"" + id + "\"");
  if (at == std::string::npos) return -1;
  const std::size_t body = dom.find("<tbody>", at), end = dom.find("</tbody>", at);
  int n = 0;
  for (std::size_t i = dom.find("<tr", body); i != std::string::npos && i < end; i = dom.find("<tr", i + 1)) ++n;
  return n;
}

/// The Khronos validator's verdict on a .glb: {"errors", "warnings", "infos", "draw_calls" (one per primitive), "triangles",
/// "materials", "first": [messages]}.
inline nlohmann::json validate_gltf(const std::filesystem::path& glb) {
  TempDir dir("gltf_validator");
  const std::filesystem::path out = dir.path / "report.json";
  const int rc = run_to("node '" + (kTestTools / "validate_gltf.js").string() + "' '" + glb.string() + "'", out);
  BOOST_TEST_REQUIRE(rc == 0, "gltf-validator: " << read_text(out.string() + ".err"));
  return nlohmann::json::parse(read_text(out));
}

}  // namespace cg::test
