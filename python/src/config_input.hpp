#pragma once
// The `config` argument of coolinggen.build / validate: a dict (JSON data as Python objects), a JSON
// text (a str starting with "{") or a path (str or os.PathLike) of a config file.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "src/config/config.hpp"

namespace cg::python {

/// Parses `config` (GIL held). Throws config::ConfigError naming the field for anything wrong: a value
/// that is not JSON data (a set, a NaN, a key that is not a str, nesting deeper than 100 levels), or
/// what the config's own parsing refuses.
config::Config load_config(const pybind11::handle& config);

/// Python JSON data -> JSON document; `path` names the value in messages ("" for the document).
nlohmann::json to_json(const pybind11::handle& value, const std::string& path, int depth = 0);

}  // namespace cg::python
