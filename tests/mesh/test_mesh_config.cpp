// The mesh section's size_growth: default, value read through to the mesher's options, and out-of-range
// values refused with the field path and the allowed range.
#define BOOST_TEST_MODULE mesh_config
#include <boost/test/unit_test.hpp>

#include <nlohmann/json.hpp>

#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/mesh_job.hpp"

using namespace cg;
using nlohmann::json;

namespace {

config::Config with_mesh(const json& mesh) {
  json doc = json::parse(config::builtin_example_json());
  if (!mesh.is_null()) doc["mesh"] = mesh;
  return config::parse_config(doc, ".", "test");
}

std::string error_of(const json& mesh) {
  try {
    with_mesh(mesh);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(size_growth_default_and_value) {
  BOOST_TEST(pipeline::mesh_options(with_mesh(json()).mesh).size_growth == 0.3);
  BOOST_TEST(pipeline::mesh_options(with_mesh({{"size_growth", 0.5}}).mesh).size_growth == 0.5);
}

BOOST_AUTO_TEST_CASE(size_growth_out_of_range) {
  for (double bad : {0.0, -0.1, 2.5}) {
    const std::string e = error_of({{"size_growth", bad}});
    BOOST_TEST(e.find("mesh.size_growth") != std::string::npos, e);
    BOOST_TEST(e.find("(0, 2]") != std::string::npos, e);
  }
}
