// Section point files: CSV (optionally with a header naming the x and y columns) and the "x y" .dat layout.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "src/blade/section.hpp"
#include "src/core/error.hpp"

namespace cg::blade {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Fields separated by commas, semicolons or whitespace.
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  const bool has_delim = line.find_first_of(",;") != std::string::npos;
  for (char ch : line) {
    const bool sep = has_delim ? (ch == ',' || ch == ';') : (ch == ' ' || ch == '\t');
    if (sep) {
      if (has_delim || !cur.empty()) out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (has_delim || !trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

bool parse_number(const std::string& s, double& v) {
  if (s.empty()) return false;
  std::istringstream in(s);
  in >> v;
  return !in.fail() && (in >> std::ws).eof();
}

}  // namespace

double millimetres_per(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre: return 1.0;
    case LengthUnit::Centimetre: return 10.0;
    case LengthUnit::Metre: return 1000.0;
    case LengthUnit::Inch: return 25.4;
  }
  return 1.0;
}

LengthUnit parse_length_unit(const std::string& name) {
  const std::string n = lower(trim(name));
  if (n == "mm") return LengthUnit::Millimetre;
  if (n == "cm") return LengthUnit::Centimetre;
  if (n == "m") return LengthUnit::Metre;
  if (n == "in" || n == "inch") return LengthUnit::Inch;
  throw InvalidGeometry("length unit '" + name + "' is not supported; allowed: mm, cm, m, in");
}

std::vector<Eigen::Vector2d> parse_section_points(std::istream& in, LengthUnit unit, const std::string& source_name) {
  const double f = millimetres_per(unit);
  std::vector<Eigen::Vector2d> pts;
  int xcol = -1, ycol = -1;  // from a header line, if any
  std::string line;
  int lineno = 0;
  bool seen_data = false;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = split_fields(t);
    const int xi = xcol >= 0 ? xcol : 0, yi = ycol >= 0 ? ycol : 1;
    double x = 0, y = 0;
    const bool numeric = static_cast<int>(fields.size()) > std::max(xi, yi) &&
                         parse_number(fields[static_cast<std::size_t>(xi)], x) &&
                         parse_number(fields[static_cast<std::size_t>(yi)], y);
    if (!numeric) {
      require(!seen_data, source_name + " line " + std::to_string(lineno) + ": expected numbers x and y, got '" + t + "'");
      // A header (or a .dat name line): take the columns whose names start with x and y.
      xcol = ycol = -1;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        const std::string h = lower(fields[k]);
        if (xcol < 0 && !h.empty() && h[0] == 'x') xcol = static_cast<int>(k);
        else if (ycol < 0 && !h.empty() && h[0] == 'y') ycol = static_cast<int>(k);
      }
      if (xcol < 0 || ycol < 0) xcol = ycol = -1;
      continue;
    }
    seen_data = true;
    pts.emplace_back(x * f, y * f);
  }
  if (pts.size() > 1 && (pts.front() - pts.back()).norm() <= 1e-12 * (1.0 + pts.front().norm())) pts.pop_back();
  require(pts.size() >= 4, source_name + ": a section needs at least 4 points, got " + std::to_string(pts.size()));
  return pts;
}

std::vector<Eigen::Vector2d> read_section_points(const std::string& path, LengthUnit unit) {
  std::ifstream in(path);
  require(static_cast<bool>(in), "section file '" + path + "' cannot be opened");
  return parse_section_points(in, unit, "section file '" + path + "'");
}

}  // namespace cg::blade
