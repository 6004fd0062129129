// Section point files: CSV (optionally with a header naming the x and y columns) and the "x y" .dat layout.
#include <algorithm>
#include <cctype>
#include <cmath>
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

// A data line: its number in the file and its fields.
struct Row {
  int line;
  std::vector<std::string> fields;
};

// True when column `col` of every row is an integer and the values count up by one (0, 1, 2, ... or
// 1, 2, 3, ...): a point-number column.
bool is_index_column(const std::vector<Row>& rows, std::size_t col) {
  double prev = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    double v = 0;
    if (rows[k].fields.size() <= col || !parse_number(rows[k].fields[col], v) || v != std::floor(v)) return false;
    if (k > 0 && v != prev + 1) return false;
    prev = v;
  }
  return rows.size() >= 2;
}

std::vector<Eigen::Vector2d> parse_section_points(std::istream& in, LengthUnit unit, const std::string& source_name,
                                                  std::vector<int>* source_lines) {
  // Pass 1: a header (the first non-numeric line before any data) and the data rows.
  std::vector<Row> rows;
  int xcol = -1, ycol = -1;  // from a header line, if any
  std::string header;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = split_fields(t);
    double v = 0;
    const bool numeric = !fields.empty() && parse_number(fields[0], v);
    if (!numeric && rows.empty()) {
      // A header (or a .dat name line; a later one before the data replaces it): take the columns whose
      // names start with x and y.
      header = t;
      xcol = ycol = -1;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        const std::string h = lower(fields[k]);
        if (xcol < 0 && !h.empty() && h[0] == 'x') xcol = static_cast<int>(k);
        else if (ycol < 0 && !h.empty() && h[0] == 'y') ycol = static_cast<int>(k);
      }
      if (xcol < 0 || ycol < 0) xcol = ycol = -1;
      continue;
    }
    rows.push_back({lineno, fields});
  }
  // Pass 2: which columns are x and y. Without a header naming them, two numeric columns are x, y;
  // three are (point number, x, y) when the first counts up by one, and ambiguous otherwise (reading
  // them as x, y would build a wrong profile without any error).
  if (xcol < 0 && !rows.empty()) {
    std::size_t columns = rows.front().fields.size();
    for (const Row& r : rows) columns = std::max(columns, r.fields.size());
    const std::string ask = "; name the columns in a header line, e.g. \"x,y\", \"i,x,y\" or \"x,y,z\"";
    if (columns == 2) {
      xcol = 0, ycol = 1;
    } else if (columns == 3 && is_index_column(rows, 0)) {
      xcol = 1, ycol = 2;
    } else if (columns >= 3) {
      require(false, source_name + ": " + std::to_string(columns) + " columns and " +
                         (header.empty() ? std::string("no header") : "no header naming x and y ('" + header + "')") +
                         ", so which are x and y is ambiguous" + ask);
    }
  }
  const double f = millimetres_per(unit);
  std::vector<Eigen::Vector2d> pts;
  std::vector<int> lines;
  for (const Row& r : rows) {
    const int xi = std::max(xcol, 0), yi = std::max(ycol, 1);
    double x = 0, y = 0;
    const bool ok = static_cast<int>(r.fields.size()) > std::max(xi, yi) && parse_number(r.fields[static_cast<std::size_t>(xi)], x) &&
                    parse_number(r.fields[static_cast<std::size_t>(yi)], y);
    std::string text;
    for (const auto& fld : r.fields) text += (text.empty() ? "" : ",") + fld;
    require(ok, source_name + " line " + std::to_string(r.line) + ": expected numbers x and y (columns " +
                    std::to_string(xi + 1) + " and " + std::to_string(yi + 1) + "), got '" + text + "'");
    // Finite in the file's unit is not enough: 1e308 in inches overflows to infinity in mm.
    require(std::isfinite(x * f) && std::isfinite(y * f),
            source_name + " line " + std::to_string(r.line) + ": x and y must be finite (also in mm), got '" + text + "'");
    pts.emplace_back(x * f, y * f);
    lines.push_back(r.line);
  }
  if (pts.size() > 1 && (pts.front() - pts.back()).norm() <= 1e-12 * (1.0 + pts.front().norm())) {
    pts.pop_back();
    lines.pop_back();
  }
  require(pts.size() >= 4, source_name + ": a section needs at least 4 points, got " + std::to_string(pts.size()));
  if (source_lines) *source_lines = std::move(lines);
  return pts;
}

std::vector<Eigen::Vector2d> read_section_points(const std::string& path, LengthUnit unit, std::vector<int>* source_lines) {
  std::ifstream in(path);
  require(static_cast<bool>(in), "section file '" + path + "' cannot be opened");
  return parse_section_points(in, unit, "section file '" + path + "'", source_lines);
}

}  // namespace cg::blade
