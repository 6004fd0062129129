#pragma once
// report.html and blade.glb of a product build, read by a real browser and by the Khronos validator
// (acceptance/browser.hpp), compared with counts that do not come from the page: the faces of
// blade.step as OCCT's STEP reader sees them, the example's film-hole count, the face picked.
#include <fstream>

#include "acceptance/browser.hpp"
#include "acceptance/product_build.hpp"
#include "brep/step_read_back.hpp"

namespace cg::test {

/// blade.glb passes the Khronos validator with no error, one primitive per face of blade.step.
inline void check_glb_validates(const ProductBuild& b) {
  const nlohmann::json v = validate_gltf(b.file("blade.glb"));
  BOOST_TEST_MESSAGE("gltf-validator on blade.glb: " << v.dump());
  BOOST_TEST(v.at("errors").get<int>() == 0, v.dump());
  BOOST_TEST(v.at("draw_calls").get<int>() == b.faces);
}

/// The page as a browser shows it: rendered (pixels off the clear colour), every face of blade.step
/// loaded, `holes` rows in the hole table, and a pick at a point of face `pick` (seen from the page's
/// default view) returns that face. A screenshot goes to <build>/tests/screenshots/<shot>.png.
inline void check_report_page(const ProductBuild& b, int faces, int holes, const std::string& pick, const std::string& shot) {
  const StepReadBack step = read_step_back(b.file("blade.step"));
  BOOST_TEST_REQUIRE(step.ok);
  BOOST_TEST(static_cast<int>(step.face_names.size()) == faces, "faces in blade.step (OCCT)");
  const std::string dom = chromium(b.file("report.html"), "#pick=" + pick);
  const auto v = element_attributes(dom, "cg-verdict");
  BOOST_TEST_MESSAGE("report.html verdict: " << dom.substr(dom.find("id=\"cg-verdict\""), 400));
  BOOST_TEST_REQUIRE(v.count("data-state") == 1u, dom.substr(0, 3000));
  BOOST_TEST(v.at("data-state") == "rendered");
  BOOST_TEST(std::stoi(v.at("data-faces")) == faces);
  BOOST_TEST(std::stoi(v.at("data-pixels")) > 0);
  BOOST_TEST(std::stoi(v.at("data-hole-rows")) == holes);
  BOOST_TEST(table_rows(dom, "hole-table") == holes);
  BOOST_TEST(v.count("data-pick") == 1u);
  if (v.count("data-pick")) BOOST_TEST(v.at("data-pick") == pick);
  std::filesystem::create_directories(kScreenshots);
  const std::filesystem::path png = kScreenshots / (shot + ".png");
  std::filesystem::remove(png);
  chromium(b.file("report.html"), "", png);
  BOOST_TEST(std::filesystem::exists(png));
  if (std::filesystem::exists(png)) BOOST_TEST(std::filesystem::file_size(png) > 10000u);
}

/// A copy of the page whose model is cut in half gives the "broken" verdict, not a blank canvas.
inline void check_truncated_model_is_broken(const ProductBuild& b) {
  std::string html = read_text(b.file("report.html"));
  const std::string open = "id=\"cg-model\">";
  const std::size_t start = html.find(open), end = html.find("</script>", start);
  BOOST_TEST_REQUIRE(start != std::string::npos);
  const std::size_t cut = start + open.size() + (end - start - open.size()) / 2;
  html.erase(cut, end - cut);
  TempDir dir("report_broken");
  const std::filesystem::path page = dir.path / "report_truncated.html";
  std::ofstream(page, std::ios::binary) << html;
  const auto v = element_attributes(chromium(page, ""), "cg-verdict");
  BOOST_TEST(v.count("data-state") == 1u);
  if (v.count("data-state")) BOOST_TEST(v.at("data-state") == "broken");
}

}  // namespace cg::test
