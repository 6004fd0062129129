// libFuzzer harness of the section point-file reader (cg::blade::parse_section_points: CSV with or
// without a header, the "x y" .dat layout, comments, point-number columns), read in every length unit.
// Expected: the points, or cg::InvalidGeometry naming the file and line. A finding is anything else:
// another exception, a crash or sanitizer report, or a result that breaks the reader's promises (at
// least 4 points, all finite in mm, one increasing file line per point).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "src/blade/section.hpp"
#include "src/core/error.hpp"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_point_file: broken promise: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const auto unit : {cg::blade::LengthUnit::Millimetre, cg::blade::LengthUnit::Centimetre,
                          cg::blade::LengthUnit::Metre, cg::blade::LengthUnit::Inch}) {
    std::istringstream in(text);
    std::vector<int> lines;
    try {
      const auto pts = cg::blade::parse_section_points(in, unit, "fuzz.csv", &lines);
      expect(pts.size() >= 4, "at least 4 points");
      expect(lines.size() == pts.size(), "one file line per point");
      for (std::size_t i = 0; i < pts.size(); ++i) {
        expect(std::isfinite(pts[i].x()) && std::isfinite(pts[i].y()), "finite points in mm");
        expect(lines[i] >= 1 && (i == 0 || lines[i] > lines[i - 1]), "increasing file lines from 1");
      }
    } catch (const cg::InvalidGeometry& e) {
      const std::string msg = e.what();
      expect(msg.rfind("fuzz.csv", 0) == 0, "the message names the file");
    }
  }
  return 0;
}
