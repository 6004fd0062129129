#pragma once
// The example used by `coolinggen build` without a config file: data/examples/hpt_rotor.json (a
// high-pressure turbine rotor blade, three parametric sections on a meridional flow path), embedded so
// the executable alone can demonstrate the whole pipeline. A test keeps the two identical.
#include "src/config/config.hpp"

namespace cg::config {

/// The example document (JSON text, follows data/schema/coolinggen.schema.json).
const char* builtin_example_json();

/// The parsed example (name "hpt_rotor").
Config builtin_example_config();

}  // namespace cg::config
