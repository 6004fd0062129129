#pragma once
#include <string>
#include <vector>

namespace cg::cli {

/// Levenshtein edit distance (insertions, deletions, substitutions; a swap of two neighbours counts 2).
int edit_distance(const std::string& a, const std::string& b);

/// The name of `names` nearest to `word` when it is a plausible misspelling (distance <= 2 and less
/// than half the name's length), else "".
std::string closest_name(const std::string& word, const std::vector<std::string>& names);

}  // namespace cg::cli
