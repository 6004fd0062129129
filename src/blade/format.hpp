#pragma once
// Number formatting for error messages of the blade model (6 significant digits).
#include <sstream>
#include <string>

namespace cg::blade::detail {

inline std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace cg::blade::detail
