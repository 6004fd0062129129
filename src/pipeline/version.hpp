#pragma once
namespace cg::pipeline {

/// The CoolingGen version ("0.1.0", the CMake project version).
const char* version();

}  // namespace cg::pipeline
