#pragma once
// A config field addressed by its path in the config document, as config errors name it:
// "cooling.core.ribs[1].suction_chord", "cooling.film_rows[0].pitch_d", or with [*] every element of an
// array: "sections[*].parametric.stagger_deg". A study sets the field to a value (mode "set") or adds
// a number to it (mode "offset").
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cg::study {

struct PathStep {
  static constexpr long kEvery = -1;  ///< [*]
  std::string key;                    ///< object member; empty for an index step
  long index = 0;                     ///< array index or kEvery (index steps only)
  bool is_index() const { return key.empty(); }
};

struct FieldPath {
  std::string text;  ///< as written
  std::vector<PathStep> steps;
};

enum class ApplyMode { kSet, kOffset };

/// Parses `text`; throws config::ConfigError naming `field` (the study field that holds the path).
FieldPath parse_field_path(const std::string& text, const std::string& field);

/// Sets (kSet) or offsets (kOffset, a number added to the field's number) the field(s) `path` names in
/// `doc`. Every object and array element on the way must exist; the last member may be missing only
/// for kSet (it is created; config parsing then says whether it is a config field). Throws
/// config::ConfigError naming `field` and the first step that does not exist.
void apply_field(nlohmann::json& doc, const FieldPath& path, ApplyMode mode, const nlohmann::json& value,
                 const std::string& field);

/// The concrete paths `path` addresses in `doc` ([*] expanded), e.g. "sections[2].parametric.stagger_deg".
std::vector<std::string> concrete_paths(const nlohmann::json& doc, const FieldPath& path);

}  // namespace cg::study
