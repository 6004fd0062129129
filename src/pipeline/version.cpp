#include "src/pipeline/version.hpp"

#ifndef COOLINGGEN_VERSION
#error "COOLINGGEN_VERSION is set by cmake/CoolingGenTargets.cmake"
#endif

namespace cg::pipeline {

const char* version() { return COOLINGGEN_VERSION; }

}  // namespace cg::pipeline
