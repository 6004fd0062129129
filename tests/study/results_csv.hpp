#pragma once
// results.csv of a study directory read back for the study tests.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace cg::test {

// results.csv as rows of cells (no quoted commas in the columns read here but the error, which is last
// of the ones compared and compared as a prefix).
inline std::vector<std::map<std::string, std::string>> read_results(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (quoted && l[i] == '"' && i + 1 < l.size() && l[i + 1] == '"') cell += '"', ++i;
      else if (l[i] == '"') quoted = !quoted;
      else if (l[i] == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += l[i];
    }
    cells.push_back(cell);
    return cells;
  };
  while (std::getline(in, line)) {
    const auto cells = split(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    BOOST_TEST_REQUIRE(cells.size() == header.size(), line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

}  // namespace cg::test
