#pragma once
#include "src/core/error.hpp"

namespace cg::config {

/// An invalid configuration. The message starts with the offending field's path in the JSON
/// document (e.g. "sections[2].parametric.max_thickness: ...") and states the allowed range.
class ConfigError : public Error {
 public:
  using Error::Error;
};

}  // namespace cg::config
