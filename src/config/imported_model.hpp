#pragma once
// The blade model of a config with blade.import (internal to build_model): the file read by the config
// reader is cut at the flow path's streamlines (src/blade_import), built like point sections and
// measured against the file. Geometry errors are ConfigErrors naming the import's field.
#include "src/blade/blade_surface.hpp"
#include "src/config/config.hpp"

namespace cg::config {

blade::BladeModel build_imported_model(const Config& config, ProgressSink* progress);

}  // namespace cg::config
