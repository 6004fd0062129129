#pragma once
// The variants of a study's design: a full grid (every combination of the parameters' levels), a Latin
// hypercube (seeded; of `candidates` draws the one whose smallest distance between two points is the
// largest, "maximin"), or the rows of a CSV file of overrides. Deterministic: the same study gives
// the same variants in the same order on every machine (own Fisher-Yates shuffle and unit draws on
// std::mt19937_64, whose output the C++ standard fixes).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "src/study/study_file.hpp"

namespace cg::study {

struct Variant {
  std::size_t index = 0;               ///< 0-based position in the design (Slurm's array task id)
  std::string id;                      ///< zero-padded index: "007"
  std::vector<nlohmann::json> values;  ///< one per parameter, in study order
};

/// Throws config::ConfigError (e.g. "design: a grid of 120000 variants exceeds 100000", CSV errors
/// naming the line and column).
std::vector<Variant> expand_design(const Study& study);

/// Latin hypercube in the unit cube: `samples` points of `dims` coordinates in [0, 1), each
/// coordinate's samples in distinct strata of width 1/samples; maximin over `candidates` draws.
std::vector<std::vector<double>> latin_hypercube(int samples, int dims, std::uint64_t seed, int candidates);

}  // namespace cg::study
