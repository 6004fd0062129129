#pragma once
// Strict reading of a JSON config document. Beyond JSON syntax it refuses what a JSON library
// silently accepts: an object key given twice (the last would win: "unit": "cm", "unit": "mm") and
// numbers beyond the range of a double (1e99999). Messages name the place in the text's terms, without
// the JSON library's exception ids: "blade.json line 4, column 12: syntax error while parsing object
// key - unexpected '}'", "flow_path.span: duplicate key ...".
#include <nlohmann/json.hpp>

#include <string>

namespace cg::config {

/// Parses `text`; throws ConfigError naming `source_name` (e.g. the file) and the line and column, or
/// the key path of a duplicate key.
nlohmann::json parse_json_document(const std::string& text, const std::string& source_name);

}  // namespace cg::config
