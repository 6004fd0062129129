#pragma once
// The film-cooling and impingement keys of the "cooling" section (data/schema/coolinggen.schema.json,
// definitions film_row, showerhead, insert, film_limits; README "Cooling features: film holes and
// inserts"):
//   "cooling": {
//     "film_rows":   [ {row}, ... ]   rows of cylindrical or laidback fan-shaped (7-7-7) holes
//     "showerhead":  {...}            staggered rows about the LE stagnation line
//     "inserts":     [ {insert}, ... ] impingement inserts in chambers
//     "film_limits": {...}            min_ligament, tool clearance
//   }
// Parsing checks types and ranges with field-path errors; what needs the blade (a hole larger than the
// wall, a row beyond an end wall, overlapping rows, an insert that does not fit) is found when the
// features are built (features/film/film_cooling.hpp) and reported by film_error() with the same
// "cooling.<...>" paths.
#include <array>

#include "features/film/film_definition.hpp"
#include "src/config/config_error.hpp"
#include "src/config/json_fields.hpp"

namespace cg::config {

/// The keys of "cooling" this parser reads.
inline constexpr std::array<const char*, 4> kFilmCoolingKeys{"film_rows", "showerhead", "inserts", "film_limits"};

/// Reads the film and insert keys of the "cooling" object at `cooling` (other keys are left to the
/// caller). Throws ConfigError.
features::FilmCoolingDefinition parse_film_cooling(const Field& cooling);

/// The ConfigError for film / insert input the blade cannot take: "cooling.<field>: <what>".
ConfigError film_error(const features::FilmInputError& e);

}  // namespace cg::config
