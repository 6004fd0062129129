#include "src/blade_import/section_table_reader.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade_import {
namespace {

// The numbers of a line whose fields are separated by whitespace, ',' or ';'; false at the first field
// that is not a number.
bool numbers_of(const std::string& line, std::vector<double>& out) {
  out.clear();
  const char* p = line.c_str();
  while (true) {
    while (*p == ' ' || *p == '\t' || *p == ',' || *p == ';' || *p == '\r') ++p;
    if (*p == '\0') return true;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || (*end != '\0' && std::string(" \t,;\r").find(*end) == std::string::npos)) return false;
    out.push_back(v);
    p = end;
  }
}

}  // namespace

SectionTable parse_section_table(std::istream& in, const std::string& name, TableFrame frame, double k) {
  SectionTable t;
  t.file = name;
  const char* columns = frame == TableFrame::Xyz ? "x y z" : "x r theta_deg";
  auto fail = [&](int line, const std::string& what) { throw InvalidGeometry(name + ":" + std::to_string(line) + ": " + what); };
  std::string line;
  std::vector<double> v;
  bool header_allowed = true;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const bool numbers = numbers_of(line, v);
    if (!numbers && header_allowed) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (!numbers || v.size() != 3)
      fail(n, std::string("expected three numbers (") + columns + "), got \"" + line.substr(first, 60) + "\"");
    for (double& x : v)
      if (!std::isfinite(x) || !std::isfinite(x * k)) fail(n, "a coordinate is not finite in mm");
    Eigen::Vector3d p(k * v[0], k * v[1], k * v[2]);
    if (frame == TableFrame::XRTheta) {
      if (v[1] <= 0) fail(n, "the radius r must be > 0, got " + format_number(v[1]));
      const double th = v[2] * kPi / 180;
      p = Eigen::Vector3d(k * v[0], k * v[1] * std::cos(th), k * v[1] * std::sin(th));
    }
    t.points.push_back(p);
    t.lines.push_back(n);
  }
  if (t.points.size() >= 2 && (t.points.back() - t.points.front()).norm() < 1e-9) {
    t.points.pop_back();
    t.lines.pop_back();
  }
  if (t.points.size() < 8)
    throw InvalidGeometry(name + ": " + std::to_string(t.points.size()) + " points; a section table needs >= 8 (" +
                          columns + ", one point per line around the outline)");
  return t;
}

SectionTable read_section_table(const std::string& path, TableFrame frame, double mm_per_unit) {
  std::ifstream in(path);
  if (!in) throw InvalidGeometry(path + ": cannot be read (missing or not a file?)");
  return parse_section_table(in, path, frame, mm_per_unit);
}

}  // namespace cg::blade_import
