#include "src/study/design.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "src/config/json_fields.hpp"
#include "src/core/format.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::size_t kMaxVariants = 100000;

// Uniform in [0, 1) from the top 53 bits (exact on every platform).
double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

// Uniform in [0, n) without modulo bias (rejection).
std::size_t below(std::mt19937_64& g, std::size_t n) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
  std::uint64_t x;
  do x = g();
  while (x >= limit);
  return static_cast<std::size_t>(x % n);
}

double min_distance(const std::vector<std::vector<double>>& pts) {
  double best = HUGE_VAL;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      double d = 0;
      for (std::size_t k = 0; k < pts[i].size(); ++k) d += (pts[i][k] - pts[j][k]) * (pts[i][k] - pts[j][k]);
      best = std::min(best, d);
    }
  return best;
}

json rounded(const Parameter& p, double x) { return p.integer ? json(static_cast<long long>(std::llround(x))) : json(x); }

// Grid levels of one parameter.
std::vector<json> levels(const Parameter& p, int design_levels) {
  if (!p.values.empty()) return p.values;
  const int n = p.levels > 0 ? p.levels : design_levels;
  std::vector<json> out;
  for (int i = 0; i < n; ++i) out.push_back(rounded(p, p.range->first + (p.range->second - p.range->first) * i / (n - 1)));
  return out;
}

// A value of one parameter at u in [0, 1): in its range, or one of its values.
json at_unit(const Parameter& p, double u) {
  if (p.range) return rounded(p, p.range->first + u * (p.range->second - p.range->first));
  return p.values[std::min(p.values.size() - 1, static_cast<std::size_t>(u * static_cast<double>(p.values.size())))];
}

std::vector<std::vector<json>> grid(const Study& s) {
  std::vector<std::vector<json>> axes;
  std::size_t total = 1;
  for (const Parameter& p : s.parameters) {
    axes.push_back(levels(p, s.design.levels));
    total *= axes.back().size();
    if (total > kMaxVariants)
      config::fail("design", "the grid has more than " + std::to_string(kMaxVariants) + " variants; use fewer levels or a latin_hypercube");
  }
  std::vector<std::vector<json>> rows(total);
  for (std::size_t r = 0; r < total; ++r) {
    std::size_t rest = r;
    rows[r].resize(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {  // the last parameter varies fastest
      rows[r][k] = axes[k][rest % axes[k].size()];
      rest /= axes[k].size();
    }
  }
  return rows;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;
      else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  cells.push_back(cell);
  for (std::string& x : cells) {
    const auto a = x.find_first_not_of(" \t"), b = x.find_last_not_of(" \t");
    x = a == std::string::npos ? "" : x.substr(a, b - a + 1);
  }
  return cells;
}

// A cell: a number when the whole cell is one, else the text (for "set" of a string field).
json cell_value(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  try {
    std::size_t used = 0;
    const double x = std::stod(text, &used);
    if (used == text.size() && std::isfinite(x)) return x;
  } catch (const std::exception&) {
  }
  return text;
}

std::vector<std::vector<json>> csv_rows(const Study& s) {
  const std::string field = "design.file";
  std::ifstream in(s.design.csv_file);
  if (!in) config::fail(field, "cannot read " + s.design.csv_file.string());
  const std::string where = s.design.csv_file.filename().string();
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") != std::string::npos && line[line.find_first_not_of(" \t")] != '#') header = split_csv_line(line);
  }
  if (header.empty()) config::fail(field, where + " has no header line (the parameter names)");
  std::vector<int> column(s.parameters.size(), -1);
  for (std::size_t c = 0; c < header.size(); ++c) {
    bool known = false;
    for (std::size_t k = 0; k < s.parameters.size(); ++k)
      if (s.parameters[k].name == header[c]) column[k] = static_cast<int>(c), known = true;
    if (!known) config::fail(field, where + " line " + std::to_string(line_no) + ": column '" + header[c] + "' is not a parameter name of the study");
  }
  for (std::size_t k = 0; k < s.parameters.size(); ++k)
    if (column[k] < 0) config::fail(field, where + ": no column '" + s.parameters[k].name + "' (" + s.parameters[k].field + ")");
  std::vector<std::vector<json>> rows;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (cells.size() != header.size())
      config::fail(field, where + " line " + std::to_string(line_no) + ": " + std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size()));
    std::vector<json> row;
    for (std::size_t k = 0; k < s.parameters.size(); ++k) {
      const json v = cell_value(cells[column[k]]);
      if (s.parameters[k].mode == ApplyMode::kOffset && !v.is_number())
        config::fail(field, where + " line " + std::to_string(line_no) + ", column '" + s.parameters[k].name + "': an offset must be a number, got '" + cells[column[k]] + "'");
      row.push_back(v);
    }
    rows.push_back(row);
    if (rows.size() > kMaxVariants) config::fail(field, where + " has more than " + std::to_string(kMaxVariants) + " rows");
  }
  if (rows.empty()) config::fail(field, where + " has no rows after the header");
  return rows;
}

}  // namespace

std::vector<std::vector<double>> latin_hypercube(int samples, int dims, std::uint64_t seed, int candidates) {
  std::mt19937_64 g(seed);
  std::vector<std::vector<double>> best;
  double best_d = -1;
  const std::size_t n = static_cast<std::size_t>(samples);
  for (int c = 0; c < candidates; ++c) {
    std::vector<std::vector<double>> pts(n, std::vector<double>(static_cast<std::size_t>(dims)));
    for (int k = 0; k < dims; ++k) {
      std::vector<std::size_t> strata(n);
      for (std::size_t i = 0; i < n; ++i) strata[i] = i;
      for (std::size_t i = n; i-- > 1;) std::swap(strata[i], strata[below(g, i + 1)]);  // Fisher-Yates
      for (std::size_t i = 0; i < n; ++i) pts[i][k] = (static_cast<double>(strata[i]) + unit(g)) / static_cast<double>(n);
    }
    const double d = min_distance(pts);
    if (d > best_d) best_d = d, best = std::move(pts);
  }
  return best;
}

std::vector<Variant> expand_design(const Study& s) {
  std::vector<std::vector<json>> rows;
  switch (s.design.kind) {
    case DesignKind::kGrid: rows = grid(s); break;
    case DesignKind::kCsv: rows = csv_rows(s); break;
    case DesignKind::kLatinHypercube:
      for (const auto& u : latin_hypercube(s.design.samples, static_cast<int>(s.parameters.size()), s.design.seed, s.design.candidates)) {
        std::vector<json> row;
        for (std::size_t k = 0; k < u.size(); ++k) row.push_back(at_unit(s.parameters[k], u[k]));
        rows.push_back(row);
      }
      break;
  }
  const std::size_t width = std::max<std::size_t>(3, std::to_string(rows.size() - 1).size());
  std::vector<Variant> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::string id = std::to_string(i);
    id.insert(0, width - id.size(), '0');
    out.push_back({i, id, rows[i]});
  }
  return out;
}

}  // namespace cg::study
