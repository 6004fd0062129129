#include "src/cli/suggest.hpp"

#include <algorithm>

namespace cg::cli {

int edit_distance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

std::string closest_name(const std::string& word, const std::vector<std::string>& names) {
  std::string best;
  int best_d = 3;
  for (const std::string& n : names) {
    const int d = edit_distance(word, n);
    if (d < best_d && 2 * d < static_cast<int>(n.size())) best = n, best_d = d;
  }
  return best;
}

}  // namespace cg::cli
