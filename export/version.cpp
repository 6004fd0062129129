#include "export/version.hpp"

#ifndef COOLINGGEN_VERSION
#error "COOLINGGEN_VERSION must be defined by the build (cmake/CoolingGenTargets.cmake)"
#endif

namespace cg::io {

const char* tool_version() { return COOLINGGEN_VERSION; }

}  // namespace cg::io
