// libFuzzer harness of the config reader: JSON text -> cg::config::parse_config_text, i.e. strict JSON
// (duplicate keys, numbers beyond a double), every field's type, range and unknown keys, the cooling
// and hand-off fields, and the section point files and passage tables the document names (relative
// paths resolved against data/examples, so the examples' files are read). The blade model is not built
// (build_model: seconds per input).
// Expected: a Config, or cg::config::ConfigError with a one-line message. A finding is anything else:
// another exception (std::out_of_range, nlohmann's type_error, cg::InvalidGeometry ...), a crash or a
// sanitizer report, or a Config that breaks the reader's promises (section points finite in mm, one
// point source per section, radial passages finite with a diameter > 0).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>

#include "src/config/config.hpp"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_config: broken promise: %s\n", what);
  std::abort();
}

bool finite(const Eigen::Vector2d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

void check_sections(const cg::config::Config& c) {
  expect(c.point_sources.size() == c.blade.sections.size(), "one point source per section");
  for (const auto& s : c.blade.sections) {
    const auto* p = std::get_if<cg::blade::PointSectionDefinition>(&s.shape);
    if (!p) continue;
    expect(p->points.size() >= 4, "a point section has at least 4 points");
    for (const auto& q : p->points) expect(finite(q), "section points finite in mm");
    expect(std::isfinite(p->le_radius) && std::isfinite(p->te_radius), "edge radii finite in mm");
    expect((!p->le_centre || finite(*p->le_centre)) && (!p->te_centre || finite(*p->te_centre)),
           "edge centres finite in mm");
  }
}

void check_cooling(const cg::config::Config& c) {
  for (const auto& r : c.cooling.passages.radial_passages)
    expect(finite(r.position) && std::isfinite(r.diameter) && r.diameter > 0,
           "radial passages finite, diameter > 0");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const cg::config::Config c =
        cg::config::parse_config_text(text, COOLINGGEN_SOURCE_DIR "/data/examples", "fuzz", "fuzz.json");
    check_sections(c);
    check_cooling(c);
  } catch (const cg::config::ConfigError& e) {
    const std::string msg = e.what();
    expect(!msg.empty() && msg.find('\n') == std::string::npos, "a one-line message");
  }
  return 0;
}
