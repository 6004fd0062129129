#pragma once
// The tool name and version written into file headers (STEP FILE_NAME, IGES global section, reports).
namespace cg::io {

inline constexpr const char* kToolName = "coolinggen";
/// The project version (CMake PROJECT_VERSION), e.g. "0.1.0".
const char* tool_version();

}  // namespace cg::io
