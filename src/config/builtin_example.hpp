#pragma once
// The example used by `coolinggen build` without a config file: a high-pressure turbine rotor blade
// with three parametric sections on a meridional flow path (conical hub, flared casing). It needs no
// data files, so the executable alone can demonstrate the whole pipeline.
#include "src/config/config.hpp"

namespace cg::config {

/// The example document (JSON text, follows data/schema/coolinggen.schema.json).
const char* builtin_example_json();

/// The parsed example (name "hpt_rotor").
Config builtin_example_config();

}  // namespace cg::config
