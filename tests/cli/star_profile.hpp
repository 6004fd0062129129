#pragma once
// A point file no LE/TE detection can handle: a five-pointed star (10 points, radii 10 and 4 mm).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace cg::test {

/// Writes `header` (lines, may be empty) then "x,y" and the 10 star points to `file`.
inline void write_star_csv(const std::filesystem::path& file, const std::string& header = "") {
  std::ofstream out(file);
  out << header << "x,y\n";
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 ? 4 : 10, a = 2 * 3.14159265358979 * k / 10;
    out << r * std::cos(a) << "," << r * std::sin(a) << "\n";
  }
}

}  // namespace cg::test
