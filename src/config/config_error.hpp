#pragma once
#include <cstdio>
#include <string>

#include "src/core/error.hpp"

namespace cg::config {

/// An invalid configuration. The message starts with the offending field's path in the JSON
/// document (e.g. "sections[2].parametric.max_thickness: ...") and states the allowed range. It is one
/// line: control characters that come from the input (a key, a file name, a line of a point file) are
/// shown escaped ("\n", "\t", "\x01"), so a message can neither span nor fake lines of the output.
class ConfigError : public Error {
 public:
  explicit ConfigError(const std::string& message) : Error(one_line(message)) {}

 private:
  static std::string one_line(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c >= 0x20 && c != 0x7f) out += ch;
      else if (c == '\n') out += "\\n";
      else if (c == '\r') out += "\\r";
      else if (c == '\t') out += "\\t";
      else {
        char hex[5];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        out += hex;
      }
    }
    return out;
  }
};

}  // namespace cg::config
